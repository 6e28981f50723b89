// mouse_input.h -- the mouse buttons as ImGui sees them: from a MouseQueue
// (editor/mouse_queue.h), stamped with the X server's event times, so a
// double click registers at any frame rate.
#pragma once

#include "app/studio/editor/mouse_queue.h"

struct GLFWwindow;

namespace procex::studio {

class MouseInput {
 public:
  // With the window's context current, before ImGui_ImplGlfw_InitForOpenGL, which chains its own button callback after this one's.
  // One per process: Xlib's event hook has no room for a pointer.
  explicit MouseInput(GLFWwindow* window);
  ~MouseInput();
  MouseInput(const MouseInput&) = delete;
  MouseInput& operator=(const MouseInput&) = delete;
  // After ImGui_ImplGlfw_NewFrame (which reads the buttons as they are now), before ImGui::NewFrame.
  void before_new_frame();
  // After ImGui::NewFrame: clicks counted by their event times, not ImGui's frame clock.
  void after_new_frame();
  // Changes still to show: the next frame should not wait for events.
  bool pending() const { return queue_.pending(); }

 private:
  GLFWwindow* window_;
  MouseQueue queue_;
  MouseQueue::Frame frame_;
};

}  // namespace procex::studio

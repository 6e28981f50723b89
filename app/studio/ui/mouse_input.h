// mouse_input.h -- the mouse buttons as ImGui sees them: their changes,
// stamped with the X server's event times and places, go into the window's
// InputQueue (editor/input_queue.h), in order with the keyboard's, and each
// frame shows ImGui the buttons of its change, so a double click registers at
// any frame rate.
#pragma once

#include "app/studio/editor/input_queue.h"

struct GLFWwindow;

namespace procex::studio {

class MouseInput {
 public:
  // With the window's context current, before ImGui_ImplGlfw_InitForOpenGL, which chains its own button callback after this one's.
  // One per process: Xlib's event hook has no room for a pointer.
  MouseInput(GLFWwindow* window, InputQueue& queue);
  ~MouseInput();
  MouseInput(const MouseInput&) = delete;
  MouseInput& operator=(const MouseInput&) = delete;
  // After ImGui_ImplGlfw_NewFrame (which reads the buttons as they are now), before ImGui::NewFrame:
  // the buttons of the frame's change (InputQueue::next).
  static void before_new_frame(const InputQueue::Frame& f);
  // After ImGui::NewFrame: clicks counted by their event times, not ImGui's frame clock.
  static void after_new_frame(const InputQueue::Frame& f);

 private:
  GLFWwindow* window_;
};

}  // namespace procex::studio

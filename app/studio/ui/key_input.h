// key_input.h -- the keyboard as ImGui sees it: from a KeyQueue
// (editor/key_queue.h), so no key press or typed character is lost to a slow frame.
#pragma once

#include "app/studio/editor/key_queue.h"

struct GLFWwindow;

namespace procex::studio {

class KeyInput {
 public:
  // Before ImGui_ImplGlfw_InitForOpenGL, which chains its key and character callbacks after these.
  // One per process: GLFW's callbacks have no room for a pointer of their own.
  explicit KeyInput(GLFWwindow* window);
  ~KeyInput();
  KeyInput(const KeyInput&) = delete;
  KeyInput& operator=(const KeyInput&) = delete;
  // After ImGui_ImplGlfw_NewFrame, before ImGui::NewFrame: the keys and characters of the next change
  // in place of those the backend's callbacks gave ImGui as they came.
  void before_new_frame();
  // Changes still to show: the next frame should not wait for events.
  bool pending() const { return queue_.pending(); }

 private:
  GLFWwindow* window_;
  KeyQueue queue_;
};

}  // namespace procex::studio

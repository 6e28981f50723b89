// key_input.h -- the keyboard as ImGui sees it: key changes and typed
// characters go into the window's InputQueue (editor/input_queue.h), in order
// with the mouse's, and each frame shows ImGui the keys of its change, so no
// key press or typed character is lost to a slow frame.
#pragma once

#include "app/studio/editor/input_queue.h"

struct GLFWwindow;

namespace procex::studio {

class KeyInput {
 public:
  // Before ImGui_ImplGlfw_InitForOpenGL, which chains its key and character callbacks after these.
  // One per process: GLFW's callbacks have no room for a pointer of their own.
  KeyInput(GLFWwindow* window, InputQueue& queue);
  ~KeyInput();
  KeyInput(const KeyInput&) = delete;
  KeyInput& operator=(const KeyInput&) = delete;
  // After ImGui_ImplGlfw_NewFrame, before ImGui::NewFrame: the keys and characters of the frame's
  // change (InputQueue::next) in place of those the backend's callbacks gave ImGui as they came.
  static void before_new_frame(const InputQueue::Frame& f);

 private:
  GLFWwindow* window_;
};

}  // namespace procex::studio

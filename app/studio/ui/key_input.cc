#include "app/studio/ui/key_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cassert>

namespace procex::studio {

namespace {

InputQueue* queue = nullptr;

void on_key(GLFWwindow*, int key, int, int action, int) {
  if (action != GLFW_REPEAT) queue->key(key, action == GLFW_PRESS);
}

void on_character(GLFWwindow*, unsigned int c) { queue->character(c); }

}  // namespace

KeyInput::KeyInput(GLFWwindow* window, InputQueue& q) : window_(window) {
  assert(!queue && "one KeyInput per process: GLFW's callbacks are plain functions");
  queue = &q;
  glfwSetKeyCallback(window_, on_key);
  glfwSetCharCallback(window_, on_character);
}

KeyInput::~KeyInput() {
  glfwSetKeyCallback(window_, nullptr);
  glfwSetCharCallback(window_, nullptr);
  queue = nullptr;
}

void KeyInput::before_new_frame(const InputQueue::Frame& f) {
  static_assert(InputQueue::kKeys == IM_ARRAYSIZE(ImGuiIO{}.KeysDown), "InputQueue holds ImGui's keys");
  ImGuiIO& io = ImGui::GetIO();
  for (int k = 0; k < InputQueue::kKeys; ++k) io.KeysDown[k] = f.keys[static_cast<std::size_t>(k)];
  const auto down = [&](int left, int right) { return f.keys[static_cast<std::size_t>(left)] || f.keys[static_cast<std::size_t>(right)]; };
  io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
  io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
  io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
  io.KeySuper = down(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
  io.InputQueueCharacters.resize(0);  // the backend's, added as they came
  for (const std::uint32_t c : f.characters) io.AddInputCharacter(c);
}

}  // namespace procex::studio

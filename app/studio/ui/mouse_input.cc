// Kept apart: <X11/Xlibint.h> defines macros, and <GL/glx.h> brings <GL/gl.h>,
// which the rest of the studio need not see.
#include "app/studio/ui/mouse_input.h"

#include <GL/glx.h>
#include <GLFW/glfw3.h>
#include <X11/Xlibint.h>
#include <imgui.h>

#include <cassert>
#include <deque>

namespace procex::studio {

namespace {

// GLFW hands a button callback no event time, so Xlib's conversion of each
// ButtonPress and ButtonRelease from the wire is hooked: it records the
// server's time and place, in order, and the callback takes them in turn.
struct Stamp {
  unsigned button;
  bool down;
  Time time;
  int x, y;
};
std::deque<Stamp> stamps;
using WireToEvent = Bool (*)(Display*, XEvent*, xEvent*);
WireToEvent previous_press = nullptr, previous_release = nullptr;
Display* hooked = nullptr;
InputQueue* queue = nullptr;

Bool stamp_button(Display* display, XEvent* event, xEvent* wire) {
  const bool down = (wire->u.u.type & 0x7f) == ButtonPress;
  const Bool kept = (down ? previous_press : previous_release)(display, event, wire);
  if (kept) {
    stamps.push_back({event->xbutton.button, down, event->xbutton.time, event->xbutton.x, event->xbutton.y});
    if (stamps.size() > 256) stamps.pop_front();  // presses on no window of ours: never taken
  }
  return kept;
}

// GLFW numbers X's buttons 1, 3, 2 as 0, 1, 2; 4 to 7 are the wheel; 8 on are GLFW's 3 on.
unsigned x_button(int glfw_button) { return glfw_button == 0 ? 1u : glfw_button == 1 ? 3u : glfw_button == 2 ? 2u : static_cast<unsigned>(glfw_button) + 5u; }

void on_button(GLFWwindow* window, int button, int action, int /*mods*/) {
  MouseButtonEvent e{button, action == GLFW_PRESS, 0, 0, 0};
  while (!stamps.empty()) {
    const Stamp s = stamps.front();
    stamps.pop_front();
    if (s.button == x_button(button) && s.down == e.down) {
      e.time_ms = static_cast<std::uint32_t>(s.time);
      e.x = static_cast<float>(s.x);
      e.y = static_cast<float>(s.y);
      queue->button(e);
      return;
    }
  }
  // No stamp (not X11): the time it reached us, which a slow frame delays.
  double x = 0, y = 0;
  glfwGetCursorPos(window, &x, &y);
  e.time_ms = static_cast<std::uint32_t>(glfwGetTime() * 1e3);
  e.x = static_cast<float>(x);
  e.y = static_cast<float>(y);
  queue->button(e);
}

}  // namespace

MouseInput::MouseInput(GLFWwindow* window, InputQueue& q) : window_(window) {
  assert(!queue && "one MouseInput per process: Xlib's hook is global");
  queue = &q;
  hooked = glXGetCurrentDisplay();  // the window's, whose context is current (glfw3native.h wants Xrandr's headers)
  if (hooked) {
    previous_press = XESetWireToEvent(hooked, ButtonPress, stamp_button);
    previous_release = XESetWireToEvent(hooked, ButtonRelease, stamp_button);
  }
  glfwSetMouseButtonCallback(window_, on_button);
}

MouseInput::~MouseInput() {
  glfwSetMouseButtonCallback(window_, nullptr);
  if (hooked) {
    XESetWireToEvent(hooked, ButtonPress, previous_press);
    XESetWireToEvent(hooked, ButtonRelease, previous_release);
  }
  stamps.clear();
  hooked = nullptr;
  queue = nullptr;
}

void MouseInput::before_new_frame(const InputQueue::Frame& f) {
  ImGuiIO& io = ImGui::GetIO();
  for (int b = 0; b < InputQueue::kButtons; ++b) io.MouseDown[b] = f.buttons[static_cast<std::size_t>(b)];
  if (f.at) io.MousePos = ImVec2((*f.at)[0], (*f.at)[1]);
}

void MouseInput::after_new_frame(const InputQueue::Frame& f) {
  ImGuiIO& io = ImGui::GetIO();
  for (int b = 0; b < InputQueue::kButtons; ++b) {
    if (!io.MouseClicked[b]) continue;
    const int clicks = f.clicks[static_cast<std::size_t>(b)];
    io.MouseClickedCount[b] = io.MouseClickedLastCount[b] = static_cast<ImU16>(clicks > 0 ? clicks : 1);
    io.MouseDoubleClicked[b] = io.MouseClickedCount[b] == 2;
  }
}

}  // namespace procex::studio

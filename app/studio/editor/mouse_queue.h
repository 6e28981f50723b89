// mouse_queue.h -- mouse button presses and releases as the window system
// stamped them, handed to the UI one change per frame.
//
// Dear ImGui 1.86 reads the buttons' state once per frame and counts clicks
// by its own frame clock. On a slow frame (a loaded machine, a sanitizer
// build, a large preview) a press, a release and a second press that arrive
// together were one long press to it, and two clicks seen in frames more
// than 0.3 s apart were no double click, however quick the person was. Here
// each press and release gets a frame of its own, at the place it happened,
// and clicks are counted by the event times, whatever the frame rate.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>

namespace procex::studio {

struct MouseButtonEvent {
  int button = 0;  // 0 left, 1 right, 2 middle (ImGui's and GLFW's numbering)
  bool down = false;
  std::uint32_t time_ms = 0;  // the window system's clock (X server time: wraps after 49 days)
  float x = 0, y = 0;         // in the window
};

class MouseQueue {
 public:
  static constexpr int kButtons = 5;  // ImGui's
  // A second press within this time and distance of the previous one counts on from it (ImGui's defaults).
  explicit MouseQueue(std::uint32_t multi_click_ms = 300, float multi_click_distance = 6.0f)
      : multi_click_ms_(multi_click_ms), multi_click_distance_(multi_click_distance) {}

  void push(const MouseButtonEvent& e);
  // What the next frame sees: the buttons after the oldest change not yet
  // shown, where it happened, and for a press its click count (2: a double click).
  struct Frame {
    std::array<bool, kButtons> down{};
    std::optional<std::array<float, 2>> at;  // none: no change pending, the cursor is where it is now
    std::array<int, kButtons> clicks{};      // 0: no press this frame
  };
  Frame next();
  bool pending() const { return !queue_.empty(); }

 private:
  struct Queued {
    MouseButtonEvent event;
    int clicks = 0;
  };
  std::uint32_t multi_click_ms_;
  float multi_click_distance_;
  std::deque<Queued> queue_;
  std::array<bool, kButtons> down_{};
  // Per button, its last press: when, where and which click of a series it was.
  std::array<std::optional<MouseButtonEvent>, kButtons> last_press_;
  std::array<int, kButtons> last_clicks_{};
};

}  // namespace procex::studio

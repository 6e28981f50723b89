#include "app/studio/editor/input_queue.h"

namespace procex::studio {

void InputQueue::button(const MouseButtonEvent& e) {
  if (e.button < 0 || e.button >= kButtons) return;
  int clicks = 0;
  if (e.down) {
    const auto b = static_cast<std::size_t>(e.button);
    const std::optional<MouseButtonEvent>& last = last_press_[b];
    // Unsigned difference: right across the server clock's wrap.
    const bool soon = last && static_cast<std::uint32_t>(e.time_ms - last->time_ms) < multi_click_ms_;
    const float dx = last ? e.x - last->x : 0, dy = last ? e.y - last->y : 0;
    const bool near = dx * dx + dy * dy < multi_click_distance_ * multi_click_distance_;
    clicks = soon && near ? last_clicks_[b] + 1 : 1;
    last_press_[b] = e;
    last_clicks_[b] = clicks;
  }
  queue_.push_back({Event::Kind::kButton, e, clicks});
}

void InputQueue::key(int key, bool down) {
  if (key < 0 || key >= kKeys) return;  // GLFW_KEY_UNKNOWN
  Event e{Event::Kind::kKey, {}};
  e.key = key;
  e.down = down;
  queue_.push_back(e);
}

void InputQueue::character(std::uint32_t c) {
  Event e{Event::Kind::kCharacter, {}};
  e.character = c;
  queue_.push_back(e);
}

InputQueue::Frame InputQueue::next() {
  Frame f;
  if (!queue_.empty() && queue_.front().kind != Event::Kind::kCharacter) {
    const Event e = queue_.front();
    queue_.pop_front();
    if (e.kind == Event::Kind::kKey) {
      keys_[static_cast<std::size_t>(e.key)] = e.down;
    } else {
      const auto b = static_cast<std::size_t>(e.button.button);
      buttons_[b] = e.button.down;
      f.at = std::array<float, 2>{e.button.x, e.button.y};
      f.clicks[b] = e.clicks;
    }
  }
  for (; !queue_.empty() && queue_.front().kind == Event::Kind::kCharacter; queue_.pop_front()) f.characters.push_back(queue_.front().character);
  f.buttons = buttons_;
  f.keys = keys_;
  return f;
}

}  // namespace procex::studio

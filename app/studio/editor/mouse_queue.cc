#include "app/studio/editor/mouse_queue.h"

namespace procex::studio {

void MouseQueue::push(const MouseButtonEvent& e) {
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
  queue_.push_back({e, clicks});
}

MouseQueue::Frame MouseQueue::next() {
  Frame f;
  if (!queue_.empty()) {
    const Queued q = queue_.front();
    queue_.pop_front();
    const auto b = static_cast<std::size_t>(q.event.button);
    down_[b] = q.event.down;
    f.at = std::array<float, 2>{q.event.x, q.event.y};
    f.clicks[b] = q.clicks;
  }
  f.down = down_;
  return f;
}

}  // namespace procex::studio

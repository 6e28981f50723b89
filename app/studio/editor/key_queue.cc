#include "app/studio/editor/key_queue.h"

namespace procex::studio {

void KeyQueue::key(int key, bool down) {
  if (key < 0 || key >= kKeys) return;  // GLFW_KEY_UNKNOWN
  queue_.push_back({key, down, 0});
}

void KeyQueue::character(std::uint32_t c) { queue_.push_back({-1, false, c}); }

KeyQueue::Frame KeyQueue::next() {
  Frame f;
  if (!queue_.empty() && queue_.front().key >= 0) {
    down_[static_cast<std::size_t>(queue_.front().key)] = queue_.front().down;
    queue_.pop_front();
  }
  for (; !queue_.empty() && queue_.front().key < 0; queue_.pop_front()) f.characters.push_back(queue_.front().character);
  f.down = down_;
  return f;
}

}  // namespace procex::studio

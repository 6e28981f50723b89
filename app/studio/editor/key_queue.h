// key_queue.h -- key presses, releases and typed characters in the order
// they came, handed to the UI one key change per frame.
//
// Dear ImGui 1.86 reads the keys' state once per frame. On a slow frame (a
// loaded machine, a sanitizer build, a large preview) a key pressed and
// released before the next frame was never seen down: Ctrl+Z or Tab did
// nothing. And a character typed in the same frame as the key that opens a
// text field (Tab, then the node's name) went nowhere, the field not yet
// having the keyboard. Here each press and release gets a frame of its own,
// and the characters a press typed come with it, as they would to a person
// typing at any frame rate (editor/mouse_queue.h does the same for the mouse).
#pragma once

#include <bitset>
#include <cstdint>
#include <deque>
#include <vector>

namespace procex::studio {

class KeyQueue {
 public:
  static constexpr int kKeys = 512;  // ImGui's io.KeysDown (GLFW's key codes)

  // A key's press or release (key repeats are not changes: ImGui repeats by itself).
  void key(int key, bool down);
  // A character typed (Unicode code point), after the press that typed it.
  void character(std::uint32_t c);

  // What the next frame sees: the keys after the oldest change not yet shown,
  // and the characters typed with it (or, with no change pending, those typed
  // since: a key held down repeating).
  struct Frame {
    std::bitset<kKeys> down;
    std::vector<std::uint32_t> characters;
  };
  Frame next();
  bool pending() const { return !queue_.empty(); }

 private:
  struct Event {
    int key = -1;  // -1: a character
    bool down = false;
    std::uint32_t character = 0;
  };
  std::deque<Event> queue_;
  std::bitset<kKeys> down_;
};

}  // namespace procex::studio

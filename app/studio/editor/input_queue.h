// input_queue.h -- mouse button presses and releases, key presses and
// releases and typed characters, in the one order they came, handed to the UI
// one change per frame.
//
// Dear ImGui 1.86 reads the buttons' and keys' state once per frame and
// counts clicks by its own frame clock. On a slow frame (a loaded machine, a
// sanitizer build, a large preview) a press, a release and a second press
// that arrived together were one long press to it, a key pressed and released
// before the next frame was never seen down, and a character typed in the
// same frame as the key that opens a text field (Tab, then the node's name)
// went nowhere. Here each change of a button or a key gets a frame of its
// own, mouse and keyboard in one queue: a click then a key (select a node,
// then Delete) apply in that order, whatever the frame rate, as two queues
// taking one change each per frame could not promise. The characters a key
// press typed come with it, a button change comes at the place it happened,
// and clicks are counted by the window system's event times.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace procex::studio {

struct MouseButtonEvent {
  int button = 0;  // 0 left, 1 right, 2 middle (ImGui's and GLFW's numbering)
  bool down = false;
  std::uint32_t time_ms = 0;  // the window system's clock (X server time: wraps after 49 days)
  float x = 0, y = 0;         // in the window
};

class InputQueue {
 public:
  static constexpr int kButtons = 5;  // ImGui's io.MouseDown
  static constexpr int kKeys = 512;   // ImGui's io.KeysDown (GLFW's key codes)
  // A second press within this time and distance of the previous one counts on from it (ImGui's defaults).
  explicit InputQueue(std::uint32_t multi_click_ms = 300, float multi_click_distance = 6.0f)
      : multi_click_ms_(multi_click_ms), multi_click_distance_(multi_click_distance) {}

  void button(const MouseButtonEvent& e);
  // A key's press or release (key repeats are not changes: ImGui repeats by itself).
  void key(int key, bool down);
  // A character typed (Unicode code point), after the press that typed it.
  void character(std::uint32_t c);

  // What the next frame sees: the buttons and keys after the oldest change
  // not yet shown, and with it the characters typed after it (or, with no
  // change pending, those typed since: a key held down repeating).
  struct Frame {
    std::array<bool, kButtons> buttons{};
    std::optional<std::array<float, 2>> at;  // a button change's place; none: the cursor is where it is now
    std::array<int, kButtons> clicks{};      // a press's click count (2: a double click); 0: no press this frame
    std::bitset<kKeys> keys;
    std::vector<std::uint32_t> characters;
  };
  Frame next();
  // Changes still to show: the next frame should not wait for events.
  bool pending() const { return !queue_.empty(); }

 private:
  struct Event {
    enum class Kind { kButton, kKey, kCharacter } kind;
    MouseButtonEvent button;  // kButton
    int clicks = 0;           // kButton, a press: which click of a series
    int key = 0;              // kKey
    bool down = false;        // kKey
    std::uint32_t character = 0;
  };
  std::uint32_t multi_click_ms_;
  float multi_click_distance_;
  std::deque<Event> queue_;
  std::array<bool, kButtons> buttons_{};
  std::bitset<kKeys> keys_;
  // Per button, its last press: when, where and which click of a series it was.
  std::array<std::optional<MouseButtonEvent>, kButtons> last_press_;
  std::array<int, kButtons> last_clicks_{};
};

}  // namespace procex::studio

// studio_driver.h -- drives a real procex-studio window under Xvfb, for the
// window tests: the studio started on a recipe with --ui-map, real X input
// through xdotool, and the screen read back with xwd.
//
// The studio's --ui-map file says where pins and widgets are on screen, and
// how far the studio has got (revision, settled, dirty); tests wait on it
// rather than on time, so a loaded machine makes them slower, not flaky.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace procex::studio::driver {

namespace fs = std::filesystem;
using json = nlohmann::json;

// A studio process on `recipe`, its home and ui map in `dir`; killed when destroyed.
class Studio {
 public:
  Studio(const fs::path& recipe, const fs::path& dir, std::vector<std::string> extra = {"--autosave", "0"});
  ~Studio();
  Studio(const Studio&) = delete;
  Studio& operator=(const Studio&) = delete;
  // The newest map that satisfies `ready`; fails the test after a timeout (unless not `required`:
  // then the last map, for a gesture to try again).
  json wait(const std::string& what, const std::function<bool(const json&)>& ready, std::chrono::seconds timeout = std::chrono::seconds(30),
            bool required = true);
  // Exit code, or -1 when it did not exit in time.
  int wait_exit(std::chrono::seconds timeout);
  // Stops and continues the process (SIGSTOP, SIGCONT): input sent between the two reaches it
  // at once, as during one slow frame.
  void pause();
  void resume();
  pid_t pid() const { return pid_; }

 private:
  fs::path map_;
  pid_t pid_ = -1;
};

// One thread of a studio, found by its name, held still (ptrace: that thread alone stops, the others
// go on) until release() or destruction. Only a thread asleep (waiting, in a system call) is taken: one
// stopped while it holds a lock the window's thread takes would stop that thread too.
class HeldThread {
 public:
  HeldThread(pid_t pid, const std::string& name);
  ~HeldThread() { release(); }
  HeldThread(const HeldThread&) = delete;
  HeldThread& operator=(const HeldThread&) = delete;
  bool held() const { return tid_ > 0; }
  void release();

 private:
  pid_t tid_ = -1;
};

void xdo(const std::string& args);
// Presses and releases the keys (xdotool's "ctrl+s"); the studio shows each key change in a frame of
// its own (editor/input_queue.h), so however slow its frames, none is lost.
void press(const std::string& keys);
// Whether the map lists node `node`'s pins: a node added while the canvas was drawn is listed a frame before them.
bool pins_shown(const json& map, std::uint64_t node);
// Screen position of a pin, from the map.
std::pair<int, int> pin(const json& map, std::uint64_t node, int port, bool output);
// Screen centre of an inspector widget (map "params") or another widget (map "buttons").
std::pair<int, int> widget_centre(const json& map, const std::string& param);
std::pair<int, int> button_centre(const json& map, const std::string& name);
void drag(std::pair<int, int> from, std::pair<int, int> to);
// Ctrl+click turns an ImGui slider into a text field; type the value and Enter.
void type_into_slider(std::pair<int, int> at, const std::string& value);
void click(std::pair<int, int> at);
std::uint64_t revision(const json& j);
// Clicks `at` (a widget on `map`, the studio's newest map) once and waits until `done`.
// The studio shows every press and release in a frame of its own
// (editor/input_queue.h), so a loaded machine makes it slower, never loses the click.
json click_and_wait(Studio& studio, const json& map, const std::function<std::pair<int, int>(const json&)>& at, const std::string& what,
                 const std::function<bool(const json&)>& done);
// Double-clicks `at` once and waits until `done`: the studio counts clicks by
// their event times, so a double click registers at any frame rate.
json double_click_and_wait(Studio& studio, const json& map, const std::function<std::pair<int, int>(const json&)>& at, const std::string& what,
                           const std::function<bool(const json&)>& done);
// Opens menu `menu` (a "buttons" entry: "menu_view"), clicks its item `item`
// once the map lists it (a menu's items are listed once it has placed
// itself) and waits until `done`.
json menu_item_and_wait(Studio& studio, const json& map, const std::string& menu, const std::string& item,
                        const std::function<bool(const json&)>& done);
// Waits until a text field has the keyboard (the map's keyboard.text), selects its text and types `text` over it.
json type_into_focused_field(Studio& studio, const std::string& what, const std::string& text);

// Drops `file` on the studio's window at its canvas, as a file manager
// would: a real XDND drag from another X client (PROCEX_XDND_DROP).
void drop_file(const json& map, const fs::path& file);

// The screen now (xwd | xwdtopnm), so a test sees what a person would.
struct Screen {
  long w = 0, h = 0;
  std::string ppm;
  std::size_t at = 0;  // the first RGB byte
  // Pixels of window rectangle [x, y, w, h] (window `origin` on screen) whose colour passes `is`.
  long count(std::pair<long, long> origin, const json& r, const std::function<bool(double, double, double)>& is) const;
};
Screen capture_screen();
// Captures the screen until `done` holds of it, or the deadline passes: the last capture. The map
// is written as a frame is built; the screen shows that frame after it is drawn, later on a loaded machine.
Screen screen_when(const std::function<bool(const Screen&)>& done, std::chrono::seconds timeout = std::chrono::seconds(20));
std::pair<long, long> window_origin(const json& map);

// Ctrl+S, then Ctrl+Q: saved, and a clean exit.
void save_and_quit(Studio& studio);
// An empty folder for one test's files, removed when the test has ended (its studios
// killed) if it passed.
fs::path fresh_dir(const std::string& name);
// A copy of one of tests/studio/data's recipes in `dir`, to edit and save.
fs::path copy_test_recipe(const std::string& name, const fs::path& dir);

}  // namespace procex::studio::driver

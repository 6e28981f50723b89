#include "tests/studio/interaction/studio_driver.h"

#include <signal.h>
#include <spawn.h>
#include <sys/ptrace.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>

extern char** environ;

namespace procex::studio::driver {

using namespace std::chrono_literals;

Studio::Studio(const fs::path& recipe, const fs::path& dir, std::vector<std::string> extra) : map_(dir / "ui_map.json") {
  setenv("PROCEX_STUDIO_HOME", (dir / "home").c_str(), 1);
  setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1);  // the panel layout: this test's, not the user's
  fs::remove(map_);
  std::vector<std::string> args = {PROCEX_STUDIO_EXE, recipe.string(), "--ui-map", map_.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  EXPECT_EQ(posix_spawn(&pid_, argv[0], nullptr, nullptr, argv.data(), environ), 0);
}

Studio::~Studio() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

json Studio::wait(const std::string& what, const std::function<bool(const json&)>& ready, std::chrono::seconds timeout, bool required) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  json last;
  while (std::chrono::steady_clock::now() < end) {
    std::ifstream in(map_);
    json j = json::parse(in, nullptr, false);
    if (!j.is_discarded()) {
      last = j;
      if (ready(j)) return j;
    }
    std::this_thread::sleep_for(50ms);
  }
  if (required) ADD_FAILURE() << "timed out waiting for: " << what << "\nlast ui map: " << last.dump().substr(0, 2000);
  return last;
}

int Studio::wait_exit(std::chrono::seconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    std::this_thread::sleep_for(50ms);
  }
  return -1;
}

void Studio::pause() { ASSERT_EQ(kill(pid_, SIGSTOP), 0); }

void Studio::resume() { ASSERT_EQ(kill(pid_, SIGCONT), 0); }

namespace {

// The state letter of /proc/PID/task/TID/stat ('S': asleep, 't': stopped by a tracer), or 0.
char thread_state(pid_t pid, pid_t tid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(tid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t name_end = stat.rfind(')');  // the name, in brackets, may hold spaces
  return name_end != std::string::npos && name_end + 2 < stat.size() ? stat[name_end + 2] : 0;
}

}  // namespace

HeldThread::HeldThread(pid_t pid, const std::string& name) {
  pid_t tid = -1;
  std::error_code ec;
  for (const auto& task : fs::directory_iterator("/proc/" + std::to_string(pid) + "/task", ec)) {
    std::ifstream comm(task.path() / "comm");
    std::string n;
    if (std::getline(comm, n) && n == name) tid = std::stoi(task.path().filename().string());
  }
  if (tid < 0) {
    ADD_FAILURE() << "the studio has no thread named " << name;
    return;
  }
  if (const char state = thread_state(pid, tid); state != 'S') {
    ADD_FAILURE() << "thread " << name << " is not asleep (state " << state << ")";
    return;
  }
  if (ptrace(PTRACE_SEIZE, tid, nullptr, nullptr) != 0) {
    ADD_FAILURE() << "ptrace(PTRACE_SEIZE) of thread " << name << ": " << std::strerror(errno);
    return;
  }
  tid_ = tid;
  int status = 0;
  if (ptrace(PTRACE_INTERRUPT, tid, nullptr, nullptr) != 0 || waitpid(tid, &status, __WALL) != tid || !WIFSTOPPED(status)) {
    ADD_FAILURE() << "thread " << name << " did not stop: " << std::strerror(errno);
    release();
  }
}

void HeldThread::release() {
  if (tid_ > 0) ptrace(PTRACE_DETACH, tid_, nullptr, nullptr);
  tid_ = -1;
}

void xdo(const std::string& args) {
  const std::string cmd = "xdotool " + args;
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

void press(const std::string& keys) { xdo("key " + keys); }

bool pins_shown(const json& map, std::uint64_t node) {
  return std::any_of(map["pins"].begin(), map["pins"].end(), [&](const json& p) { return p["node"] == node; });
}

std::pair<int, int> pin(const json& map, std::uint64_t node, int port, bool output) {
  for (const json& p : map["pins"])
    if (p["node"] == node && p["port"] == port && p["output"] == output)
      return {map["window"][0].get<int>() + static_cast<int>(p["x"].get<double>()), map["window"][1].get<int>() + static_cast<int>(p["y"].get<double>())};
  ADD_FAILURE() << "no pin " << node << "." << port << (output ? " out" : " in") << " on screen";
  return {0, 0};
}

std::pair<int, int> widget_centre(const json& map, const std::string& param) {
  const json& r = map["params"][param];
  return {map["window"][0].get<int>() + static_cast<int>(r[0].get<double>() + r[2].get<double>() / 2),
          map["window"][1].get<int>() + static_cast<int>(r[1].get<double>() + r[3].get<double>() / 2)};
}

void drag(std::pair<int, int> from, std::pair<int, int> to) {
  const std::string a = std::to_string(from.first) + " " + std::to_string(from.second);
  const std::string mid = std::to_string((from.first + to.first) / 2) + " " + std::to_string((from.second + to.second) / 2 + 20);
  const std::string b = std::to_string(to.first) + " " + std::to_string(to.second);
  xdo("sleep 0.3 mousemove " + a + " sleep 0.3 mousedown 1 sleep 0.2 mousemove " + mid + " sleep 0.2 mousemove " + b + " sleep 0.2 mouseup 1 sleep 0.2");
}

void type_into_slider(std::pair<int, int> at, const std::string& value) {
  xdo("mousemove " + std::to_string(at.first) + " " + std::to_string(at.second) +
      " sleep 0.2 keydown ctrl sleep 0.15 click 1 sleep 0.15 keyup ctrl sleep 0.3");
  press("ctrl+a");
  xdo("type " + value);
  press("Return");
}

std::pair<int, int> button_centre(const json& map, const std::string& name) {
  const json& r = map["buttons"][name];
  return {map["window"][0].get<int>() + static_cast<int>(r[0].get<double>() + r[2].get<double>() / 2),
          map["window"][1].get<int>() + static_cast<int>(r[1].get<double>() + r[3].get<double>() / 2)};
}

void click(std::pair<int, int> at) { xdo("mousemove " + std::to_string(at.first) + " " + std::to_string(at.second) + " sleep 0.3 click 1 sleep 0.2"); }

std::uint64_t revision(const json& j) { return j["revision"].get<std::uint64_t>(); }

json click_and_wait(Studio& studio, const json& map, const std::function<std::pair<int, int>(const json&)>& at,
                 const std::string& what, const std::function<bool(const json&)>& done) {
  const std::uint64_t rev = revision(map);
  click(at(map));
  return studio.wait(what, [&](const json& j) { return revision(j) > rev && done(j); });
}

json double_click_and_wait(Studio& studio, const json& map, const std::function<std::pair<int, int>(const json&)>& at, const std::string& what,
                           const std::function<bool(const json&)>& done) {
  const auto [x, y] = at(map);
  xdo("mousemove " + std::to_string(x) + " " + std::to_string(y) + " sleep 0.3 mousedown 1 sleep 0.04 mouseup 1 sleep 0.1 mousedown 1 sleep 0.04 mouseup 1 sleep 0.3");
  return studio.wait(what, done);
}

json menu_item_and_wait(Studio& studio, const json& map, const std::string& menu, const std::string& item,
                        const std::function<bool(const json&)>& done) {
  click(button_centre(map, menu));
  click(button_centre(studio.wait(item + " shown", [&](const json& j) { return j["buttons"].contains(item); }), item));
  return studio.wait(item, done);
}

json type_into_focused_field(Studio& studio, const std::string& what, const std::string& text) {
  const json map = studio.wait(what + " has the keyboard", [](const json& j) { return j["keyboard"]["text"] == true; });
  press("ctrl+a");
  xdo("type '" + text + "'");
  return map;
}

void drop_file(const json& map, const fs::path& file) {
  FILE* pipe = popen("xdotool search --name 'procex-studio$' | head -n 1", "r");
  ASSERT_TRUE(pipe);
  char id[64] = {};
  const bool read = std::fgets(id, sizeof id, pipe) != nullptr;
  pclose(pipe);
  ASSERT_TRUE(read) << "no procex-studio window";
  const auto canvas = map["canvas"];
  const int x = map["window"][0].get<int>() + static_cast<int>(canvas[0].get<double>() + canvas[2].get<double>() * 0.5);
  const int y = map["window"][1].get<int>() + static_cast<int>(canvas[1].get<double>() + canvas[3].get<double>() * 0.5);
  const std::string cmd = std::string(PROCEX_XDND_DROP) + " " + std::string(id).substr(0, std::string(id).find('\n')) + " " + std::to_string(x) + " " +
                          std::to_string(y) + " '" + file.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

long Screen::count(std::pair<long, long> origin, const json& r, const std::function<bool(double, double, double)>& is) const {
  const long x0 = origin.first + static_cast<long>(r[0].get<double>()), y0 = origin.second + static_cast<long>(r[1].get<double>());
  const long x1 = x0 + static_cast<long>(r[2].get<double>()), y1 = y0 + static_cast<long>(r[3].get<double>());
  long n = 0;
  for (long y = std::max(0L, y0); y < std::min(h, y1); ++y)
    for (long x = std::max(0L, x0); x < std::min(w, x1); ++x) {
      const std::size_t i = at + static_cast<std::size_t>((y * w + x) * 3);
      if (i + 2 >= ppm.size()) break;
      n += is(static_cast<unsigned char>(ppm[i]), static_cast<unsigned char>(ppm[i + 1]), static_cast<unsigned char>(ppm[i + 2]));
    }
  return n;
}

Screen capture_screen() {
  Screen s;
  FILE* pipe = popen("xwd -root -silent | xwdtopnm 2>/dev/null", "r");
  if (!pipe) {
    ADD_FAILURE() << "cannot run xwd";
    return s;
  }
  char buf[65536];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) s.ppm.append(buf, n);
  pclose(pipe);
  // P6 <width> <height> <maxval>, whitespace-separated, then RGB bytes.
  std::vector<long> header;
  while (header.size() < 4 && s.at < s.ppm.size()) {
    while (s.at < s.ppm.size() && std::isspace(static_cast<unsigned char>(s.ppm[s.at]))) ++s.at;
    const std::size_t start = s.at;
    while (s.at < s.ppm.size() && !std::isspace(static_cast<unsigned char>(s.ppm[s.at]))) ++s.at;
    const std::string token = s.ppm.substr(start, s.at - start);
    header.push_back(header.empty() ? (token == "P6" ? 6 : -1) : std::atol(token.c_str()));
  }
  ++s.at;
  if (header.size() < 4 || header[0] != 6 || header[3] != 255) {
    ADD_FAILURE() << "xwd | xwdtopnm gave no 8-bit P6 image";
    return {};
  }
  s.w = header[1];
  s.h = header[2];
  return s;
}

Screen screen_when(const std::function<bool(const Screen&)>& done, std::chrono::seconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  Screen s = capture_screen();
  while (!done(s) && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(50ms);
    s = capture_screen();
  }
  return s;
}

std::pair<long, long> window_origin(const json& map) { return {map["window"][0].get<long>(), map["window"][1].get<long>()}; }

void save_and_quit(Studio& studio) {
  press("ctrl+s");
  studio.wait("saved", [](const json& j) { return !j["dirty"].get<bool>(); });
  press("ctrl+q");
  EXPECT_EQ(studio.wait_exit(20s), 0);
}

namespace {

// Removes the folders fresh_dir made once their test has ended, so after its
// studios are killed: a studio still running writes its ui map as the folder
// goes, and removing it then fails with "Directory not empty". A failed
// test's folder stays, to look at.
class FreshDirs : public ::testing::EmptyTestEventListener {
 public:
  static FreshDirs& instance() {
    static FreshDirs* dirs = [] {
      auto* d = new FreshDirs;
      ::testing::UnitTest::GetInstance()->listeners().Append(d);  // owned by gtest from here
      return d;
    }();
    return *dirs;
  }
  void add(const fs::path& dir) { dirs_.push_back(dir); }
  void OnTestEnd(const ::testing::TestInfo& test) override {
    if (test.result()->Passed())
      for (const fs::path& dir : dirs_) fs::remove_all(dir);
    dirs_.clear();
  }

 private:
  std::vector<fs::path> dirs_;
};

}  // namespace

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("procex_studio_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  FreshDirs::instance().add(dir);
  return dir;
}

fs::path copy_test_recipe(const std::string& name, const fs::path& dir) {
  const fs::path recipe = dir / name;
  fs::copy_file(fs::path(PROCEX_TEST_DATA) / name, recipe);
  return recipe;
}

}  // namespace procex::studio::driver

// Where a batch's temporary files live and what is left of them: every one
// beside the output (on the disk that is to hold it, so the final rename
// works and /tmp does not fill), none in TMPDIR; none left after a run that
// succeeds, fails, or is stopped by SIGINT or SIGTERM, and the output of the
// run before intact. The spools are unnamed (O_TMPFILE: they show in
// /proc/PID/fd as "FOLDER/#INODE (deleted)"); the staged output and report
// are named TARGET.tmp-PID-N beside their targets.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli/batch_command.h"
#include "app/cli/recipe_session.h"
#include "tests/app/command_test.h"
#include "tests/app/generated_footprints.h"
#include "tests/app/spawn_procex.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const fs::path kSamples = PROCEX_SAMPLES;

// The files process `pid` has open, by where they are.
std::vector<fs::path> open_files(pid_t pid) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it("/proc/" + std::to_string(pid) + "/fd", ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code read;
    const fs::path target = fs::read_symlink(it->path(), read);
    if (!read) out.push_back(target);
  }
  return out;
}

std::size_t count_in(const std::vector<fs::path>& files, const fs::path& folder) {
  std::size_t n = 0;
  for (const fs::path& f : files) n += f.parent_path() == folder;
  return n;
}

// Each file in `folder` and its bytes.
std::map<std::string, std::string> contents(const fs::path& folder) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) out[e.path().filename().string()] = read_text(e.path());
  return out;
}

bool has_name_with(const fs::path& folder, const std::string& part) {
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().find(part) != std::string::npos) return true;
  return false;
}

class BatchTemporaryFiles : public test::CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    out_dir_ = dir_ / "out", tmp_dir_ = dir_ / "tmp";
    fs::create_directories(out_dir_), fs::create_directories(tmp_dir_);
    test::write_footprints(dir_ / "footprints.geojson", 3000);
    // The run before: what an interrupted or failed run must leave as it was.
    std::ofstream(out_dir_ / "city.glb") << "the previous run's .glb";
    std::ofstream(out_dir_ / "city.json") << "the previous run's report";
    before_ = contents(out_dir_);
  }

  // Starts `procex batch` into out/city.glb with TMPDIR set to tmp/.
  pid_t start() {
    return test::spawn_procex({"batch", (kSamples / "city.pxg").string(), "--footprints",
                               (dir_ / "footprints.geojson").string(), "-o", (out_dir_ / "city.glb").string(),
                               "--report", (out_dir_ / "city.json").string(), "--jobs", "1", "--no-progress"},
                              {"TMPDIR=" + tmp_dir_.string()}, test::ChildStderr::kDiscard);
  }

  // Watches the run's open files until `ready` says so (true) or it ends
  // (false); any file it opens in TMPDIR fails the test.
  template <class Ready>
  bool watch(pid_t pid, Ready ready) {
    while (true) {
      const std::vector<fs::path> open = open_files(pid);
      EXPECT_EQ(count_in(open, tmp_dir_), 0u) << "a temporary file in TMPDIR";
      most_open_beside_ = std::max(most_open_beside_, count_in(open, out_dir_));
      if (ready(open)) return true;
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        status_ = status;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }

  int wait(pid_t pid) {
    int status = 0;
    EXPECT_EQ(::waitpid(pid, &status, 0), pid);
    return status;
  }

  // Stops a run with `signal` once `ready`; then the output folder is as the
  // run before left it and TMPDIR is empty.
  template <class Ready>
  void stop_when(int signal, Ready ready) {
    const pid_t pid = start();
    ASSERT_TRUE(watch(pid, ready)) << "the run ended (status " << status_ << ") before it could be stopped";
    ASSERT_EQ(::kill(pid, signal), 0);
    const int status = wait(pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
    EXPECT_EQ(contents(out_dir_), before_) << "the previous output is not intact, or a temporary file was left";
    EXPECT_TRUE(fs::is_empty(tmp_dir_));
  }

  fs::path out_dir_, tmp_dir_;
  std::map<std::string, std::string> before_;
  std::size_t most_open_beside_ = 0;
  int status_ = -1;
};

// The footprints' spool, the report's entries and the .glb's nine spools.
constexpr std::size_t kSpools = 11;

TEST_F(BatchTemporaryFiles, ARunThatSucceedsKeepsThemBesideTheOutputAndLeavesNone) {
  const pid_t pid = start();
  EXPECT_FALSE(watch(pid, [](const auto&) { return false; }));
  EXPECT_TRUE(WIFEXITED(status_) && WEXITSTATUS(status_) == 0) << "status " << status_;
  EXPECT_GE(most_open_beside_, kSpools);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out_dir_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"city.glb", "city.json"}));
  EXPECT_NE(read_text(out_dir_ / "city.glb"), before_["city.glb"]);
  EXPECT_TRUE(fs::is_empty(tmp_dir_));
}

// SIGINT while the buildings are made: the report is staged (named, beside
// it) and every spool is open.
TEST_F(BatchTemporaryFiles, SigintWhileBuildingsAreMadeLeavesNone) {
  stop_when(SIGINT, [&](const std::vector<fs::path>& open) {
    return count_in(open, out_dir_) >= kSpools && has_name_with(out_dir_, "city.json.tmp-");
  });
}

// SIGTERM while the .glb is copied from its spools into its staged file.
TEST_F(BatchTemporaryFiles, SigtermWhileTheGlbIsWrittenLeavesNone) {
  stop_when(SIGTERM, [&](const std::vector<fs::path>&) { return has_name_with(out_dir_, "city.glb.tmp-"); });
}

// A run that fails (the .glb writer refuses a file past its limit, after some
// windows are spooled) closes its spools and leaves the previous output.
TEST_F(BatchTemporaryFiles, ARunThatFailsLeavesNone) {
  test::write_footprints(dir_ / "few.geojson", 1000);  // too few for a sample ahead: the writer judges
  BatchCommandOptions o;
  o.recipe = kSamples / "city.pxg";
  o.footprints = dir_ / "few.geojson";
  o.output = out_dir_ / "city.glb";
  o.report = out_dir_ / "city.json";
  o.jobs = 1, o.progress = false;
  o.glb_max_bytes = 3'000'000;  // about a fifth of the 1000 buildings' .glb
  EXPECT_EQ(run_batch(o, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("buildings made; nothing written"), std::string::npos) << err_.str();
  EXPECT_EQ(contents(out_dir_), before_);
  EXPECT_EQ(count_in(open_files(::getpid()), out_dir_), 0u);
}

}  // namespace
}  // namespace procex

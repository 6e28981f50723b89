// AtomicFileSet: files that change together or not at all, and no temporary
// file left behind by a failure or by SIGTERM / SIGINT in the middle.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/atomic_file_set.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

class AtomicFiles : public test::ScratchDirTest {
 protected:
  std::size_t files() { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
};

TEST_F(AtomicFiles, AllOrNothing) {
  {
    AtomicFileSet set;
    set.add(dir_ / "mesh.obj", "mesh");
    set.add(dir_ / "report.json", "draft");
    set.add(dir_ / "report.json", "final");  // replaces the draft
    EXPECT_FALSE(fs::exists(dir_ / "mesh.obj"));
    set.commit();
  }
  EXPECT_EQ(test::read_text(dir_ / "mesh.obj"), "mesh");
  EXPECT_EQ(test::read_text(dir_ / "report.json"), "final");
  EXPECT_EQ(files(), 2u);
  {
    AtomicFileSet set;
    set.add(dir_ / "mesh.obj", "new mesh");
    EXPECT_THROW(set.add(dir_ / "missing" / "report.json", "x"), IoError);
  }  // never committed: the old files stay, no temporary is left
  EXPECT_EQ(test::read_text(dir_ / "mesh.obj"), "mesh");
  EXPECT_EQ(files(), 2u);
  // A folder in the way is found before anything is renamed (an .obj whose .mtl went first).
  fs::create_directories(dir_ / "isdir.obj");
  {
    AtomicFileSet set;
    set.add(dir_ / "isdir.mtl", "mtl");
    set.add(dir_ / "isdir.obj", "obj");
    EXPECT_THROW(set.commit(), IoError);
  }
  EXPECT_FALSE(fs::exists(dir_ / "isdir.mtl"));
  EXPECT_EQ(files(), 3u);
}

// A process stopped with SIGTERM or SIGINT while its files are staged
// removes them and still dies of the signal.
TEST_F(AtomicFiles, ASignalRemovesTheTemporaries) {
  for (const int sig : {SIGTERM, SIGINT}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      AtomicFileSet set;
      set.add(dir_ / "big.glb", std::string(1 << 20, 'x'));
      ::raise(sig);
      ::_exit(0);  // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_EQ(files(), 0u) << "a temporary file was left behind";
  }
}

}  // namespace
}  // namespace procex

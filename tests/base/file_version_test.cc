// file_version: an edit shows in the version even where it keeps the file's
// size and modification time (written again within one tick of the file
// system's clock); an unchanged file keeps its version; a missing one has its own.
// A FileVersionMemo answers each file as it first saw it.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/file_version.h"
#include "base/file_version_memo.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

class FileVersionTest : public test::ScratchDirTest {
 protected:
};

TEST_F(FileVersionTest, AnEditWithinOneTickAtTheSameSizeIsANewVersion) {
  const fs::path file = dir_ / "door.mtl";
  std::ofstream(file) << "Kd 0.2 0.25 0.3\n";
  const auto tick = fs::file_time_type::clock::now();
  fs::last_write_time(file, tick);
  const FileVersion first = file_version(file);
  EXPECT_EQ(file_version(file), first);
  std::ofstream(file) << "Kd 0.7 0.25 0.3\n";
  fs::last_write_time(file, tick);  // as if written within the same tick
  const FileVersion second = file_version(file);
  EXPECT_EQ(second.size, first.size);
  EXPECT_EQ(second.time, first.time);
  EXPECT_NE(second, first);
  EXPECT_EQ(file_version(file), second);
}

TEST_F(FileVersionTest, AMissingFileOrAFolderHasNoContent) {
  const FileVersion missing = file_version(dir_ / "missing.png");
  EXPECT_EQ(missing.size, static_cast<std::uintmax_t>(-1));
  EXPECT_EQ(missing.content, 0u);
  EXPECT_EQ(file_version(dir_).content, 0u);
  std::ofstream(dir_ / "missing.png") << "x";
  EXPECT_NE(file_version(dir_ / "missing.png"), missing);
}

TEST_F(FileVersionTest, AMemoKeepsTheVersionItSawFirst) {
  const fs::path file = dir_ / "window.obj";
  std::ofstream(file) << "v 0 0 0\n";
  FileVersionMemo memo;
  const FileVersion first = memo.version(file);
  EXPECT_EQ(first, file_version(file));
  std::ofstream(file) << "v 0 0 0\nv 1 0 0\n";
  EXPECT_NE(file_version(file), first);
  EXPECT_EQ(memo.version(file), first);
  EXPECT_EQ(file_version(file, &memo), first);
  EXPECT_EQ(file_version(file, nullptr), file_version(file));
  FileVersionMemo later;
  EXPECT_EQ(later.version(file), file_version(file));
}

}  // namespace
}  // namespace procex

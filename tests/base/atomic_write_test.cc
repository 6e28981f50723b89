// write_file_atomically: whole files or nothing, temporary files never left
// behind, failures named.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "base/atomic_write.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

class AtomicWrite : public test::ScratchDirTest {
 protected:
  std::size_t files() { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }
};

TEST_F(AtomicWrite, WritesAndReplacesWholeFiles) {
  const fs::path file = dir_ / "a.txt";
  write_file_atomically(file, "first");
  EXPECT_EQ(test::read_text(file), "first");
  write_file_atomically(file, std::string("second\0with a zero byte", 23));
  EXPECT_EQ(test::read_text(file), std::string("second\0with a zero byte", 23));
  write_file_atomically(file, "");
  EXPECT_EQ(test::read_text(file), "");
  EXPECT_EQ(files(), 1u);  // no temporary file left
}

// More pieces than one writev takes (IOV_MAX, 1024 on Linux), empty ones among them.
TEST_F(AtomicWrite, PiecesAreWrittenInOrder) {
  std::vector<std::string> texts;
  for (int i = 0; i < 3000; ++i) texts.push_back(i % 7 == 0 ? std::string() : std::to_string(i) + ",");
  const std::vector<std::string_view> pieces(texts.begin(), texts.end());
  std::string joined;
  for (const std::string& t : texts) joined += t;
  write_file_atomically(dir_ / "pieces.txt", pieces);
  EXPECT_EQ(test::read_text(dir_ / "pieces.txt"), joined);
  EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicWrite, FailuresNameTheFileAndLeaveNothing) {
  fs::create_directories(dir_ / "taken");  // a folder where the file should go: the rename fails
  try {
    write_file_atomically(dir_ / "taken", "x");
    FAIL() << "writing over a folder succeeded";
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), (dir_ / "taken").string());
    EXPECT_NE(std::string(e.what()).find("taken"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_file_atomically(dir_ / "no_such_folder" / "a.txt", "x"), IoError);
  EXPECT_EQ(files(), 1u);  // only the folder: the temporary file was removed
}

// Concurrent writers to one file: each write is whole, the last rename wins.
TEST_F(AtomicWrite, ConcurrentWritersNeverMix) {
  const fs::path file = dir_ / "shared.txt";
  std::vector<std::thread> writers;
  for (char c = 'a'; c < 'e'; ++c)
    writers.emplace_back([&file, c] {
      for (int i = 0; i < 20; ++i) write_file_atomically(file, std::string(100000, c));
    });
  for (std::thread& t : writers) t.join();
  const std::string text = test::read_text(file);
  ASSERT_EQ(text.size(), 100000u);
  EXPECT_EQ(text, std::string(100000, text[0]));
  EXPECT_EQ(files(), 1u);
}

}  // namespace
}  // namespace procex

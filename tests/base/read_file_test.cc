// read_file: whatever a path names (a folder, a FIFO, a huge file), a clear
// IoError or the bytes; never a hang or an allocation the size of a folder.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "base/read_file.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

class ReadFile : public test::ScratchDirTest {
 protected:
  std::string error_of(const fs::path& p, std::size_t limit = 1 << 20) {
    try {
      read_file(p, limit);
    } catch (const IoError& e) {
      EXPECT_EQ(e.path(), p.string());
      return e.what();
    }
    return "read without error";
  }
};

TEST_F(ReadFile, ReadsTheBytes) {
  std::ofstream(dir_ / "a.txt", std::ios::binary) << std::string("ab\0c", 4);
  EXPECT_EQ(read_file(dir_ / "a.txt", 4), std::string("ab\0c", 4));
  std::ofstream(dir_ / "empty.txt").close();
  EXPECT_EQ(read_file(dir_ / "empty.txt", 4), "");
}

TEST_F(ReadFile, RefusesWhatIsNotARegularFileWithItsReason) {
  EXPECT_NE(error_of(dir_).find("it is a folder, not a file"), std::string::npos) << error_of(dir_);
  EXPECT_NE(error_of(dir_ / "missing").find("No such file"), std::string::npos);
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);  // no writer: a blocking open would hang
  EXPECT_NE(error_of(dir_ / "fifo").find("not a regular file"), std::string::npos) << error_of(dir_ / "fifo");
  std::ofstream(dir_ / "big.txt") << std::string(100, 'x');
  EXPECT_NE(error_of(dir_ / "big.txt", 99).find("100 bytes; the limit"), std::string::npos) << error_of(dir_ / "big.txt", 99);
}

}  // namespace
}  // namespace procex

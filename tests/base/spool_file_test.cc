// SpoolFile: bytes set aside come back in order, whatever the sizes of the
// appends (around and past its buffer), and go into a file written
// atomically between pieces from memory.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/atomic_write.h"
#include "base/io_error.h"
#include "base/spool_file.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

// Appends of sizes from 0 bytes to several megabytes, each byte telling its position.
std::vector<std::string> appends() {
  std::vector<std::string> out;
  std::size_t at = 0;
  for (const std::size_t n : {0, 1, 7, 1000, (1 << 20) - 3, 5, (3 << 20) + 11, 0, 65536, 2}) {
    std::string s(n, '\0');
    for (char& c : s) c = static_cast<char>((at++ * 131) % 251);
    out.push_back(std::move(s));
  }
  return out;
}

TEST(SpoolFile, GivesBackEveryByteInOrder) {
  SpoolFile spool(fs::temp_directory_path());
  std::string expected;
  for (const std::string& s : appends()) {
    spool.append(s);
    expected += s;
    EXPECT_EQ(spool.size(), expected.size());
    std::string back;
    spool.read([&](std::string_view chunk) { back += chunk; });
    ASSERT_EQ(back, expected);
  }
}

// Each append read back alone, from the file, the buffer or across the two,
// and a range past the end refused.
TEST(SpoolFile, GivesBackARangeAlone) {
  SpoolFile spool(fs::temp_directory_path());
  std::string all;
  std::vector<std::pair<std::uint64_t, std::string>> records;
  for (const std::string& s : appends()) {
    records.emplace_back(spool.size(), s);
    spool.append(s), all += s;
    for (const auto& [at, bytes] : records) ASSERT_EQ(spool.read_at(at, bytes.size()), bytes) << at;
  }
  EXPECT_EQ(spool.read_at((1 << 20) - 100, 300), all.substr((1 << 20) - 100, 300));
  EXPECT_EQ(spool.read_at(all.size() - 3, 3), all.substr(all.size() - 3));
  EXPECT_THROW(spool.read_at(all.size() - 3, 4), IoError);
}

TEST(SpoolFile, IsCopiedIntoAFileBetweenOtherPieces) {
  const fs::path dir = fs::temp_directory_path() / ("procex_spool_file_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  SpoolFile spool(dir), empty(dir);
  std::string middle;
  for (const std::string& s : appends()) spool.append(s), middle += s;
  const FilePiece pieces[] = {{"head "}, {{}, &spool}, {{}, &empty}, {" tail"}};
  write_file_atomically(dir / "out.bin", pieces);
  std::ifstream in(dir / "out.bin", std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), "head " + middle + " tail");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 1);  // no temporary file left beside it
  fs::remove_all(dir);
}

// The files this process has open in `folder` (an unnamed one shows as
// "folder/#inode (deleted)").
std::vector<std::string> open_in(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& fd : fs::directory_iterator("/proc/self/fd")) {
    std::error_code ec;
    const fs::path target = fs::read_symlink(fd.path(), ec);
    if (!ec && target.parent_path() == folder) out.push_back(target.string());
  }
  return out;
}

// A spool is made in the folder it is given (beside an output, on its disk),
// leaves no name there, and is gone when dropped; a folder where none can be
// made is named in the error.
TEST(SpoolFile, LivesInItsFolderAndGoesWhenDropped) {
  const fs::path dir = fs::temp_directory_path() / ("procex_spool_folder_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    SpoolFile spool(dir.string());
    spool.append(std::string(3 << 20, 'x'));  // past the buffer: in the file
    EXPECT_EQ(open_in(dir).size(), 1u);
    EXPECT_TRUE(fs::is_empty(dir));
  }
  EXPECT_TRUE(open_in(dir).empty());
  try {
    SpoolFile spool((dir / "missing").string());
    ADD_FAILURE() << "a spool in a missing folder was made";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "missing").string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(folder_beside("city.glb"), ".");
  EXPECT_EQ(folder_beside(dir / "city.glb"), dir.string());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace procex

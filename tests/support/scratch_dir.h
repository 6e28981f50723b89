// A folder of a test's own under the system's temporary folder: named for the
// test and the process (ctest runs each test in a process of its own, in
// parallel, so two never share one), made empty when the test starts and
// removed with everything in it when it ends, so no test leaves files behind.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace procex::test {

// A whole file's bytes ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("procex_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;  // a test that failed half-way may have left it read-only
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& p) const { return path_ / p; }

 private:
  std::filesystem::path path_;
};

// A fixture whose tests each get a ScratchDir, `dir_`, named for the suite
// and the test.
class ScratchDirTest : public ::testing::Test {
 protected:
  static std::string test_name() {
    const ::testing::TestInfo* t = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(t->test_suite_name()) + "_" + t->name();
    for (char& c : name)
      if (c == '/') c = '_';  // parameterised tests' names
    return name;
  }
  ScratchDir scratch_{test_name()};
  const std::filesystem::path& dir_ = scratch_.path();
};

}  // namespace procex::test

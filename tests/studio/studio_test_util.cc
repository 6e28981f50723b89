#include "tests/studio/studio_test_util.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace procex::studio::test {

std::filesystem::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "procex_studio_tests" /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path house_recipe() { return std::filesystem::path(PROCEX_TEST_DATA) / "house.pxg"; }

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace procex::studio::test

// studio_test_util.h -- shared helpers for the studio's editor tests.
#pragma once

#include <filesystem>
#include <string>

#include "graph/graph.h"

namespace procex::studio::test {

// A fresh, empty folder under the system temp folder, named for the running test.
std::filesystem::path temp_dir();
// The L-shaped house of tests/studio/data/house.pxg.
std::filesystem::path house_recipe();
std::string read_text(const std::filesystem::path& file);

}  // namespace procex::studio::test

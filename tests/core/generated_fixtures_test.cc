// Every failure the generators found, minimised (tests/support/generators/
// shrink.h) and kept as tests/data/generated_<class>_<seed>.geojson, and
// corpus footprints that failed, minimised the same way (generated_<kind>_<OSM
// id>.geojson): each must now pass every property its class checks.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/geojson.h"
#include "tests/support/generators/check_case.h"
#include "tests/support/generators/shrink.h"

namespace procex::testing {
namespace {

std::vector<std::filesystem::path> fixtures() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(PROCEX_TEST_DATA))
    if (e.path().filename().string().rfind("generated_", 0) == 0 && e.path().extension() == ".geojson")
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(GeneratedFixtures, EveryFixturePassesEveryProperty) {
  const std::vector<std::filesystem::path> files = fixtures();
  ASSERT_FALSE(files.empty()) << "no generated_*.geojson in " << PROCEX_TEST_DATA;
  for (const std::filesystem::path& file : files) {
    const GeoJsonCollection read = read_geojson_file(file);
    ASSERT_EQ(read.features.size(), 1u) << file;
    const GeneratedCase c = case_from_fixture(read.features[0]);
    const CaseResult r = check_case(c);
    for (const std::string& line : r.problems) ADD_FAILURE() << file.filename().string() << " (" << c.description << "): " << line;
  }
}

}  // namespace
}  // namespace procex::testing

// Every sample recipe (but city.pxg, which needs footprints bound: see
// tests/app/batch_command_test.cc) evaluates, and its summary matches the one
// stored in samples/expected/<name>.json within the stored tolerance.
// scripts/update-expected.sh rewrites the stored summaries (never ctest).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/support/mesh_summary.h"
#include "tests/expected/sample_summaries.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const fs::path kSamples = PROCEX_SAMPLES;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void expect_close(const json& want, const json& got, const std::string& what) {
  const double length = want["tolerance"]["length"], volume = want["tolerance"]["volume_relative"];
  EXPECT_EQ(want["meshes"], got["meshes"]) << what;
  EXPECT_EQ(want["faces"], got["faces"]) << what;
  EXPECT_EQ(want["faces_per_tag"], got["faces_per_tag"]) << what;
  EXPECT_EQ(want.value("placed", json::object()), got.value("placed", json::object())) << what;
  for (const char* end : {"min", "max"})
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(want["bounds"][end][k].get<double>(), got["bounds"][end][k].get<double>(), length) << what << " " << end;
  EXPECT_NEAR(want["volume"].get<double>(), got["volume"].get<double>(), volume * std::abs(want["volume"].get<double>()))
      << what;
}

class Sample : public ::testing::TestWithParam<std::string> {};

TEST_P(Sample, EvaluatesToItsStoredSummary) {
  const fs::path file = kSamples / (GetParam() + ".pxg");
  const Graph g = load_pxg(file);
  const EvalResult r = test::evaluate_mesh(g, kSamples);
  for (const Diagnostic& d : r.diagnostics) EXPECT_NE(d.severity, Severity::kError) << d.to_string();
  ASSERT_TRUE(r.ok());
  const json got = test::summary_json(summarize(r.output("mesh")->get<MeshSet>()));
  const fs::path expected = kSamples / "expected" / (GetParam() + ".json");
  ASSERT_TRUE(fs::exists(expected)) << expected << " is missing: run scripts/update-expected.sh and review it";
  expect_close(json::parse(read_text(expected)), got, GetParam());
}

TEST_P(Sample, FileIsCanonical) {
  const fs::path file = kSamples / (GetParam() + ".pxg");
  EXPECT_EQ(to_pxg(load_pxg(file)), read_text(file));
}

std::vector<std::string> sample_names() { return test::sample_recipe_names(kSamples); }

INSTANTIATE_TEST_SUITE_P(Samples, Sample, ::testing::ValuesIn(sample_names()),
                         [](const auto& info) { return info.param; });

TEST(Samples, AllAreTested) {
  EXPECT_GE(sample_names().size(), 5u);
  EXPECT_TRUE(fs::exists(kSamples / "city.pxg"));
}

}  // namespace
}  // namespace procex

// Every sample recipe (but city.pxg, which needs footprints bound: see
// tests/app/batch_command_test.cc) evaluates, and its summary matches the one
// stored in samples/expected/<name>.json within the stored tolerance.
// PROCEX_UPDATE_EXPECTED=1 rewrites the stored summaries instead.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/support/mesh_summary.h"
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

// Placed meshes (instances per mesh name) only where a recipe places some.
json summary_json(const MeshSummary& s) {
  json j = {{"meshes", s.meshes},
            {"faces", s.faces},
            {"faces_per_tag", s.faces_per_tag},
            {"bounds", {{"min", {s.min.x, s.min.y, s.min.z}}, {"max", {s.max.x, s.max.y, s.max.z}}}},
            {"volume", s.volume}};
  if (!s.placed.empty()) j["placed"] = s.placed;
  j["tolerance"] = {{"length", 1e-6}, {"volume_relative", 1e-6}};
  return j;
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
  const json got = summary_json(summarize(r.output("mesh")->get<MeshSet>()));
  const fs::path expected = kSamples / "expected" / (GetParam() + ".json");
  if (std::getenv("PROCEX_UPDATE_EXPECTED")) {
    fs::create_directories(expected.parent_path());
    std::ofstream(expected) << got.dump(1) << "\n";
    GTEST_SKIP() << "rewrote " << expected;
  }
  ASSERT_TRUE(fs::exists(expected)) << expected << " is missing: run with PROCEX_UPDATE_EXPECTED=1 once";
  expect_close(json::parse(read_text(expected)), got, GetParam());
}

TEST_P(Sample, FileIsCanonical) {
  const fs::path file = kSamples / (GetParam() + ".pxg");
  EXPECT_EQ(to_pxg(load_pxg(file)), read_text(file));
}

std::vector<std::string> sample_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kSamples))
    if (e.path().extension() == ".pxg" && e.path().stem() != "city") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Samples, Sample, ::testing::ValuesIn(sample_names()),
                         [](const auto& info) { return info.param; });

TEST(Samples, AllAreTested) {
  EXPECT_GE(sample_names().size(), 5u);
  EXPECT_TRUE(fs::exists(kSamples / "city.pxg"));
}

}  // namespace
}  // namespace procex

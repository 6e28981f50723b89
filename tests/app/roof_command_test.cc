// `procex roof` end to end: GeoJSON in, one OBJ and one JSON report out, one
// bad feature never stopping the others, the process exit codes.
#include "app/cli/roof_command.h"
#include "tests/app/sample_block.h"
#include "tests/support/scratch_dir.h"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace procex {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The "g name" lines of an OBJ file, in order.
std::vector<std::string> obj_groups(const fs::path& p) {
  std::vector<std::string> groups;
  std::istringstream in(read_file(p));
  for (std::string line; std::getline(in, line);)
    if (line.rfind("g ", 0) == 0) groups.push_back(line.substr(2));
  return groups;
}

class RoofCommand : public test::ScratchDirTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  RoofOptions options_for(const fs::path& input) {
    RoofOptions o;
    o.input = input;
    o.output = dir_ / "out.obj";
    o.report = dir_ / "report.json";
    return o;
  }
  int run(const RoofOptions& o) {
    out_.str(""), err_.str("");
    return run_roof(o, out_, err_);
  }
  nlohmann::json report() { return nlohmann::json::parse(read_file(dir_ / "report.json")); }

  std::ostringstream out_, err_;
};

std::string feature(const std::string& id, const std::string& geometry, const std::string& properties = "{}") {
  return R"({"type":"Feature","id":")" + id + R"(","properties":)" + properties + R"(,"geometry":)" + geometry + "}";
}

std::string collection(const std::vector<std::string>& features) {
  std::string s = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i < features.size(); ++i) s += (i ? "," : "") + features[i];
  return s + "]}";
}

const std::string kSquare10 = R"({"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]]]})";

TEST_F(RoofCommand, SampleBlockEveryFeatureOk) {
  RoofOptions o = options_for(test::kSampleBlock);
  o.angle_deg = 40.0;
  ASSERT_EQ(run(o), 0) << err_.str();
  const nlohmann::json r = report();
  ASSERT_EQ(r["features"].size(), 18u);
  EXPECT_EQ(r["summary"]["features"], 18);
  EXPECT_EQ(r["summary"]["ok"], 18) << err_.str();
  EXPECT_EQ(r["summary"]["failed"], 0);
  std::vector<std::string> ids;
  for (const auto& f : r["features"]) {
    ids.push_back(f["id"]);
    EXPECT_EQ(f["status"], "ok") << f.dump();
    EXPECT_TRUE(f["validation"]["ok"].get<bool>()) << f.dump();
    EXPECT_GT(f["volume"].get<double>(), 0.0);
    EXPECT_GT(f["max_height"].get<double>(), 0.0);
    EXPECT_GT(f["faces"].get<int>(), 0);
  }
  EXPECT_EQ(obj_groups(dir_ / "out.obj"), ids);
}

TEST_F(RoofCommand, BadFeaturesAreRefusedAndTheOthersStillRun) {
  //   bowtie:  (0,0)-(10,10)-(10,0)-(0,10) crosses itself
  const fs::path in = write(
      "mixed.geojson",
      collection({feature("square", kSquare10),
                  feature("bowtie", R"({"type":"Polygon","coordinates":[[[0,0],[10,10],[10,0],[0,10],[0,0]]]})"),
                  feature("text", R"({"type":"Polygon","coordinates":[[[0,0],["ten",0],[10,10],[0,0]]]})"),
                  feature("two", R"({"type":"MultiPolygon","coordinates":[[[[0,0],[4,0],[4,4],[0,4],[0,0]]],
                                                                        [[[10,0],[14,0],[14,4],[10,4],[10,0]]]]})"),
                  feature("courtyard", R"({"type":"Polygon","coordinates":[[[0,0],[30,0],[30,30],[0,30],[0,0]],
                                                                          [[10,10],[10,20],[20,20],[20,10],[10,10]]]})")}));
  ASSERT_EQ(run(options_for(in)), 0) << err_.str();
  const nlohmann::json r = report();
  ASSERT_EQ(r["features"].size(), 5u);
  const std::vector<std::string> ids = {"square", "bowtie", "text", "two", "courtyard"};
  const std::vector<std::string> status = {"ok", "refused", "refused", "ok", "ok"};
  for (std::size_t i = 0; i < ids.size(); ++i) {
    EXPECT_EQ(r["features"][i]["id"], ids[i]);
    EXPECT_EQ(r["features"][i]["status"], status[i]) << r["features"][i].dump();
  }
  EXPECT_NE(r["features"][1]["reason"].get<std::string>(), "");
  // The reader's reason names where in the file the bad value is.
  EXPECT_NE(r["features"][2]["reason"].get<std::string>().find("/features/2/geometry/coordinates"), std::string::npos)
      << r["features"][2]["reason"];
  EXPECT_EQ(r["summary"]["ok"], 3);
  EXPECT_EQ(r["summary"]["refused"], 2);
  EXPECT_EQ(r["summary"]["failed"], 0);
  EXPECT_EQ(obj_groups(dir_ / "out.obj"), (std::vector<std::string>{"square", "two", "courtyard"}));
  EXPECT_NE(err_.str().find("bowtie"), std::string::npos);
}

// A 10 x 10 square at 45 degrees is a pyramid 5 high: volume 100 * 5 / 3.
TEST_F(RoofCommand, HipRoofVolumeAndHeight) {
  ASSERT_EQ(run(options_for(write("square.geojson", collection({feature("sq", kSquare10)})))), 0) << err_.str();
  const nlohmann::json f = report()["features"][0];
  EXPECT_NEAR(f["max_height"].get<double>(), 5.0, 1e-9);
  EXPECT_NEAR(f["volume"].get<double>(), 500.0 / 3.0, 1e-6);
}

// Each roof says the clustering scale it closed at and what it was held to:
// the square at the first scale, to 1e-6 of its diagonal; the jittered star
// of tests/data/star_coarse_2226.geojson only at the coarsest (1e-5, after
// three finer ones), so to ten times that.
TEST_F(RoofCommand, EachRoofSaysTheScaleItClosedAtAndTheToleranceItWasHeldTo) {
  ASSERT_EQ(run(options_for(write("square.geojson", collection({feature("sq", kSquare10)})))), 0) << err_.str();
  const nlohmann::json square = report()["features"][0];
  EXPECT_EQ(square["clustering_scale"], 1e-8);
  EXPECT_EQ(square["retries"], 0);
  EXPECT_NEAR(square["validation"]["tolerance"].get<double>(), 1e-6 * std::sqrt(10.0 * 10.0 * 2 + 5.0 * 5.0), 1e-15);

  ASSERT_EQ(run(options_for(fs::path(PROCEX_TEST_DATA) / "star_coarse_2226.geojson")), 0) << err_.str();
  const nlohmann::json star = report()["features"][0];
  EXPECT_EQ(star["status"], "ok") << star.dump();
  EXPECT_EQ(star["clustering_scale"], 1e-5);
  EXPECT_EQ(star["retries"], 3);
  EXPECT_GT(star["validation"]["max_planarity_error"].get<double>(), 1e-3);
  EXPECT_GT(star["validation"]["tolerance"].get<double>(), 1e-4 * 200.0);
}

// Capped at 2: a frustum, the integral of (10 - 2z)^2 from 0 to 2 = 392 / 3.
TEST_F(RoofCommand, MaxHeightCapsTheRoof) {
  RoofOptions o = options_for(write("square.geojson", collection({feature("sq", kSquare10)})));
  o.max_height = 2.0;
  ASSERT_EQ(run(o), 0) << err_.str();
  const nlohmann::json f = report()["features"][0];
  EXPECT_NEAR(f["max_height"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(f["volume"].get<double>(), 392.0 / 3.0, 1e-6);
  EXPECT_EQ(report()["options"]["max_height"], 2.0);
}

// A footprint past the budget fails on its own with the limit it passed; the
// others in the file still run.
TEST_F(RoofCommand, BudgetRefusesAFootprintWithTheReason) {
  std::ostringstream ring_text;
  ring_text << "[";
  for (int k = 0; k < 200; ++k)
    ring_text << "[" << 10.0 * std::cos(2 * M_PI * k / 200) << "," << 10.0 * std::sin(2 * M_PI * k / 200) << "],";
  ring_text << "[10,0]]";
  const std::string ring = ring_text.str();
  RoofOptions o = options_for(write("two.geojson", collection({feature("sq", kSquare10),
                                                               feature("round", R"({"type":"Polygon","coordinates":[)" +
                                                                                    ring + "]}")})));
  o.budget.max_vertices = 100;
  EXPECT_EQ(run(o), kExitFeatureFailed);
  const nlohmann::json r = report();
  EXPECT_EQ(r["features"][0]["status"], "ok");
  EXPECT_EQ(r["features"][1]["status"], "failed");
  EXPECT_NE(r["features"][1]["reason"].get<std::string>().find("vertex budget"), std::string::npos)
      << r["features"][1]["reason"];
}

//   +-------------------+   a 10 x 6 gable: long sides at 45 degrees meet in a
//   |                   |   ridge 3 high, the short ends are vertical walls;
//   +-------------------+   volume 10 * (6 * 3 / 2) = 90.
TEST_F(RoofCommand, AnglesPropertyGivesPerEdgeAngles) {
  const std::string rect = R"({"type":"Polygon","coordinates":[[[0,0],[10,0],[10,6],[0,6],[0,0]]]})";
  const fs::path in = write("angles.geojson",
                            collection({feature("gable", rect, R"({"pitch":[[45,0,45,0]]})"),
                                        feature("short", rect, R"({"pitch":[[45,0,45]]})"),
                                        feature("none", rect)}));
  RoofOptions o = options_for(in);
  o.angles_property = "pitch";
  o.angle_deg = 30.0;
  ASSERT_EQ(run(o), 0) << err_.str();
  const nlohmann::json r = report();
  EXPECT_EQ(r["features"][0]["status"], "ok") << r["features"][0].dump();
  EXPECT_NEAR(r["features"][0]["max_height"].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(r["features"][0]["volume"].get<double>(), 90.0, 1e-6);
  EXPECT_EQ(r["features"][1]["status"], "refused") << "3 angles for 4 edges";
  // Without the property the feature falls back to --angle, and says so.
  EXPECT_EQ(r["features"][2]["status"], "ok");
  ASSERT_FALSE(r["features"][2]["notes"].empty());
  EXPECT_NE(r["features"][2]["notes"][0].get<std::string>().find("pitch"), std::string::npos);
}

TEST_F(RoofCommand, UnreadableInputWritesNothing) {
  EXPECT_EQ(run(options_for(dir_ / "missing.geojson")), kExitUnusableFile);
  EXPECT_NE(err_.str().find("missing.geojson"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "out.obj"));
  EXPECT_FALSE(fs::exists(dir_ / "report.json"));
  EXPECT_EQ(run(options_for(write("array.geojson", "[1, 2]"))), kExitUnusableFile);
}

TEST_F(RoofCommand, UnwritableOutputIsAnError) {
  RoofOptions o = options_for(write("square.geojson", collection({feature("sq", kSquare10)})));
  o.output = dir_ / "no" / "such" / "dir" / "out.obj";
  EXPECT_EQ(run(o), kExitUnusableFile);
  EXPECT_NE(err_.str().find("out.obj"), std::string::npos) << err_.str();
}

// Parallel runs must not change a byte of the mesh or the order of the report.
TEST_F(RoofCommand, OutputDoesNotDependOnJobs) {
  RoofOptions o = options_for(test::kSampleBlock);
  std::string obj[2];
  nlohmann::json features[2];
  for (int k = 0; k < 2; ++k) {
    o.jobs = k + 1;
    ASSERT_EQ(run(o), 0) << err_.str();
    obj[k] = read_file(o.output);
    features[k] = report()["features"];
    for (auto& f : features[k]) {
      f.erase("ms");
      if (f["validation"].is_object()) f["validation"].erase("ms");
    }
  }
  EXPECT_EQ(obj[0], obj[1]);
  EXPECT_EQ(features[0], features[1]);
}

int exit_code_of(const std::string& command) {
  const int status = std::system((command + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(RoofCommand, ExecutableExitCodes) {
  const std::string exe = PROCEX_CLI_EXE;
  const std::string sample = test::kSampleBlock.string();
  const std::string outs = " -o " + (dir_ / "out.obj").string() + " --report " + (dir_ / "report.json").string();
  EXPECT_EQ(exit_code_of(exe + " roof " + sample + " --angle 40 --jobs 2" + outs), 0);
  EXPECT_TRUE(fs::exists(dir_ / "report.json"));
  fs::remove(dir_ / "out.obj"), fs::remove(dir_ / "report.json");
  EXPECT_NE(exit_code_of(exe + " roof " + sample + " --angle 120" + outs), 0) << "angle out of [-90, 90]";
  EXPECT_NE(exit_code_of(exe + " roof " + sample + " --max-height -1" + outs), 0);
  EXPECT_NE(exit_code_of(exe + " roof " + sample), 0) << "-o and --report are required";
  EXPECT_NE(exit_code_of(exe), 0) << "a subcommand is required";
  // NaN passes every comparison: refused like any other bad option, with procex's code, not CLI11's (104-109).
  EXPECT_EQ(exit_code_of(exe + " roof " + sample + " --angle nan" + outs), kExitUnusableFile);
  EXPECT_EQ(exit_code_of(exe + " roof " + sample + " --max-height nan" + outs), kExitUnusableFile);
  EXPECT_EQ(exit_code_of(exe + " roof " + sample + " --jobs x" + outs), kExitUnusableFile);
  EXPECT_EQ(exit_code_of(exe + " batch x.pxg --footprints y -o z.glb --shard 0/-2"), kExitUnusableFile);
  EXPECT_EQ(exit_code_of(exe + " --version"), 0);
  EXPECT_EQ(exit_code_of(exe + " roof --help"), 0);
  EXPECT_FALSE(fs::exists(dir_ / "out.obj"));
  EXPECT_EQ(exit_code_of(exe + " roof " + (dir_ / "missing.geojson").string() + outs), kExitUnusableFile);
}

}  // namespace
}  // namespace procex

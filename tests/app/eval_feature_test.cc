// procex eval --footprints F --feature ID: one feature bound exactly as
// procex batch binds each one (same bytes as batch's per-building file),
// properties set exposed parameters, and bad choices name the problem.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "app/cli/recipe_session.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = PROCEX_SAMPLES;
const fs::path& kBlock = test::kSampleBlock;

using test::read_text;

// The same 20 m x 12 m plan three times: a church, a garage; then a point, which is no footprint.
constexpr const char* kTwoTypes = R"({"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "church_1", "properties": {"building": "church"},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[20,0],[20,12],[0,12],[0,0]]]}},
 {"type": "Feature", "id": "garage_1", "properties": {"building": "garage"},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[20,0],[20,12],[0,12],[0,0]]]}},
 {"type": "Feature", "id": "broken", "properties": {},
  "geometry": {"type": "Point", "coordinates": [0,0]}}
]})";

class EvalFeature : public test::CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    std::ofstream(dir_ / "two_types.geojson") << kTwoTypes;
  }
  EvalCommandOptions options(const fs::path& footprints, const std::string& feature, const fs::path& output) {
    EvalCommandOptions o;
    o.recipe = kSamples / "city.pxg";
    o.output = output;
    o.footprints = footprints;
    o.feature = feature;
    return o;
  }
  double top(const fs::path& obj) {
    double z = -1e300;
    std::istringstream in(read_text(obj));
    for (std::string line; std::getline(in, line);)
      if (line.rfind("v ", 0) == 0) {
        double x, h, south;  // +Y up
        std::istringstream(line.substr(2)) >> x >> h >> south;
        z = std::max(z, h);
      }
    return z;
  }
};

// Byte for byte what batch writes for that building, by id and by index.
TEST_F(EvalFeature, SameBytesAsBatchPerBuilding) {
  BatchCommandOptions b;
  b.recipe = kSamples / "city.pxg";
  b.footprints = kBlock;
  b.output = dir_ / "batch/";
  b.format = "obj";
  b.progress = false;
  ASSERT_EQ(run_batch(b, out_, err_), 0) << err_.str();
  fs::create_directories(dir_ / "by_id");
  fs::create_directories(dir_ / "by_index");
  ASSERT_EQ(run_eval(options(kBlock, "w49209552", dir_ / "by_id" / "w49209552.obj"), out_, err_), 0) << err_.str();
  ASSERT_EQ(run_eval(options(kBlock, "2", dir_ / "by_index" / "w49209552.obj"), out_, err_), 0) << err_.str();
  const std::string want = read_text(dir_ / "batch" / "w49209552.obj");
  ASSERT_FALSE(want.empty());
  EXPECT_EQ(read_text(dir_ / "by_id" / "w49209552.obj"), want);
  EXPECT_EQ(read_text(dir_ / "by_index" / "w49209552.obj"), want);
}

// The property `building` chooses the Switch case: a church is taller than a garage on the same plan.
TEST_F(EvalFeature, PropertiesSetExposedParameters) {
  const fs::path file = dir_ / "two_types.geojson";
  ASSERT_EQ(run_eval(options(file, "church_1", dir_ / "church.obj"), out_, err_), 0) << err_.str();
  ASSERT_EQ(run_eval(options(file, "1", dir_ / "garage.obj"), out_, err_), 0) << err_.str();
  EXPECT_GT(top(dir_ / "church.obj"), 12.0);
  EXPECT_LT(top(dir_ / "garage.obj"), 12.0);
  EXPECT_GT(top(dir_ / "church.obj"), top(dir_ / "garage.obj"));
}

TEST_F(EvalFeature, BadChoicesNameTheProblem) {
  const fs::path file = dir_ / "two_types.geojson";
  EXPECT_EQ(run_eval(options(file, "nope", dir_ / "x.obj"), out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("no feature with id or index 'nope' (3 features)"), std::string::npos) << err_.str();
  err_.str("");
  EXPECT_EQ(run_eval(options(file, "7", dir_ / "x.obj"), out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("'7'"), std::string::npos) << err_.str();
  err_.str("");
  EXPECT_EQ(run_eval(options(file, "broken", dir_ / "x.obj"), out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("feature broken (index 2)"), std::string::npos) << err_.str();
  err_.str("");
  EXPECT_EQ(run_eval(options(dir_ / "missing.geojson", "0", dir_ / "x.obj"), out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("missing.geojson"), std::string::npos) << err_.str();
  err_.str("");
  EvalCommandOptions house = options(file, "0", dir_ / "x.obj");
  house.recipe = kSamples / "house.pxg";
  EXPECT_EQ(run_eval(house, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("graph input named 'footprint'"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "x.obj"));
}

// --footprints and --feature go together.
TEST_F(EvalFeature, ExecutableNeedsBothOptions) {
  const std::string eval = std::string(PROCEX_CLI_EXE) + " eval " + (kSamples / "city.pxg").string() + " -o " +
                           (dir_ / "x.glb").string();
  auto run = [](const std::string& cmd) { return WEXITSTATUS(std::system((cmd + " >/dev/null 2>&1").c_str())); };
  EXPECT_NE(run(eval + " --footprints " + kBlock.string()), 0);
  EXPECT_NE(run(eval + " --feature 0"), 0);
  EXPECT_EQ(run(eval + " --footprints " + kBlock.string() + " --feature 0"), 0);
  EXPECT_TRUE(fs::exists(dir_ / "x.glb"));
}

}  // namespace
}  // namespace procex

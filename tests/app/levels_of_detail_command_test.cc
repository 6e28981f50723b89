// `procex eval/batch --lod N`: one recipe written at each level of detail, a
// file per level (x.lod0.glb ... x.lod3.glb), each accepted by the Khronos
// glTF validator without errors or warnings. (Not glTF's MSFT_lod in one
// file: the validator cannot check that extension, only note it, and
// three.js's loader ignores it.)
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"
#include "tests/support/gltf_scripts.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
const fs::path kSamples = PROCEX_SAMPLES;

class LodCommand : public test::CommandTest {
 protected:
  void expect_valid(const fs::path& glb) {
    SCOPED_TRACE(glb.filename().string());
    const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", glb);
    ASSERT_EQ(v.problem, "");
    EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
    EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
    triangles_.push_back(v.report["info"]["totalTriangleCount"].get<int>());
  }
  std::vector<int> triangles_;
};

TEST_F(LodCommand, EvalWritesEachLevelAsAValidFile) {
  for (int lod = 0; lod <= 3; ++lod) {
    EvalCommandOptions o;
    o.recipe = kSamples / "setback_tower.pxg";
    o.output = dir_ / ("tower.lod" + std::to_string(lod) + ".glb");
    o.lod = lod;
    ASSERT_EQ(run_eval(o, out_, err_), 0) << err_.str();
    expect_valid(o.output);
  }
  ASSERT_EQ(triangles_.size(), 4u);
  // Footprint < block < the stepped tower < the tower with its windows.
  EXPECT_LT(triangles_[0], triangles_[1]);
  EXPECT_LT(triangles_[1], triangles_[2]);
  EXPECT_LT(triangles_[2], triangles_[3]);
  EXPECT_NE(out_.str().find("placed meshes -> " + (dir_ / "tower.lod3.glb").string()), std::string::npos) << out_.str();
  EXPECT_EQ(out_.str().find("placed meshes -> " + (dir_ / "tower.lod2.glb").string()), std::string::npos) << out_.str();
}

TEST_F(LodCommand, BatchWritesBlocksForEveryBuilding) {
  BatchCommandOptions o;
  o.recipe = kSamples / "city.pxg";
  o.footprints = test::kSampleBlock;
  o.output = dir_ / "city.lod1.glb";
  o.report = dir_ / "city.lod1.json";
  o.progress = false;
  o.lod = 1;
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  expect_valid(o.output);
  std::ifstream in(o.report);
  const nlohmann::json report = nlohmann::json::parse(in);
  ASSERT_EQ(report["buildings"].size(), 18u);
  for (const nlohmann::json& b : report["buildings"]) {
    SCOPED_TRACE(b.dump());
    EXPECT_EQ(b["status"], "ok");
  }
}

// The executable's option: 0 to 3, anything else refused before a file is written.
TEST_F(LodCommand, TheExecutableTakesLevelsZeroToThree) {
  const auto run = [&](const std::string& lod, const fs::path& output) {
    const std::string command = std::string(PROCEX_CLI_EXE) + " eval " + (kSamples / "house.pxg").string() + " -o " +
                                output.string() + " --lod " + lod + " >" + (dir_ / "log").string() + " 2>&1";
    return WEXITSTATUS(std::system(command.c_str()));
  };
  EXPECT_EQ(run("1", dir_ / "house.lod1.glb"), 0) << test::read_text(dir_ / "log");
  expect_valid(dir_ / "house.lod1.glb");
  for (const char* bad : {"4", "-1", "two"}) {
    EXPECT_EQ(run(bad, dir_ / "x.glb"), 2) << bad;
    EXPECT_NE(test::read_text(dir_ / "log").find("--lod"), std::string::npos) << test::read_text(dir_ / "log");
    EXPECT_FALSE(fs::exists(dir_ / "x.glb"));
  }
}

}  // namespace
}  // namespace procex

// procex eval / validate / stats / nodes, in process (streams captured) and
// through the real executable for exit codes.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "app/cli/eval_command.h"
#include "app/cli/nodes_command.h"
#include "app/cli/recipe_session.h"
#include "app/cli/stats_command.h"
#include "app/cli/validate_command.h"
#include "tests/app/command_test.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = PROCEX_SAMPLES;

class RecipeCommands : public test::CommandTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
};

using test::read_text;

TEST_F(RecipeCommands, EvalWritesEveryFormat) {
  for (const char* ext : {".obj", ".ply", ".glb"}) {
    const fs::path out = dir_ / (std::string("house") + ext);
    EXPECT_EQ(run_eval({kSamples / "house.pxg", out, {}, {}, {}, {}, {}, {}}, out_, err_), 0) << err_.str();
    EXPECT_GT(fs::file_size(out), 100u) << ext;
  }
  const std::string obj = read_text(dir_ / "house.obj");
  EXPECT_NE(obj.find("mtllib house.mtl"), std::string::npos);
  EXPECT_NE(obj.find("usemtl roof"), std::string::npos);
  EXPECT_NE(obj.find("usemtl gable"), std::string::npos);
  EXPECT_NE(read_text(dir_ / "house.mtl").find("newmtl wall"), std::string::npos);
}

TEST_F(RecipeCommands, SetChangesExposedParameters) {
  const fs::path a = dir_ / "a.obj", b = dir_ / "b.obj";
  ASSERT_EQ(run_eval({kSamples / "house.pxg", a, {}, {}, {}, {}, {}, {}}, out_, err_), 0) << err_.str();
  ASSERT_EQ(run_eval({kSamples / "house.pxg", b, {"shape=rectangle", "pitch=30"}, {}, {}, {}, {}, {}}, out_, err_), 0) << err_.str();
  EXPECT_NE(read_text(a), read_text(b));
}

// A preset is a named set of exposed values: the same mesh as setting them one by one; --set still wins.
TEST_F(RecipeCommands, PresetSetsItsExposedValues) {
  const fs::path by_hand = dir_ / "a.ply", preset = dir_ / "b.ply", both = dir_ / "c.ply", plain = dir_ / "d.ply";
  ASSERT_EQ(run_eval({kSamples / "house.pxg", by_hand, {"pitch=35", "shape=rectangle"}, {}, {}, {}, {}, {}}, out_, err_), 0) << err_.str();
  ASSERT_EQ(run_eval({kSamples / "house.pxg", preset, {}, {}, {}, {}, "cottage", {}}, out_, err_), 0) << err_.str();
  EXPECT_EQ(read_text(by_hand), read_text(preset));
  ASSERT_EQ(run_eval({kSamples / "house.pxg", both, {"pitch=50", "shape=l"}, {}, {}, {}, "cottage", {}}, out_, err_), 0) << err_.str();
  ASSERT_EQ(run_eval({kSamples / "house.pxg", plain, {}, {}, {}, {}, {}, {}}, out_, err_), 0) << err_.str();
  EXPECT_EQ(read_text(both), read_text(plain));
  EXPECT_EQ(run_eval({kSamples / "house.pxg", dir_ / "x.obj", {}, {}, {}, {}, "tall", {}}, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("--preset tall: no preset 'tall' (it has: cottage, steep)"), std::string::npos) << err_.str();
}

TEST_F(RecipeCommands, BadSettingsNameTheProblem) {
  EXPECT_EQ(run_eval({kSamples / "house.pxg", dir_ / "x.obj", {"colour=red"}, {}, {}, {}, {}, {}}, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("--set colour=red: the recipe has no exposed parameter or input named 'colour'"),
            std::string::npos) << err_.str();
  err_.str("");
  EXPECT_EQ(run_eval({kSamples / "house.pxg", dir_ / "x.obj", {"shape=star"}, {}, {}, {}, {}, {}}, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("--set shape=star: "), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "x.obj"));
}

TEST_F(RecipeCommands, FailingNodeIsNamedAndNothingIsWritten) {
  std::string text = read_text(kSamples / "gallery_hipped.pxg");
  text.replace(text.find("\"* = hip\""), 9, "\"* = pagoda\"");
  const fs::path recipe = write("broken.pxg", text);
  EXPECT_EQ(run_eval({recipe, dir_ / "broken.obj", {}, {}, {}, {}, {}, {}}, out_, err_), kExitEvaluationFailed);
  EXPECT_NE(err_.str().find("broken.pxg: error: node 11 (Assign Profiles): rules: rule 1 ('* = pagoda')"),
            std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "broken.obj"));
}

TEST_F(RecipeCommands, UnreadableRecipeNamesFileAndPlace) {
  const fs::path recipe = write("bad.pxg", "{\"format\": \"procex-graph\",\n \"version\": 2,\n \"nodes\": [}");
  EXPECT_EQ(run_eval({recipe, dir_ / "x.glb", {}, {}, {}, {}, {}, {}}, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("bad.pxg: line 3"), std::string::npos) << err_.str();
  err_.str("");
  EXPECT_EQ(run_validate({dir_ / "missing.pxg", {}}, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("missing.pxg"), std::string::npos) << err_.str();
}

TEST_F(RecipeCommands, ValidateReportsUnboundInputsWithoutEvaluating) {
  EXPECT_EQ(run_validate({kSamples / "house.pxg", {}}, out_, err_), 0) << err_.str();
  EXPECT_NE(out_.str().find("6 nodes, 6 links, 0 inputs, 1 outputs, 2 exposed parameters"), std::string::npos) << out_.str();
  // city.pxg's footprint is bound per feature by batch: noted, not a problem.
  EXPECT_EQ(run_validate({kSamples / "city.pxg", {}}, out_, err_), 0) << err_.str();
  EXPECT_NE(out_.str().find("note: input 'footprint' (footprint) has no default"), std::string::npos) << out_.str();
  // A link to a missing node is.
  std::string text;
  {
    std::ifstream in(kSamples / "gallery_hipped.pxg");
    std::stringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  text.replace(text.find("\"12.mesh\""), 9, "\"13.mesh\"");
  EXPECT_EQ(run_validate({write("dangling.pxg", text), {}}, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("dangling.pxg"), std::string::npos) << err_.str();
}

TEST_F(RecipeCommands, StatsShowsNodesAndCacheHits) {
  EXPECT_EQ(run_stats({kSamples / "house.pxg", {}, {}}, out_, err_), 0) << err_.str();
  EXPECT_NE(out_.str().find("Extrude"), std::string::npos);
  EXPECT_NE(out_.str().find("second evaluation: 1 cache hits, 0 computed"), std::string::npos) << out_.str();
}

TEST_F(RecipeCommands, NodesListsEveryTypeAndDocuments) {
  EXPECT_EQ(run_nodes({false}, out_), 0);
  for (const char* type : {"Footprint Shape", "Assign Profiles", "Extrude", "Anchor", "Mesh Placement", "Switch", "Export"})
    EXPECT_NE(out_.str().find(type), std::string::npos) << type;
  std::ostringstream md;
  EXPECT_EQ(run_nodes({true}, md), 0);
  EXPECT_NE(md.str().find("#"), std::string::npos);
  EXPECT_NE(md.str().find("street_direction"), std::string::npos);
  EXPECT_NE(md.str().find("from_start"), std::string::npos);  // Anchor's modes, from its declaration
}

TEST_F(RecipeCommands, ExecutableExitCodes) {
  const std::string exe = PROCEX_CLI_EXE;
  auto run = [](const std::string& cmd) { return WEXITSTATUS(std::system((cmd + " >/dev/null 2>&1").c_str())); };
  EXPECT_EQ(run(exe + " eval " + (kSamples / "house.pxg").string() + " -o " + (dir_ / "h.glb").string()), 0);
  EXPECT_EQ(run(exe + " eval " + (kSamples / "house.pxg").string() + " -o " + (dir_ / "h.stl").string()), 2);
  EXPECT_EQ(run(exe + " validate " + (kSamples / "city.pxg").string()), 0);
  EXPECT_EQ(run(exe + " nodes --markdown"), 0);
  EXPECT_NE(run(exe + " eval"), 0);  // missing arguments
  for (const char* cmd : {"eval", "batch", "merge", "validate", "stats", "nodes"})
    EXPECT_EQ(run(exe + " " + cmd + " --help"), 0) << cmd;
}

}  // namespace
}  // namespace procex

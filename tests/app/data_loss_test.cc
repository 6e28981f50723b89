// Runs that used to lose data silently: per-building files whose names
// collide or are too long, a report given the path of an input or of the
// mesh, and a run where nothing was produced ending with exit 0.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/merge_command.h"
#include "app/cli/recipe_session.h"
#include "app/cli/roof_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const fs::path kSamples = PROCEX_SAMPLES;
const fs::path& kBlock = test::kSampleBlock;

std::string square_feature(const std::string& id_json) {
  return R"({"type": "Feature", "id": )" + id_json +
         R"(, "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[8,0],[8,6],[0,6],[0,0]]]}})";
}

class DataLoss : public test::CommandTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  BatchCommandOptions batch(const fs::path& footprints, const std::string& output) {
    BatchCommandOptions o;
    o.recipe = kSamples / "city.pxg";
    o.footprints = footprints;
    o.output = dir_ / output;
    o.progress = false;
    return o;
  }
};

TEST_F(DataLoss, PerBuildingNamesAreUniqueAndBounded) {
  const std::string long_id(300, 'x');
  const fs::path in = write("ids.geojson", R"({"type": "FeatureCollection", "features": [)" + square_feature(R"("a/b")") + "," +
                                               square_feature(R"("a_b")") + "," + square_feature(R"("日本")") + "," +
                                               square_feature(R"("中国")") + "," + square_feature(R"("a_b")") + "," +
                                               square_feature(R"("A_B")") + "," + square_feature("\"" + long_id + "\"") + "]}");
  BatchCommandOptions o = batch(in, "out/");
  o.report = dir_ / "report.json";
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  std::set<std::string> on_disk;
  for (const auto& entry : fs::directory_iterator(dir_ / "out")) on_disk.insert(entry.path().filename().string());
  EXPECT_EQ(on_disk.size(), 7u);  // one file per building, none overwritten
  const nlohmann::json report = nlohmann::json::parse(read_text(o.report));
  std::set<std::string> named;
  for (const auto& b : report["buildings"]) {
    const std::string file = b["file"].get<std::string>();
    EXPECT_LE(file.size(), 120u) << file;
    EXPECT_TRUE(on_disk.count(file)) << file;
    named.insert(file);
  }
  EXPECT_EQ(named.size(), 7u);
}

TEST_F(DataLoss, OutputsNeverOverwriteInputsOrEachOther) {
  const fs::path footprints = dir_ / "block.geojson";
  fs::copy_file(kBlock, footprints);
  const std::string before = read_text(footprints);
  BatchCommandOptions same_as_input = batch(footprints, "city.glb");
  same_as_input.report = footprints;
  EXPECT_EQ(run_batch(same_as_input, out_, err_), kExitUnusableInput);
  BatchCommandOptions same_as_mesh = batch(footprints, "city.glb");
  same_as_mesh.report = same_as_mesh.output;
  EXPECT_EQ(run_batch(same_as_mesh, out_, err_), kExitUnusableInput);
  RoofOptions roof;
  roof.input = footprints;
  roof.output = dir_ / "roofs.obj";
  roof.report = dir_ / "." / "block.geojson";  // the same file, spelled differently
  EXPECT_EQ(run_roof(roof, out_, err_), kExitUnusableFile);
  roof.report = dir_ / "roofs.mtl";  // the .obj's material file
  EXPECT_EQ(run_roof(roof, out_, err_), kExitUnusableFile);
  MergeCommandOptions merge{{dir_ / "part.glb"}, dir_ / "part.glb", {}};
  EXPECT_EQ(run_merge(merge, out_, err_), kExitUnusableInput);
  EXPECT_EQ(read_text(footprints), before);
  EXPECT_FALSE(fs::exists(dir_ / "city.glb"));
  EXPECT_NE(err_.str().find("would overwrite"), std::string::npos) << err_.str();
}

TEST_F(DataLoss, AReportThatCannotBeWrittenLeavesTheMeshAlone) {
  BatchCommandOptions o = batch(kBlock, "city.glb");
  o.report = dir_ / "no_such_folder" / "report.json";
  EXPECT_EQ(run_batch(o, out_, err_), kExitUnusableInput);
  EXPECT_FALSE(fs::exists(o.output));
}

// A plan no recipe can use is "refused", with the same reason, by roof and by
// batch; a run that produced nothing exits non-zero.
TEST_F(DataLoss, NothingProducedIsNoSuccess) {
  struct Case {
    std::string name, ring, reason;
  };
  const std::vector<Case> cases = {
      {"bowtie", "[0,0],[10,10],[10,0],[0,10],[0,0]", "loop 0 intersects itself"},
      {"needle", "[0,0],[1000,0],[1000,1e-9],[0,0]", "loop 0 has 2 distinct vertices (points closer than"},
      {"far", "[-1e308,-1e308],[1e308,-1e308],[1e308,1e308],[-1e308,1e308],[-1e308,-1e308]", "m from the origin"},
  };
  for (const Case& c : cases) {
    const fs::path in = write(c.name + ".geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature",
        "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[)" + c.ring + "]]}}]}");
    RoofOptions roof;
    roof.input = in;
    roof.output = dir_ / (c.name + ".obj");
    roof.report = dir_ / (c.name + "_roof.json");
    EXPECT_EQ(run_roof(roof, out_, err_), kExitFeatureFailed) << c.name;
    BatchCommandOptions b = batch(in, c.name + ".glb");
    b.report = dir_ / (c.name + "_batch.json");
    EXPECT_EQ(run_batch(b, out_, err_), kExitEvaluationFailed) << c.name;
    const nlohmann::json by_roof = nlohmann::json::parse(read_text(roof.report))["features"][0];
    const nlohmann::json by_batch = nlohmann::json::parse(read_text(b.report))["buildings"][0];
    EXPECT_EQ(by_roof["status"], "refused") << c.name;
    EXPECT_EQ(by_batch["status"], "refused") << c.name;
    EXPECT_EQ(by_roof["reason"], by_batch["reason"]) << c.name;
    EXPECT_NE(by_batch["reason"].get<std::string>().find(c.reason), std::string::npos) << by_batch;
  }
}

// merge gets the shards of one run, each once, or refuses: the same shard
// twice, one missing, shards of N=2 with N=3, or another run's shard.
TEST_F(DataLoss, MergeRefusesASetThatIsNotOneWhole) {
  auto shard = [&](std::size_t i, std::size_t n, const fs::path& footprints) {
    // (Built with append: g++ 12 warns falsely on "s" + std::to_string.)
    BatchCommandOptions o =
        batch(footprints, std::string("s").append(std::to_string(i)).append("of").append(std::to_string(n)).append(footprints.stem().string()).append(".glb"));
    o.shard = i, o.shards = n;
    o.report = fs::path(o.output).replace_extension(".json");
    EXPECT_EQ(run_batch(o, out_, err_), 0) << err_.str();
    return std::vector<fs::path>{o.output, o.report};
  };
  const fs::path other = dir_ / "other.geojson";
  std::ofstream(other) << read_text(kBlock) << "\n";  // the same buildings, another file
  const auto a = shard(0, 2, kBlock), b = shard(1, 2, kBlock), c = shard(1, 3, kBlock), d = shard(1, 2, other);
  auto merge = [&](std::vector<std::vector<fs::path>> parts) {
    MergeCommandOptions m;
    for (const auto& p : parts) m.parts.insert(m.parts.end(), p.begin(), p.end());
    m.output = dir_ / "merged.glb";
    m.report = dir_ / "merged.json";
    err_.str("");
    return run_merge(m, out_, err_);
  };
  EXPECT_EQ(merge({a, b}), 0) << err_.str();
  fs::remove(dir_ / "merged.glb"), fs::remove(dir_ / "merged.json");
  EXPECT_EQ(merge({a, a, b}), kExitUnusableInput);
  EXPECT_EQ(merge({a}), kExitUnusableInput);
  EXPECT_NE(err_.str().find("shard 1 of 2 is missing"), std::string::npos) << err_.str();
  EXPECT_EQ(merge({a, c}), kExitUnusableInput);
  EXPECT_EQ(merge({a, d}), kExitUnusableInput);
  EXPECT_NE(err_.str().find("another recipe, footprint file or streets file"), std::string::npos) << err_.str();
  // The .glb parts carry the same stamp in their scene's extras: without
  // reports the set is checked as strictly.
  auto meshes_only = [&](std::vector<std::vector<fs::path>> parts) {
    MergeCommandOptions m;
    for (const auto& p : parts) m.parts.push_back(p[0]);
    m.output = dir_ / "merged.glb";
    err_.str("");
    return run_merge(m, out_, err_);
  };
  for (const auto& [parts, said] : std::vector<std::pair<std::vector<std::vector<fs::path>>, std::string>>{
           {{a, a}, "shard 0 again"},
           {{a}, "shard 1 of 2 is missing"},
           {{a, c}, "but " + a[0].string() + " is one of 2"},
           {{a, d}, "another recipe, footprint file or streets file"}}) {
    EXPECT_EQ(meshes_only(parts), kExitUnusableInput) << said;
    EXPECT_NE(err_.str().find(said), std::string::npos) << err_.str();
  }
  const auto e = shard(0, 2, other);
  EXPECT_EQ(merge({{a[0], b[0], e[1], d[1]}}), kExitUnusableInput);  // the meshes of one run, the reports of another
  EXPECT_NE(err_.str().find("come from different runs"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "merged.glb"));
  EXPECT_EQ(meshes_only({a, b}), 0) << err_.str();
}

}  // namespace
}  // namespace procex

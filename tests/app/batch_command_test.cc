// procex batch and procex merge: the city sample against its stored summary,
// byte-identical output whatever --jobs, shards merged into the unsharded
// bytes, failures reported while the batch goes on.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/feature_binding.h"
#include "app/cli/merge_command.h"
#include "app/cli/recipe_session.h"
#include "app/cli/shard_stamp.h"
#include "core/geom/party_walls.h"
#include "core/io/footprint_read.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"
#include "tests/support/gltf_scripts.h"
#include "tests/expected/sample_summaries.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

const fs::path kSamples = PROCEX_SAMPLES;
const fs::path& kBlock = test::kSampleBlock;

using test::read_text;

class Batch : public test::CommandTest {
 protected:
  BatchCommandOptions options(const std::string& output) {
    BatchCommandOptions o;
    o.recipe = kSamples / "city.pxg";
    o.footprints = kBlock;
    o.output = dir_ / output;
    o.progress = false;
    return o;
  }
};

// Per building: its summary, compared with samples/expected/city.json.
TEST_F(Batch, CitySampleMatchesStoredSummary) {
  BatchCommandOptions o = options("city.glb");
  o.report = dir_ / "city.json";
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  const json report = json::parse(read_text(o.report));
  EXPECT_EQ(report["summary"]["ok"], 18);
  json got = test::city_buildings(report);
  const fs::path expected = kSamples / "expected" / "city.json";
  const json want = json::parse(read_text(expected));
  const double length = want["tolerance"]["length"], rel = want["tolerance"]["volume_relative"];
  ASSERT_EQ(want["buildings"].size(), got.size());
  for (const auto& [id, w] : want["buildings"].items()) {
    SCOPED_TRACE(id);
    ASSERT_TRUE(got.contains(id));
    const json& g = got[id];
    EXPECT_EQ(w["faces_per_tag"], g["faces_per_tag"]);
    EXPECT_EQ(w.value("placed", json::object()), g.value("placed", json::object()));  // windows and doors
    for (const char* end : {"min", "max"})
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(w["bounds"][end][k].get<double>(), g["bounds"][end][k].get<double>(), length);
    EXPECT_NEAR(w["volume"].get<double>(), g["volume"].get<double>(), rel * std::abs(w["volume"].get<double>()));
  }
  // Five building types: at least the house, apartment and church branches appear in this block.
  std::set<double> heights;
  for (const json& b : report["buildings"]) heights.insert(b["bounds"]["max"][2].get<double>() > 20 ? 2 : 1);
  EXPECT_EQ(heights.size(), 2u);
}

TEST_F(Batch, SameBytesWhateverJobs) {
  for (const char* ext : {".glb", ".obj"}) {
    BatchCommandOptions one = options(std::string("city") + ext), two = options(std::string("city") + ext);
    fs::create_directories(dir_ / "one");
    fs::create_directories(dir_ / "two");
    one.output = dir_ / "one" / one.output.filename(), two.output = dir_ / "two" / two.output.filename();
    one.jobs = 1, two.jobs = 2;
    ASSERT_EQ(run_batch(one, out_, err_), 0) << err_.str();
    ASSERT_EQ(run_batch(two, out_, err_), 0) << err_.str();
    EXPECT_TRUE(read_text(one.output) == read_text(two.output)) << ext;
  }
  // Per-building files, written by the workers as their buildings are made.
  for (const char* format : {"glb", "obj", "ply"}) {
    BatchCommandOptions one = options(std::string("one_") + format + "/"), two = options(std::string("two_") + format + "/");
    one.format = two.format = format;
    one.jobs = 1, two.jobs = 2;
    ASSERT_EQ(run_batch(one, out_, err_), 0) << err_.str();
    ASSERT_EQ(run_batch(two, out_, err_), 0) << err_.str();
    std::size_t files = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(one.output)) {
      ++files;
      EXPECT_TRUE(read_text(e.path()) == read_text(two.output / e.path().filename())) << e.path();
    }
    EXPECT_EQ(files, static_cast<std::size_t>(std::distance(fs::directory_iterator(two.output), fs::directory_iterator())));
    EXPECT_GE(files, 18u) << format;
  }
}

TEST_F(Batch, ShardsMergeIntoTheUnshardedBytes) {
  BatchCommandOptions all = options("all.glb");
  all.report = dir_ / "all.json";
  ASSERT_EQ(run_batch(all, out_, err_), 0) << err_.str();
  MergeCommandOptions merge;
  for (std::size_t i = 0; i < 3; ++i) {
    BatchCommandOptions shard = options("shard" + std::to_string(i) + ".glb");
    shard.shard = i, shard.shards = 3, shard.jobs = static_cast<int>(i % 2 + 1);
    shard.report = dir_ / ("shard" + std::to_string(i) + ".json");
    ASSERT_EQ(run_batch(shard, out_, err_), 0) << err_.str();
    merge.parts.push_back(shard.report);
    merge.parts.push_back(shard.output);
  }
  merge.output = dir_ / "merged.glb";
  merge.report = dir_ / "merged.json";
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  EXPECT_EQ(read_text(all.output), read_text(merge.output));
  const json a = json::parse(read_text(all.report)), m = json::parse(read_text(merge.report));
  ASSERT_EQ(a["buildings"].size(), m["buildings"].size());
  for (std::size_t i = 0; i < a["buildings"].size(); ++i) {
    EXPECT_EQ(a["buildings"][i]["id"], m["buildings"][i]["id"]);
    EXPECT_EQ(a["buildings"][i]["faces_per_tag"], m["buildings"][i]["faces_per_tag"]);
  }
  EXPECT_EQ(m["summary"]["ok"], 18);
}

TEST_F(Batch, GlbCarriesBuildingIdsAndTags) {
  BatchCommandOptions o = options("city.glb");
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  const std::vector<GltfMeshData> meshes = read_glb_scene(o.output).meshes;
  ASSERT_EQ(meshes.size(), 18u);  // walls and roof of a building in one mesh
  EXPECT_EQ(meshes[0].building, "w49209546");
  EXPECT_EQ(meshes[0].feature, 0);
  std::set<std::string> tags;
  for (const auto& m : meshes)
    for (const auto& p : m.primitives) tags.insert(p.tag);
  EXPECT_TRUE(tags.count("roof") && tags.count("wall") && tags.count("base"));
}

TEST_F(Batch, OneFilePerBuilding) {
  BatchCommandOptions o = options("per_building/");
  o.format = "obj";
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "per_building" / "w362871296.obj"));
  EXPECT_TRUE(fs::exists(dir_ / "per_building" / "r1484217.mtl"));
}

// Per-building files and a single .glb stream out as buildings finish in
// order, so the batch holds no building's faces once written: the in-memory
// budget that refuses another single output does not apply to them.
TEST_F(Batch, StreamedOutputsAreNotHeldForTheBudget) {
  BatchCommandOptions one = options("city.obj");
  one.max_faces = 10;
  EXPECT_EQ(run_batch(one, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("nothing written"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(one.output));
  BatchCommandOptions glb = options("city.glb");
  glb.max_faces = 10;
  ASSERT_EQ(run_batch(glb, out_, err_), 0) << err_.str();
  EXPECT_EQ(read_glb_scene(glb.output).meshes.size(), 18u);
  BatchCommandOptions folder = options("per_building/");
  folder.max_faces = 10;
  folder.report = dir_ / "report.json";
  ASSERT_EQ(run_batch(folder, out_, err_), 0) << err_.str();
  const nlohmann::json report = nlohmann::json::parse(read_text(folder.report));
  ASSERT_GT(report["buildings"].size(), 1u);
  for (const auto& b : report["buildings"]) {
    ASSERT_EQ(b["status"], "ok") << b;
    EXPECT_TRUE(fs::exists(folder.output / b["file"].get<std::string>())) << b;
  }
}

// The .glb a batch streams building by building has the bytes write_glb
// writes for the scene it holds (read back and written whole), and so has
// procex merge of the one part (streamed too), for the sample block and for
// 150 generated footprints rendered in groups of 16, one of them unreadable; the Khronos
// validator passes it.
TEST_F(Batch, StreamedGlbHasTheBytesOfTheSceneInMemory) {
  std::string features;
  for (int i = 0; i < 150; ++i) {
    const double x = 40.0 * (i % 12), y = 40.0 * (i / 12), w = 8 + i % 7, d = 9 + i % 5;
    const std::string ring = i == 77 ? "[[0,0],[1,1],[1,0],[0,1],[0,0]]"  // a bow-tie: refused, reported
                                     : "[[" + std::to_string(x) + "," + std::to_string(y) + "],[" +
                                           std::to_string(x + w) + "," + std::to_string(y) + "],[" +
                                           std::to_string(x + w) + "," + std::to_string(y + d) + "],[" +
                                           std::to_string(x) + "," + std::to_string(y + d) + "],[" +
                                           std::to_string(x) + "," + std::to_string(y) + "]]";
    features += std::string(i ? "," : "") + R"({"type":"Feature","id":"g)" + std::to_string(i) +
                R"(","properties":{"building:levels":)" + std::to_string(1 + i % 4) +
                R"(},"geometry":{"type":"Polygon","coordinates":[)" + ring + "]}}";
  }
  std::ofstream(dir_ / "generated.geojson") << R"({"type":"FeatureCollection","features":[)" << features << "]}";
  for (const fs::path& footprints : {kBlock, dir_ / "generated.geojson"}) {
    SCOPED_TRACE(footprints);
    BatchCommandOptions o = options("streamed.glb");
    o.footprints = footprints, o.jobs = 1;  // groups of 16
    o.report = dir_ / "streamed.json";
    ASSERT_LE(run_batch(o, out_, err_), 1) << err_.str();
    ASSERT_EQ(read_glb_scene(o.output).meshes.size(), footprints == kBlock ? 18u : 149u);
    GltfScene scene = read_glb_scene(o.output);  // its stamp read back with its members in key order: as written
    scene.extras["shard"] = to_json(read_shard_stamp(json::parse(scene.extras["shard"]), o.output, "")).dump();
    write_glb(dir_ / "memory.glb", scene);
    EXPECT_TRUE(read_text(o.output) == read_text(dir_ / "memory.glb"));
    MergeCommandOptions merge;
    merge.parts = {o.output};
    merge.output = dir_ / "merged.glb";
    ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
    EXPECT_TRUE(read_text(o.output) == read_text(merge.output));
    const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", o.output);
    ASSERT_TRUE(v.problem.empty()) << v.problem;
    EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
    EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
  }
}

// A batch resolves the files its recipe names once for all its buildings
// (EvalOptions::resolved_paths), never a symlink out of the recipe's folder:
// a texture linked from outside fails every building, naming the file, and
// linked from inside the folder it is every building's.
TEST_F(Batch, ATextureLinkedFromOutsideTheFolderFailsEveryBuilding) {
  const fs::path folder = dir_ / "recipe";
  fs::create_directories(folder / "textures");
  fs::copy(kSamples / "meshes", folder / "meshes", fs::copy_options::recursive);
  fs::copy_file(kSamples / "textures" / "brick.png", dir_ / "secret.png");
  fs::copy_file(kSamples / "textures" / "brick.png", folder / "textures" / "brick.png");
  json recipe = json::parse(read_text(kSamples / "city.pxg"));
  int last = 0;
  for (const json& n : recipe["nodes"]) last = std::max(last, n["id"].get<int>());
  recipe["nodes"].push_back({{"id", last + 1}, {"type", "Material"}, {"version", 1},
                             {"params", {{"tag", "wall"}, {"texture", "textures/link.png"}}}});
  for (json& l : recipe["links"])
    if (l["to"] == "@mesh") l["to"] = std::to_string(last + 1) + ".mesh";
  recipe["links"].push_back({{"from", std::to_string(last + 1) + ".mesh"}, {"to", "@mesh"}});
  std::ofstream(folder / "city.pxg") << recipe.dump();
  BatchCommandOptions o = options("linked.glb");
  o.recipe = folder / "city.pxg";
  o.report = dir_ / "linked.json";

  fs::create_symlink(dir_ / "secret.png", folder / "textures" / "link.png");
  EXPECT_EQ(run_batch(o, out_, err_), kExitEvaluationFailed);
  json report = json::parse(read_text(o.report));
  EXPECT_EQ(report["summary"]["ok"], 0);
  EXPECT_EQ(report["summary"]["failed"], 18);
  for (const json& b : report["buildings"])
    EXPECT_NE(b["reason"].get<std::string>().find("texture: 'textures/link.png' lies outside the recipe's folder"),
              std::string::npos)
        << b;

  fs::remove(folder / "textures" / "link.png");
  fs::create_symlink(folder / "textures" / "brick.png", folder / "textures" / "link.png");
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  report = json::parse(read_text(o.report));
  EXPECT_EQ(report["summary"]["ok"], 18);
  EXPECT_NE(read_text(o.output).find(read_text(folder / "textures" / "brick.png")), std::string::npos)
      << "the texture is embedded";
}

TEST_F(Batch, FailuresAreReportedAndTheBatchGoesOn) {
  BatchCommandOptions o = options("bad.glb");
  o.footprints = fs::path(PROCEX_TEST_DATA) / "geojson_bad_features.geojson";
  o.report = dir_ / "bad.json";
  const int code = run_batch(o, out_, err_);
  const json report = json::parse(read_text(o.report));
  EXPECT_GT(report["summary"]["refused"].get<int>() + report["summary"]["failed"].get<int>(), 0);
  EXPECT_GT(report["summary"]["ok"].get<int>(), 0);
  EXPECT_EQ(code, report["summary"]["failed"].get<int>() > 0 ? kExitEvaluationFailed : 0);
  EXPECT_NE(err_.str().find("procex batch: feature "), std::string::npos) << err_.str();
  EXPECT_TRUE(fs::exists(o.output));
}

// A plan no recipe can use is refused before the recipe runs, in procex
// roof's words; with nothing produced the run exits 1.
TEST_F(Batch, SelfIntersectingFootprintIsRefused) {
  BatchCommandOptions o = options("osm.glb");
  o.footprints = fs::path(PROCEX_TEST_DATA) / "geojson_osm_self_intersecting_baltimore.geojson";
  o.report = dir_ / "osm.json";
  EXPECT_EQ(run_batch(o, out_, err_), kExitEvaluationFailed);
  const json report = json::parse(read_text(o.report));
  EXPECT_EQ(report["summary"]["refused"].get<int>(), 2);
  for (const json& b : report["buildings"])
    EXPECT_EQ(b["reason"].get<std::string>().rfind("loop 0 intersects itself: its edge 1", 0), 0u) << b;
}

// Properties set exposed parameters of the same name, numbers with units included ("12 m").
TEST_F(Batch, PropertiesSetExposedParameters) {
  std::string text = read_text(kSamples / "gallery_hipped.pxg");
  // A batch recipe: the footprint from the graph input, the roof pitch exposed as "height" (so
  // good_square's property "height": "12 m" sets a 12 degree pitch).
  auto replace = [&text](const std::string& from, const std::string& to) { text.replace(text.find(from), from.size(), to); };
  replace("\"from\": \"1.footprint\"", "\"from\": \"@footprint\"");
  replace("\"inputs\": []", "\"inputs\": [{\"doc\": \"\", \"name\": \"footprint\", \"type\": \"footprint\"}]");
  replace("\"name\": \"pitch\"", "\"name\": \"height\"");
  std::ofstream(dir_ / "by_height.pxg") << text;
  BatchCommandOptions o = options("by_height.glb");
  o.recipe = dir_ / "by_height.pxg";
  o.footprints = fs::path(PROCEX_TEST_DATA) / "geojson_bad_features.geojson";
  o.report = dir_ / "by_height.json";
  run_batch(o, out_, err_);
  ASSERT_TRUE(fs::exists(o.report)) << err_.str();
  const json report = json::parse(read_text(o.report));
  ASSERT_EQ(report["buildings"][0]["id"], "good_square");
  ASSERT_EQ(report["buildings"][0]["status"], "ok") << report["buildings"][0];
  // A 10 x 10 square peaks at 5 / tan(pitch): 5 m at the recipe's 45 degrees, 23.5 m at 12.
  EXPECT_NEAR(report["buildings"][0]["bounds"]["max"][2].get<double>(), 5.0 / std::tan(12 * M_PI / 180), 1e-9);
}

// The city recipe's graph input party_edges gets each building's edges shared
// with a neighbour in the file: one blank vertical face tagged party per such
// edge, as many as party_edges finds on the block read on its own.
TEST_F(Batch, PartyWallsOfTheSampleBlock) {
  BatchCommandOptions o = options("city.glb");
  o.report = dir_ / "city.json";
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  const json report = json::parse(read_text(o.report));
  const GeoJsonCollection block = read_footprints(kBlock);
  std::vector<PlanLoops> plans;
  for (const GeoJsonFeature& f : block.features) plans.push_back(f.loops);
  const auto party = party_edges(plans, kPartyWallDistance);
  std::size_t shared = 0, with_party = 0;
  for (std::size_t i = 0; i < block.features.size(); ++i) {
    shared += party[i].size();
    with_party += !party[i].empty();
    for (const auto& b : report["buildings"]) {
      if (b["id"] != block.features[i].id) continue;
      SCOPED_TRACE(block.features[i].id);
      const std::size_t faces = b["faces_per_tag"].contains("party") ? b["faces_per_tag"]["party"].get<std::size_t>() : 0;
      EXPECT_EQ(faces, party[i].size());
    }
  }
  EXPECT_GE(with_party, 4u);  // the block has terraced neighbours
  EXPECT_GE(shared, with_party);
}

TEST_F(Batch, RecipeWithoutFootprintInputIsRefused) {
  BatchCommandOptions o = options("x.glb");
  o.recipe = kSamples / "house.pxg";
  EXPECT_EQ(run_batch(o, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("house.pxg: the recipe needs a graph input named 'footprint'"), std::string::npos) << err_.str();
}

TEST(BatchShard, Parses) {
  std::size_t i = 9, n = 9;
  EXPECT_TRUE(parse_shard("2/5", i, n));
  EXPECT_EQ(i, 2u);
  EXPECT_EQ(n, 5u);
  EXPECT_FALSE(parse_shard("5/5", i, n));
  EXPECT_FALSE(parse_shard("1/0", i, n));
  // Negative and huge numbers used to wrap through sscanf's %zu.
  for (const char* bad : {"0/-2", "-1/3", "0/99999999999999999999999", "1/3x", "1 /3", "+1/3", "/3", "1/"})
    EXPECT_FALSE(parse_shard(bad, i, n)) << bad;
  EXPECT_FALSE(parse_shard("1/2x", i, n));
  EXPECT_FALSE(parse_shard("a/2", i, n));
}

}  // namespace
}  // namespace procex

// The .glb files procex writes pass the Khronos glTF validator with no errors
// and load in three.js's GLTFLoader, with tags and building ids where they
// belong. Both run under Node.js from tools/node_modules (scripts/install-deps.sh
// installs them); a missing node or module fails the tests.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <filesystem>
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path& kRoot = test::kRepository;
const fs::path kTools = kRoot / "tools";

struct ProcessRun {
  int code = -1;
  std::string out;
};

ProcessRun run(const std::string& command) {
  ProcessRun r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.out.append(buf, n);
  const int status = ::pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class GltfExport : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    ASSERT_EQ(run("node --version").code, 0) << "node (Node.js) is not installed: the glTF validator and three.js "
                                                    "tests need it (scripts/install-deps.sh)";
    ASSERT_TRUE(fs::exists(kTools / "node_modules" / "gltf-validator") && fs::exists(kTools / "node_modules" / "three"))
        << "run scripts/install-deps.sh (or: cd tools && npm ci) to install the glTF validator and three.js";
  }
  // lod 2: the buildings without their placed windows and doors (each placed mesh is a mesh of its own).
  fs::path city(std::optional<int> lod = std::nullopt) {
    BatchCommandOptions o;
    o.recipe = kRoot / "samples" / "city.pxg";
    o.footprints = test::kSampleBlock;
    o.output = dir_ / "city.glb";
    o.progress = false;
    o.lod = lod;
    std::ostringstream out, err;
    EXPECT_EQ(run_batch(o, out, err), 0) << err.str();
    return o.output;
  }
  // samples/windows_grid.pxg with the sample's textured door placed in its
  // grid instead of the window (in dir_, with the meshes beside it), written
  // to dir_/out/house<extension>.
  fs::path textured_house(const std::string& extension) {
    fs::copy(kRoot / "samples" / "meshes", dir_ / "meshes", fs::copy_options::recursive | fs::copy_options::skip_existing);
    std::ifstream in(kRoot / "samples" / "windows_grid.pxg");
    std::string recipe((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string window = "\"file\": \"meshes/window_frame.obj\"";
    const std::size_t at = recipe.find(window);
    EXPECT_NE(at, std::string::npos);
    recipe.replace(at, window.size(), "\"file\": \"meshes/door_textured.obj\"");
    std::ofstream(dir_ / "textured.pxg") << recipe;
    fs::create_directories(dir_ / "out");
    const fs::path output = dir_ / "out" / ("house" + extension);
    std::ostringstream o, e;
    EXPECT_EQ(run_eval(test::eval_options(dir_ / "textured.pxg", output), o, e), 0) << e.str();
    return output;
  }
  json node_json(const char* script, const fs::path& glb, int want_code) {
    const ProcessRun r = run("node " + (kTools / script).string() + " " + glb.string());
    EXPECT_EQ(r.code, want_code) << r.out;
    try {
      return json::parse(r.out);
    } catch (const json::exception&) {
      ADD_FAILURE() << script << " printed no JSON: " << r.out;
      return {};
    }
  }
};

// Every recipe in samples/ (city.pxg, whose footprint is a graph input, as
// procex batch writes it for the sample block), as procex eval writes it.
TEST_F(GltfExport, EverySampleValidatesWithoutErrors) {
  std::vector<fs::path> files = {city()};
  std::vector<fs::path> recipes;
  for (const auto& entry : fs::directory_iterator(kRoot / "samples"))
    if (entry.path().extension() == ".pxg" && entry.path().stem() != "city") recipes.push_back(entry.path());
  std::sort(recipes.begin(), recipes.end());
  ASSERT_GE(recipes.size(), 20u) << "samples/ lost its recipes";
  for (const fs::path& recipe : recipes) {
    const fs::path out = dir_ / (recipe.stem().string() + ".glb");
    std::ostringstream o, e;
    ASSERT_EQ(run_eval(test::eval_options(recipe, out), o, e), 0) << recipe << ": " << e.str();
    files.push_back(out);
  }
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.filename().string());
    const json report = node_json("validate_gltf.mjs", f, 0);
    EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
    EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
    EXPECT_GT(report["info"]["totalTriangleCount"].get<int>(), 0);
  }
}

TEST_F(GltfExport, ValidatorCatchesABrokenFile) {
  const fs::path glb = city();
  std::string bytes;
  {
    std::ifstream in(glb, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  bytes.resize(bytes.size() - 100);  // the binary chunk is cut short
  std::ofstream(dir_ / "cut.glb", std::ios::binary) << bytes;
  const json report = node_json("validate_gltf.mjs", dir_ / "cut.glb", 1);
  EXPECT_GT(report["issues"]["numErrors"].get<int>(), 0);
}

TEST_F(GltfExport, ThreeJsLoadsTagsAndBuildings) {
  const json loaded = node_json("load_gltf_three.mjs", city(2), 0);
  EXPECT_EQ(loaded["nodes"], 18);  // one per building
  std::set<std::string> tags, buildings;
  for (const json& m : loaded["meshes"]) {
    tags.insert(m["tag"].get<std::string>());
    buildings.insert(m["building"].get<std::string>());
    EXPECT_EQ(m["tag"], m["material"]);
    EXPECT_EQ(m["tag_attribute"], json::array({m["tag"]}));  // every vertex's _TAG names the primitive's tag
    EXPECT_TRUE(m["normals"].get<bool>());
    EXPECT_LT(m["normal_error"].get<double>(), 1e-6) << "flat normals, outward as the triangles wind";
    EXPECT_GT(m["triangles"].get<int>(), 0);
  }
  EXPECT_EQ(tags, (std::set<std::string>{"base", "cap", "gable", "party", "roof", "wall"}));
  EXPECT_EQ(buildings.size(), 18u);
  EXPECT_TRUE(buildings.count("w362871296"));  // the cathedral
}

// glTF is +Y up: three.js shows every building standing on y = 0 with its
// plan not mirrored (x east, -z north), each building one top node named by
// its id, standing at its local origin, with its feature's properties and the
// recipe's values in extras, and texture coordinates on every primitive.
TEST_F(GltfExport, ThreeJsSeesBuildingsUprightAtTheirOrigins) {
  BatchCommandOptions o;
  o.recipe = kRoot / "samples" / "city.pxg";
  o.footprints = test::kSampleBlock;
  o.output = dir_ / "city.glb";
  o.report = dir_ / "city.json";
  o.progress = false;
  o.lod = 2;  // the buildings alone: their windows and doors are nodes of their own under them
  std::ostringstream out, err;
  ASSERT_EQ(run_batch(o, out, err), 0) << err.str();
  std::map<std::string, json> report;
  {
    std::ifstream in(o.report);
    const json whole = json::parse(in);
    for (const json& b : whole["buildings"]) report[b["id"].get<std::string>()] = b;
  }
  const json loaded = node_json("load_gltf_three.mjs", o.output, 0);
  ASSERT_EQ(loaded["top"].size(), report.size());
  for (const json& node : loaded["top"]) {
    const std::string id = node["name"];
    SCOPED_TRACE(id);
    ASSERT_TRUE(report.count(id));
    const json& origin = node["extras"]["origin"];  // east, north, up
    ASSERT_EQ(origin.size(), 3u);
    EXPECT_EQ(node["position"], json::array({origin[0], origin[2], -origin[1].get<double>()}));
    EXPECT_EQ(node["extras"]["properties"]["region"], "monaco") << node["extras"].dump();  // every feature has it
    EXPECT_FALSE(node["extras"]["parameters"].empty()) << node["extras"].dump();
  }
  std::map<std::string, std::pair<std::array<double, 3>, std::array<double, 3>>> seen;
  for (const json& m : loaded["meshes"]) {
    EXPECT_TRUE(m["uvs"].get<bool>());
    auto [it, added] = seen.try_emplace(m["building"].get<std::string>());
    auto& [lo, hi] = it->second;
    for (int k = 0; k < 3; ++k) {
      lo[k] = added ? m["min"][k].get<double>() : std::min(lo[k], m["min"][k].get<double>());
      hi[k] = added ? m["max"][k].get<double>() : std::max(hi[k], m["max"][k].get<double>());
    }
  }
  ASSERT_EQ(seen.size(), report.size());
  for (const auto& [id, box] : seen) {
    SCOPED_TRACE(id);
    const json& b = report[id]["bounds"];
    const auto at = [&](const char* end, int k) { return b[end][k].get<double>(); };
    EXPECT_NEAR(box.first[0], at("min", 0), 1e-3);  // x east
    EXPECT_NEAR(box.second[0], at("max", 0), 1e-3);
    EXPECT_NEAR(box.first[1], at("min", 2), 1e-3);  // y up
    EXPECT_NEAR(box.second[1], at("max", 2), 1e-3);
    EXPECT_NEAR(box.first[2], -at("max", 1), 1e-3);  // z south
    EXPECT_NEAR(box.second[2], -at("min", 1), 1e-3);
  }
}

// Millimetres at UTM coordinates: the sample block moved to (500 km east,
// 4,840 km north), where float32 steps by 0.5 m, is the same block in
// three.js (its matrices in doubles), building for building to the
// millimetre, moved by exactly that much: each node's translation holds the
// building's origin in double precision, its vertices are relative to it.
TEST_F(GltfExport, ThreeJsKeepsMillimetresAtUtmCoordinates) {
  const glm::dvec2 offset(500000.0, 4840000.0);
  json block = json::parse(std::ifstream(test::kSampleBlock));
  block.erase("projection");  // its frame no longer
  for (json& f : block["features"]) {
    ASSERT_EQ(f["geometry"]["type"], "Polygon");
    for (json& ring : f["geometry"]["coordinates"])
      for (json& p : ring) p = json::array({p[0].get<double>() + offset.x, p[1].get<double>() + offset.y});
  }
  std::ofstream(dir_ / "block_far.geojson") << block.dump();
  // Each building's bounds as three.js sees them (x east, y up, z south).
  const auto bounds = [&](const fs::path& footprints, const std::string& name) {
    BatchCommandOptions o;
    o.recipe = kRoot / "samples" / "city.pxg";
    o.footprints = footprints;
    o.output = dir_ / (name + ".glb");
    o.progress = false;
    o.lod = 2;
    std::ostringstream out, err;
    EXPECT_EQ(run_batch(o, out, err), 0) << err.str();
    std::map<std::string, std::pair<glm::dvec3, glm::dvec3>> seen;
    const json loaded = node_json("load_gltf_three.mjs", o.output, 0);
    for (const json& m : loaded["meshes"]) {
      auto [it, added] = seen.try_emplace(m["building"].get<std::string>());
      for (int k = 0; k < 3; ++k) {
        const double lo = m["min"][k], hi = m["max"][k];
        it->second.first[k] = added ? lo : std::min(it->second.first[k], lo);
        it->second.second[k] = added ? hi : std::max(it->second.second[k], hi);
      }
    }
    return seen;
  };
  const auto near = bounds(test::kSampleBlock, "near");
  const auto far = bounds(dir_ / "block_far.geojson", "far");
  ASSERT_EQ(near.size(), 18u);
  ASSERT_EQ(far.size(), near.size());
  const glm::dvec3 moved(offset.x, 0.0, -offset.y);
  for (const auto& [id, box] : near) {
    SCOPED_TRACE(id);
    ASSERT_TRUE(far.count(id));
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(far.at(id).first[k], box.first[k] + moved[k], 1e-3) << "axis " << k;
      EXPECT_NEAR(far.at(id).second[k], box.second[k] + moved[k], 1e-3) << "axis " << k;
    }
  }
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

// A placed mesh's material and texture reach the .glb: the image embedded
// once, the validator content (no errors, no warnings, the image read), and
// three.js showing the doors with their texture and their own texture
// coordinates.
TEST_F(GltfExport, PlacedMeshKeepsItsMaterialAndTexture) {
  const fs::path glb = textured_house(".glb");
  const json report = node_json("validate_gltf.mjs", glb, 0);
  EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
  ASSERT_EQ(report["info"]["resources"].size(), 2u) << report["info"].dump(1);  // the binary chunk and the image
  const json& image = report["info"]["resources"][1];
  EXPECT_EQ(image["pointer"], "/images/0");
  EXPECT_EQ(image["mimeType"], "image/png");
  EXPECT_EQ(image["image"]["width"], 16);
  EXPECT_EQ(image["image"]["height"], 32);

  const json loaded = node_json("load_gltf_three.mjs", glb, 0);
  int doors = 0;
  for (const json& m : loaded["meshes"]) {
    EXPECT_EQ(m["texture"].get<bool>(), m["tag"] == "door") << m.dump();
    if (m["tag"] != "door") continue;
    ++doors;
    EXPECT_TRUE(m["uvs"].get<bool>());
    EXPECT_EQ(m["colour"], json::array({1, 1, 1}));
    EXPECT_EQ(m["texture_size"], json::array({16, 32}));  // the image decoded
  }
  EXPECT_GT(doors, 0);
}

// The .obj's library gives the door its colour and a map_Kd that names the
// sample's image relative to the output's folder.
TEST_F(GltfExport, ObjLibraryNamesThePlacedMeshsTexture) {
  const fs::path obj = textured_house(".obj");
  std::ifstream in(dir_ / "out" / "house.mtl");
  const std::string mtl((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(mtl.find("newmtl door\nKd 1 1 1\nPr 0.9\nPm 0\nmap_Kd ../meshes/door_planks.png\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl door_frame\nKd 0.2 0.25 0.3\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl wall\nKd 0.82 0.78 0.7\n"), std::string::npos) << mtl;  // the building keeps its tag colours
  EXPECT_TRUE(fs::exists(obj.parent_path() / "../meshes/door_planks.png"));
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

// samples/textured_house.pxg made for batch (its Footprint Shape replaced by
// the graph input `footprint`), in dir, its textures beside it.
fs::path textured_batch_recipe(const fs::path& dir) {
  fs::copy(kRoot / "samples" / "textures", dir / "textures", fs::copy_options::recursive | fs::copy_options::skip_existing);
  json recipe = json::parse(std::ifstream(kRoot / "samples" / "textured_house.pxg"));
  recipe["inputs"] = json::array({{{"name", "footprint"}, {"type", "footprint"}, {"doc", "bound by procex batch"}}});
  for (json& link : recipe["links"])
    if (link["from"] == "1.footprint") link["from"] = "@footprint";
  json nodes = json::array(), exposed = json::array();
  for (const json& n : recipe["nodes"])
    if (n["id"] != 1) nodes.push_back(n);
  for (const json& e : recipe["exposed"])
    if (e["node"] != 1) exposed.push_back(e);
  recipe["nodes"] = nodes;
  recipe["exposed"] = exposed;
  recipe["editor"]["nodes"].erase("1");
  recipe["presets"] = json::array();
  std::ofstream(dir / "textured_batch.pxg") << recipe.dump(1);
  return dir / "textured_batch.pxg";
}

// The Material nodes' looks reach the .glb: the validator finds no error and
// no warning in the sample's file nor in a batch's (every building's walls
// sharing one embedded brick image), and three.js sees each tag's roughness,
// metalness, texture and its repeat (KHR_texture_transform: 1 / tile_size).
TEST_F(GltfExport, MaterialsReachTheValidatorAndThreeJs) {
  const fs::path single = dir_ / "textured_house.glb";
  std::ostringstream o, e;
  ASSERT_EQ(run_eval(test::eval_options(kRoot / "samples" / "textured_house.pxg", single), o, e), 0) << e.str();
  BatchCommandOptions b;
  b.recipe = textured_batch_recipe(dir_);
  b.footprints = test::kSampleBlock;
  b.output = dir_ / "textured_block.glb";
  b.progress = false;
  ASSERT_EQ(run_batch(b, o, e), 0) << e.str();
  for (const fs::path& glb : {single, b.output}) {
    SCOPED_TRACE(glb.filename().string());
    const json report = node_json("validate_gltf.mjs", glb, 0);
    EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
    EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
    EXPECT_EQ(report["info"]["resources"].size(), 3u) << report["info"].dump(1);  // the binary chunk, brick, roof tiles
    EXPECT_EQ(report["info"]["extensionsUsed"], json::array({"KHR_texture_transform"}));

    const json loaded = node_json("load_gltf_three.mjs", glb, 0);
    std::map<std::string, int> seen;
    for (const json& m : loaded["meshes"]) {
      const std::string tag = m["tag"];
      ++seen[tag];
      SCOPED_TRACE(tag);
      if (tag == "wall" || tag == "gable") {
        EXPECT_NEAR(m["roughness"].get<double>(), 0.85, 1e-6);
        EXPECT_EQ(m["metalness"], 0);
        EXPECT_EQ(m["texture_size"], json::array({64, 64}));
        EXPECT_NEAR(m["texture_repeat"][0].get<double>(), 1 / 0.8, 1e-6);
        EXPECT_NEAR(m["texture_repeat"][1].get<double>(), 1 / 0.8, 1e-6);
        EXPECT_EQ(m["colour"], json::array({1, 1, 1}));
      } else if (tag == "roof") {
        EXPECT_NEAR(m["roughness"].get<double>(), 0.6, 1e-6);
        EXPECT_NEAR(m["texture_repeat"][0].get<double>(), 1 / 1.2, 1e-6);
      } else if (tag == "soffit") {
        EXPECT_FALSE(m["texture"].get<bool>());
        EXPECT_NEAR(m["roughness"].get<double>(), 0.5, 1e-6);
        EXPECT_NEAR(m["colour"][2].get<double>(), 0.85, 1e-6);
      } else {
        EXPECT_FALSE(m["texture"].get<bool>());
        EXPECT_NEAR(m["roughness"].get<double>(), 0.9, 1e-6);  // a tag without a Material keeps procex's look
      }
    }
    EXPECT_GT(seen["wall"], 0);
    EXPECT_GT(seen["roof"], 0);
    EXPECT_GT(seen["soffit"], 0);
  }
}

// The .obj's library: each tag's colour, roughness and metalness (MTL's PBR
// extension) and its texture scaled to tiles (-s 1/tile_size), named relative
// to the .obj.
TEST_F(GltfExport, ObjLibraryScalesTheTextureToItsTiles) {
  fs::copy(kRoot / "samples" / "textures", dir_ / "textures");
  fs::copy_file(kRoot / "samples" / "textured_house.pxg", dir_ / "textured_house.pxg");
  fs::create_directories(dir_ / "out");
  std::ostringstream o, e;
  ASSERT_EQ(run_eval(test::eval_options(dir_ / "textured_house.pxg", dir_ / "out" / "house.obj"), o, e), 0)
      << e.str();
  std::ifstream in(dir_ / "out" / "house.mtl");
  const std::string mtl((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(mtl.find("newmtl wall\nKd 1 1 1\nPr 0.85\nPm 0\nmap_Kd -s 1.25 1.25 1 ../textures/brick.png\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl soffit\nKd 0.9 0.9 0.85\nPr 0.5\nPm 0\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl base\nKd "), std::string::npos) << mtl;
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

// samples/windows_grid.pxg with the sample's textured door (door_textured.obj:
// `door` planks from an image, a painted `door_frame`) placed in its grid
// with the tag `entrance`; the attic keeps its window (frame, glass, sill).
// With `material`, a Material node after the placements names `entrance`:
// green, roughness 0.4. Written by procex eval to dir/out/doors<extension>.
fs::path tagged_doors(const fs::path& dir, bool material, const std::string& extension) {
  fs::copy(kRoot / "samples" / "meshes", dir / "meshes", fs::copy_options::recursive | fs::copy_options::skip_existing);
  json recipe = json::parse(std::ifstream(kRoot / "samples" / "windows_grid.pxg"));
  for (json& n : recipe["nodes"])
    if (n["id"] == 9) n["params"]["file"] = "meshes/door_textured.obj", n["params"]["tag"] = "entrance";
  if (material) {
    recipe["nodes"].push_back({{"id", 11}, {"type", "Material"}, {"version", 1},
                               {"params", {{"tag", "entrance"}, {"colour", {0.1, 0.5, 0.2}}, {"roughness", 0.4}}}});
    for (json& link : recipe["links"])
      if (link["to"] == "@mesh") link["to"] = "11.mesh";
    recipe["links"].push_back({{"from", "11.mesh"}, {"to", "@mesh"}});
  }
  const fs::path pxg = dir / (material ? "green_doors.pxg" : "doors.pxg");
  std::ofstream(pxg) << recipe.dump(1);
  fs::create_directories(dir / "out");
  const fs::path output = dir / "out" / (pxg.stem().string() + extension);
  std::ostringstream o, e;
  EXPECT_EQ(run_eval(test::eval_options(pxg, output), o, e), 0) << e.str();
  return output;
}

// What Blender (headless, tools/blender_import.py) makes of `file`: its objects.
json blender_objects(const fs::path& dir, const fs::path& file) {
  const fs::path report = dir / "blender.json";
  const ProcessRun r = run("blender -b --factory-startup --python " + (kTools / "blender_import.py").string() + " -- " +
                           report.string() + " " + file.string());
  EXPECT_EQ(r.code, 0) << "blender (scripts/install-deps.sh installs it) failed:\n" << r.out;
  return json::parse(std::ifstream(report)).at(file.string());
}

// The placed doors' looks in three.js, by their primitive's tag: of the
// meshes placed under the instance tag `entrance`.
std::map<std::string, json> entrance_looks(const json& loaded) {
  std::map<std::string, json> looks;
  for (const json& m : loaded["meshes"])
    if (m["node_tag"] == "entrance") looks[m["tag"].get<std::string>()] = m;
  return looks;
}

// A placement's tag does not take the placed mesh's own materials away: the
// doors placed as `entrance` keep their planks image and painted frame in the
// .glb (the validator content, three.js showing them) and in the .obj's
// library (two looks under the tag: entrance, entrance_2), which Blender reads.
TEST_F(GltfExport, APlacementsTagKeepsThePlacedMeshsOwnMaterials) {
  const fs::path glb = tagged_doors(dir_, false, ".glb");
  const json report = node_json("validate_gltf.mjs", glb, 0);
  EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["info"]["resources"].size(), 2u) << report["info"].dump(1);  // the binary chunk and the planks
  const auto looks = entrance_looks(node_json("load_gltf_three.mjs", glb, 0));
  ASSERT_TRUE(looks.count("door") && looks.count("door_frame")) << json(looks).dump(1);
  EXPECT_TRUE(looks.at("door")["texture"].get<bool>());
  EXPECT_EQ(looks.at("door")["texture_size"], json::array({16, 32}));
  EXPECT_FALSE(looks.at("door_frame")["texture"].get<bool>());
  EXPECT_NEAR(looks.at("door_frame")["colour"][2].get<double>(), 0.3, 1e-6);

  const fs::path obj = tagged_doors(dir_, false, ".obj");
  const std::string mtl = test::read_text(dir_ / "out" / "doors.mtl");
  EXPECT_NE(mtl.find("newmtl entrance\nKd 1 1 1\nPr 0.9\nPm 0\nmap_Kd ../meshes/door_planks.png\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl entrance_2\nKd 0.2 0.25 0.3\n"), std::string::npos) << mtl;
  EXPECT_EQ(mtl.find("newmtl door"), std::string::npos) << mtl;      // the doors' faces are the entrance's
  std::map<std::string, json> blender;
  for (const json& o : blender_objects(dir_, obj))
    for (const auto& [name, look] : o["looks"].items()) blender[name] = look;
  ASSERT_TRUE(blender.count("entrance") && blender.count("entrance_2")) << json(blender).dump(1);
  EXPECT_EQ(blender.at("entrance")["image"], "door_planks.png");
  EXPECT_TRUE(blender.at("entrance_2")["image"].is_null());
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(blender.at("entrance_2")["colour"][k].get<double>(), (std::array{0.2, 0.25, 0.3}[k]), 1e-6);
}

// A Material naming the placement's tag reaches the placed faces: the doors
// placed as `entrance` are green and no longer show their planks in the .glb
// (validator, three.js) nor in the .obj (its library, Blender), while the
// attic's untagged window keeps its own materials.
TEST_F(GltfExport, AMaterialNamingAPlacementsTagReachesItsFaces) {
  const fs::path glb = tagged_doors(dir_, true, ".glb");
  const json report = node_json("validate_gltf.mjs", glb, 0);
  EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["info"]["resources"].size(), 1u) << report["info"].dump(1);  // no image left
  const json loaded = node_json("load_gltf_three.mjs", glb, 0);
  const auto looks = entrance_looks(loaded);
  ASSERT_EQ(looks.size(), 1u) << json(looks).dump(1);
  const json& green = looks.begin()->second;
  EXPECT_EQ(looks.begin()->first, "entrance");
  EXPECT_EQ(green["material"], "entrance");
  EXPECT_FALSE(green["texture"].get<bool>());
  EXPECT_NEAR(green["roughness"].get<double>(), 0.4, 1e-6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(green["colour"][k].get<double>(), (std::array{0.1, 0.5, 0.2}[k]), 1e-6);
  std::set<std::string> attic;
  for (const json& m : loaded["meshes"])
    if (m["tag"] == "frame" || m["tag"] == "glass" || m["tag"] == "sill") attic.insert(m["tag"].get<std::string>());
  EXPECT_EQ(attic, (std::set<std::string>{"frame", "glass", "sill"}));

  const fs::path obj = tagged_doors(dir_, true, ".obj");
  const std::string mtl = test::read_text(dir_ / "out" / "green_doors.mtl");
  const std::string green_entrance = "newmtl entrance\nKd 0.1 0.5 0.2\nPr 0.4\nPm 0\n";
  const std::size_t at = mtl.find(green_entrance);
  ASSERT_NE(at, std::string::npos) << mtl;
  EXPECT_NE(mtl.substr(at + green_entrance.size(), 6), "map_Kd") << mtl;
  EXPECT_EQ(mtl.find("entrance_2"), std::string::npos) << mtl;
  EXPECT_EQ(mtl.find("door_planks"), std::string::npos) << mtl;
  std::map<std::string, json> blender;
  for (const json& o : blender_objects(dir_, obj))
    for (const auto& [name, look] : o["looks"].items()) blender[name] = look;
  ASSERT_TRUE(blender.count("entrance")) << json(blender).dump(1);
  EXPECT_TRUE(blender.at("entrance")["image"].is_null());
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(blender.at("entrance")["colour"][k].get<double>(), (std::array{0.1, 0.5, 0.2}[k]), 1e-6);
}

}  // namespace
}  // namespace procex

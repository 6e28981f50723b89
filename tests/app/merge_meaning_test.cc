// procex merge reads its parts by ranges (core/io/glb_read.h), no longer
// through tinygltf's document of each. Here tinygltf, the reader merge used
// before, reads the parts and the merged file: every building of the sample
// block (shards of a run with a CRS: origins in extras, textured doors
// instanced with their own materials and texture coordinates) means in the
// merged file what it meant in its part, and the Khronos validator passes
// the merged file.
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "app/cli/batch_command.h"
#include "app/cli/merge_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"
#include "tests/support/gltf_scripts.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

json value_json(const tinygltf::Value& v) {
  if (v.IsBool()) return v.Get<bool>();
  if (v.IsInt() || v.IsNumber()) return v.GetNumberAsDouble();
  if (v.IsString()) return v.Get<std::string>();
  if (v.IsArray()) {
    json out = json::array();
    for (std::size_t i = 0; i < v.ArrayLen(); ++i) out.push_back(value_json(v.Get(static_cast<int>(i))));
    return out;
  }
  if (v.IsObject()) {
    json out = json::object();
    for (const std::string& key : v.Keys()) out[key] = value_json(v.Get(key));
    return out;
  }
  return nullptr;
}

// A file as tinygltf reads it, described building by building in terms that
// do not depend on where in the file a building is: its arrays' values, its
// materials and tags by content, its instances' meshes by name.
class Described {
 public:
  explicit Described(const fs::path& file) {
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m_, &err, &warn, file.string())) << file << ": " << err;
    scene_extras = value_json(m_.scenes.at(0).extras);
    for (const int n : m_.scenes.at(0).nodes) buildings[m_.nodes.at(static_cast<std::size_t>(n)).name] = node(n);
  }
  json scene_extras;
  std::map<std::string, json> buildings;

 private:
  std::string data(int accessor) const {
    const tinygltf::Accessor& a = m_.accessors.at(static_cast<std::size_t>(accessor));
    const tinygltf::BufferView& v = m_.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const std::size_t size = a.count * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(a.type)) * 4;
    const auto& bytes = m_.buffers.at(static_cast<std::size_t>(v.buffer)).data;
    return {bytes.begin() + static_cast<std::ptrdiff_t>(v.byteOffset + a.byteOffset),
            bytes.begin() + static_cast<std::ptrdiff_t>(v.byteOffset + a.byteOffset + size)};
  }
  json material(int index) const {
    const tinygltf::Material& mat = m_.materials.at(static_cast<std::size_t>(index));
    json out = {{"name", mat.name},
                {"colour", mat.pbrMetallicRoughness.baseColorFactor},
                {"roughness", mat.pbrMetallicRoughness.roughnessFactor},
                {"metallic", mat.pbrMetallicRoughness.metallicFactor}};
    if (const int t = mat.pbrMetallicRoughness.baseColorTexture.index; t >= 0) {
      const tinygltf::Image& image = m_.images.at(static_cast<std::size_t>(m_.textures.at(static_cast<std::size_t>(t)).source));
      const auto& bytes = m_.buffers.at(0).data;
      const tinygltf::BufferView& v = m_.bufferViews.at(static_cast<std::size_t>(image.bufferView));
      out["image"] = json::binary_t(std::vector<std::uint8_t>(bytes.begin() + static_cast<std::ptrdiff_t>(v.byteOffset),
                                                              bytes.begin() + static_cast<std::ptrdiff_t>(v.byteOffset + v.byteLength)));
      out["mime"] = image.mimeType;
      for (const auto& [name, ext] : mat.pbrMetallicRoughness.baseColorTexture.extensions) out["texture"][name] = value_json(ext);
    }
    return out;
  }
  json mesh(int index) const {
    const tinygltf::Mesh& mesh = m_.meshes.at(static_cast<std::size_t>(index));
    const json tags = value_json(m_.asset.extras)["tags"];
    json out = {{"name", mesh.name}, {"extras", value_json(mesh.extras)}, {"primitives", json::array()}};
    for (const tinygltf::Primitive& p : mesh.primitives) {
      const std::string indices = data(p.indices);
      json prim = {{"extras", value_json(p.extras)}, {"mode", p.mode}, {"material", material(p.material)},
                   {"indices", json::binary_t(std::vector<std::uint8_t>(indices.begin(), indices.end()))}};
      for (const auto& [name, accessor] : p.attributes) {
        const std::string bytes = data(accessor);
        if (name == "_TAG") {  // numbers into the asset's list of tags, which differs between files: the names
          std::vector<float> ids(bytes.size() / 4);
          std::memcpy(ids.data(), bytes.data(), bytes.size());
          for (const float id : ids) prim["tags"].push_back(tags.at(static_cast<std::size_t>(id)));
        } else {
          prim[name] = json::binary_t(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
        }
      }
      out["primitives"].push_back(prim);
    }
    return out;
  }
  json node(int index) const {
    const tinygltf::Node& n = m_.nodes.at(static_cast<std::size_t>(index));
    json out = {{"name", n.name}, {"translation", n.translation}, {"matrix", n.matrix}, {"extras", value_json(n.extras)}};
    if (n.mesh >= 0) out["mesh"] = mesh(n.mesh);
    for (const int c : n.children) out["children"].push_back(node(c));
    return out;
  }
  tinygltf::Model m_;
};

class MergeMeaning : public test::CommandTest {};

// Three shards of a run merged; each of the parts' buildings compared with
// the merged file's. `footprints`: their file; `crs`: the run's --crs
// ("" for none); `streets`: street lines, which give the houses their
// textured doors. Counts what the buildings hold.
struct Held {
  std::size_t buildings = 0, instanced = 0, textured = 0;
};

Held merge_and_compare(const fs::path& dir, const fs::path& footprints, const std::string& crs, const fs::path& streets,
                       std::ostream& out, std::ostream& err) {
  Held held;
  MergeCommandOptions merge;
  for (std::size_t i = 0; i < 3; ++i) {
    BatchCommandOptions shard;
    shard.recipe = fs::path(PROCEX_SAMPLES) / "city.pxg";
    shard.footprints = footprints, shard.streets = streets;
    shard.export_options.crs = crs;
    shard.output = dir / ("shard" + std::to_string(i) + ".glb");
    shard.progress = false, shard.jobs = 1, shard.shard = i, shard.shards = 3;
    EXPECT_EQ(run_batch(shard, out, err), 0);
    merge.parts.push_back(shard.output);
  }
  merge.output = dir / "merged.glb";
  EXPECT_EQ(run_merge(merge, out, err), 0);

  const Described merged(merge.output);
  for (const fs::path& part : merge.parts) {
    const Described shard(part);
    EXPECT_EQ(shard.scene_extras.value("crs", json()), merged.scene_extras.value("crs", json()));
    for (const auto& [name, building] : shard.buildings) {
      SCOPED_TRACE(name);
      ++held.buildings;
      EXPECT_TRUE(merged.buildings.count(name) && building == merged.buildings.at(name));
      EXPECT_TRUE(building.at("extras").contains("origin"));
      held.instanced += building.contains("children");
      held.textured += building.dump().find("\"image\"") != std::string::npos;
    }
  }
  EXPECT_EQ(held.buildings, merged.buildings.size());
  EXPECT_EQ(merged.scene_extras.at("shard").at("count"), 1.0);
  EXPECT_EQ(merged.scene_extras.contains("crs"), !crs.empty());  // the run's CRS, as WKT

  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", merge.output);
  EXPECT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
  EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
  return held;
}

TEST_F(MergeMeaning, TheSampleBlockInItsCrs) {
  const Held held = merge_and_compare(dir_, test::kSampleBlock, test::sample_block_crs(), {}, out_, err_);
  EXPECT_EQ(held.buildings, 18u) << err_.str();
  EXPECT_GT(held.instanced, 0u);  // windows placed on the buildings, with their own materials
}

TEST_F(MergeMeaning, TerracedHousesWithTexturedDoors) {
  const fs::path footprints = fs::path(PROCEX_SAMPLES) / "footprints";
  const Held held = merge_and_compare(dir_, footprints / "terrace.geojson", "", footprints / "terrace_east_street.geojson",
                                      out_, err_);
  EXPECT_EQ(held.buildings, 3u) << err_.str();
  EXPECT_GT(held.textured, 0u);  // the door's image and texture coordinates
}

}  // namespace
}  // namespace procex

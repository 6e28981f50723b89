// procex merge of shard files that hold placed meshes (windows instanced on
// each building): the merged file has the bytes of the file one run writes,
// each placed mesh once, every instance where it was.
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "app/cli/merge_command.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/mesh_read.h"
#include "core/placement/frame_transform.h"
#include "core/placement/placement_gltf.h"
#include "tests/app/command_test.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::read_text;

class MergeShards : public test::CommandTest {
 protected:
  // Building b: the dormer box moved along x, a window at each of `windows`
  // places (b + 1 unless given). Each call reads the files again, as each
  // shard process does.
  PlacementResult building(int b, int windows = 0) {
    const auto box = std::make_shared<const Mesh>(read_mesh_file(fs::path(PROCEX_TEST_DATA) / "mesh_dormer_box.obj"));
    const auto window = std::make_shared<const Mesh>(read_mesh_file(fs::path(PROCEX_TEST_DATA) / "mesh_window_frame.obj"));
    PlacementResult r;
    r.building = box;
    const std::size_t w = r.add_mesh({"window", window});
    for (int k = 0; k < (windows > 0 ? windows : b + 1); ++k) {
      Frame f;
      f.origin = {10.0 * b + k, 0, 1};
      r.add_instance({w, place_at(f), k % 2 ? "shutter" : "", -1});
    }
    return r;
  }
  // (Built with append: g++ 12 warns falsely on "b" + std::to_string.)
  static std::string name(int b) { return std::string("b").append(std::to_string(b)); }
  void add(GltfSceneBuilder& to, int b, int windows = 0) { to.add(building(b, windows), name(b), b); }
  // What procex batch writes in a shard's scene: shard i of n of one run.
  static GltfScene stamped(GltfScene scene, int i, int n) {
    scene.extras["shard"] = std::string(R"({"index":)").append(std::to_string(i)).append(R"(,"count":)")
                                .append(std::to_string(n)).append(R"(,"recipe":"r","footprints":"f"})");
    return scene;
  }
};

TEST_F(MergeShards, PlacedMeshesMergeIntoTheBytesOfOneRun) {
  GltfSceneBuilder one;
  for (int b = 0; b < 5; ++b) add(one, b);
  write_glb(dir_ / "one.glb", stamped(one.scene(), 0, 1));

  MergeCommandOptions merge;
  for (int shard = 0; shard < 2; ++shard) {  // buildings 0, 2, 4 and 1, 3
    GltfSceneBuilder part;
    for (int b = shard; b < 5; b += 2) add(part, b);
    merge.parts.push_back(dir_ / std::string("part").append(std::to_string(shard)).append(".glb"));
    write_glb(merge.parts.back(), stamped(part.scene(), shard, 2));
  }
  std::swap(merge.parts[0], merge.parts[1]);  // parts come in any order
  merge.output = dir_ / "merged.glb";
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  EXPECT_TRUE(read_text(merge.output) == read_text(dir_ / "one.glb"));

  const GltfScene merged = read_glb_scene(merge.output);
  ASSERT_EQ(merged.prototypes.size(), 1u);
  ASSERT_EQ(merged.meshes.size(), 5u);
  for (int b = 0; b < 5; ++b) {
    EXPECT_EQ(merged.meshes[static_cast<std::size_t>(b)].building, name(b));
    ASSERT_EQ(merged.meshes[static_cast<std::size_t>(b)].instances.size(), static_cast<std::size_t>(b + 1));
    EXPECT_EQ(merged.meshes[static_cast<std::size_t>(b)].instances.back().transform[3][0], 10.0 * b + b);
  }
}

// More buildings than merge reads back at a time (it sets each part's aside
// on disk and writes them window by window): still the bytes of one run.
TEST_F(MergeShards, ManyBuildingsMergeWindowByWindow) {
  constexpr int kBuildings = 700;
  GltfSceneBuilder one;
  for (int b = 0; b < kBuildings; ++b) add(one, b, b % 3 + 1);
  write_glb(dir_ / "one.glb", stamped(one.scene(), 0, 1));
  MergeCommandOptions merge;
  for (int shard = 0; shard < 3; ++shard) {
    GltfSceneBuilder part;
    for (int b = shard; b < kBuildings; b += 3) add(part, b, b % 3 + 1);
    merge.parts.push_back(dir_ / std::string("part").append(std::to_string(shard)).append(".glb"));
    write_glb(merge.parts.back(), stamped(part.scene(), shard, 3));
  }
  merge.output = dir_ / "merged.glb";
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  EXPECT_TRUE(read_text(merge.output) == read_text(dir_ / "one.glb"));
  EXPECT_EQ(read_glb_scene(merge.output).meshes.size(), static_cast<std::size_t>(kBuildings));
}

TEST_F(MergeShards, UnreadablePartIsNamed) {
  GltfSceneBuilder part;
  add(part, 0);
  write_glb(dir_ / "part.glb", stamped(part.scene(), 0, 2));
  std::string bytes = read_text(dir_ / "part.glb");
  bytes.resize(bytes.size() / 2);
  std::ofstream(dir_ / "cut.glb", std::ios::binary) << bytes;
  MergeCommandOptions merge{{dir_ / "part.glb", dir_ / "cut.glb"}, dir_ / "merged.glb", {}};
  EXPECT_EQ(run_merge(merge, out_, err_), 2);
  EXPECT_NE(err_.str().find("cut.glb"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(merge.output));
}

}  // namespace
}  // namespace procex

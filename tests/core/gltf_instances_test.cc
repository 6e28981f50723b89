// Placed meshes in .glb files: one glTF mesh per distinct placed mesh, one
// node per instance with its matrix; the file passes the Khronos validator
// and reads back to the same instances.

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "core/io/mesh_read.h"
#include "core/io/up_axis.h"
#include "core/placement/frame_transform.h"
#include "core/placement/placement_gltf.h"
#include "core/placement/stretch.h"
#include "tests/core/mesh_fixtures.h"
#include "tests/support/gltf_scripts.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const Mesh> read(const std::string& name) {
  return std::make_shared<const Mesh>(read_mesh_file(fs::path(PROCEX_TEST_DATA) / name));
}

class GltfInstances : public test::ScratchDirTest {
 protected:
  // Building b of a street: windows on the front wall (rotation and
  // translation), one pillar mirrored, one leaning (a shear).
  PlacementResult building(int b) {
    if (!window_) window_ = read("mesh_window_frame.obj");
    if (!pillar_) pillar_ = read("mesh_pillar.obj");
    PlacementResult r;
    const double x0 = 20.0 * b;
    r.building = std::make_shared<const Mesh>(build_mesh(test::box({x0, 0, 0}, {x0 + 10, 6, 4})));
    const std::size_t w = r.add_mesh({"window", window_});
    const std::size_t p = r.add_mesh({"pillar", pillar_});
    Frame front;  // along +x, up +z, normal -y
    for (double x : {2.5, 7.5}) {
      front.origin = {x0 + x, 0, 1};
      r.add_instance({w, place_at(front), "", 0});
    }
    front.origin = {x0 - 1, 0, 0};
    FramePlacement mirrored;
    mirrored.scale = {-1, 1, 1};
    r.add_instance({p, place_at(front, mirrored), "column", -1});
    r.add_instance({p, stretch_between(bounds(*pillar_), front, {x0 + 11, 0, 0}, {x0 + 12, 0, 4}), "", -1});
    return r;
  }

  // Two buildings sharing the window and the pillar.
  GltfScene street() {
    GltfSceneBuilder builder;
    for (int b = 0; b < 2; ++b) builder.add(building(b), "b" + std::to_string(b), b);
    return builder.scene();
  }

  std::string bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  std::shared_ptr<const Mesh> window_, pillar_;
};

TEST_F(GltfInstances, OneMeshPerPlacedMeshOneNodePerInstance) {
  const GltfScene scene = street();
  ASSERT_EQ(scene.prototypes.size(), 2u);
  EXPECT_EQ(scene.prototypes[0].building, "window");
  EXPECT_EQ(scene.prototypes[1].building, "pillar");
  EXPECT_EQ(scene.prototypes[1].primitives.at(0).tag, "stone");  // its own usemtl tag
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[1].instances.size(), 4u);
  EXPECT_EQ(scene.meshes[1].instances[2].prototype, 1u);
  EXPECT_EQ(scene.meshes[1].instances[2].tag, "column");
}

// A mesh's look is carried beside it: the same shared window with another
// material table is another prototype (and primitive material), while equal
// tables made apart (a Material node's, one per building) share one.
TEST_F(GltfInstances, OnePrototypePerMeshAndLook) {
  Material red, blue;
  red.colour = {1, 0, 0};
  blue.colour = {0, 0, 1};
  GltfSceneBuilder builder;
  for (const Material& look : {red, red, blue}) {
    PlacementResult r = building(0);
    r.meshes[0].materials = material_table({{"frame", look}});
    builder.add(r, "b");
  }
  const GltfScene& scene = builder.scene();
  ASSERT_EQ(scene.prototypes.size(), 3u);  // window red, pillar, window blue
  EXPECT_EQ(scene.meshes[0].instances[0].prototype, scene.meshes[1].instances[0].prototype);
  EXPECT_NE(scene.meshes[0].instances[0].prototype, scene.meshes[2].instances[0].prototype);
  const auto colour = [&](std::size_t prototype) {
    for (const GltfPrimitiveData& p : scene.prototypes.at(prototype).primitives)
      if (p.tag == "frame" && p.material) return p.material->colour;
    ADD_FAILURE() << "prototype " << prototype << " has no material for frame";
    return std::array<double, 3>{};
  };
  EXPECT_EQ(colour(scene.meshes[0].instances[0].prototype), red.colour);
  EXPECT_EQ(colour(scene.meshes[2].instances[0].prototype), blue.colour);
}

// A batch's buildings share one memo of placed meshes in glTF form: each
// builder still gets the prototypes it would make alone, a mesh named or
// coloured otherwise by another building not taken for the first one's.
TEST_F(GltfInstances, BuildersSharingPrototypesMakeWhatEachMakesAlone) {
  Material red;
  red.colour = {1, 0, 0};
  const auto looks = [&](const std::string& name, const MaterialTable& materials) {
    PlacementResult r = building(0);
    r.meshes[0].name = name;
    r.meshes[0].materials = materials;
    return r;
  };
  const PlacementResult buildings[] = {looks("window", nullptr), looks("door", nullptr),
                                       looks("window", material_table({{"frame", red}})), looks("window", nullptr)};
  const auto shared = std::make_shared<GltfPrototypeMemo>();
  for (const PlacementResult& b : buildings) {
    GltfSceneBuilder alone, sharing(shared);
    alone.add(b, "b");
    sharing.add(b, "b");
    ASSERT_EQ(sharing.scene().prototypes.size(), alone.scene().prototypes.size());
    for (std::size_t p = 0; p < alone.scene().prototypes.size(); ++p) {
      EXPECT_EQ(sharing.scene().prototypes[p].building, alone.scene().prototypes[p].building);
      EXPECT_TRUE(sharing.scene().prototypes[p].primitives == alone.scene().prototypes[p].primitives) << p;
    }
  }
}

TEST_F(GltfInstances, RoundTripKeepsEveryInstance) {
  const GltfScene scene = street();
  const fs::path file = dir_ / "street.glb";
  write_glb(file, scene);
  const GltfScene back = read_glb_scene(file);
  ASSERT_EQ(back.prototypes.size(), 2u);
  ASSERT_EQ(back.meshes.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_EQ(back.prototypes[p].building, scene.prototypes[p].building);
    ASSERT_EQ(back.prototypes[p].primitives.size(), scene.prototypes[p].primitives.size());
    EXPECT_EQ(back.prototypes[p].primitives[0].positions, scene.prototypes[p].primitives[0].positions);
  }
  for (std::size_t b = 0; b < 2; ++b) {
    EXPECT_EQ(back.meshes[b].building, scene.meshes[b].building);
    EXPECT_EQ(back.meshes[b].feature, scene.meshes[b].feature);
    ASSERT_EQ(back.meshes[b].instances.size(), scene.meshes[b].instances.size());
    for (std::size_t i = 0; i < scene.meshes[b].instances.size(); ++i) {
      const GltfInstanceData &want = scene.meshes[b].instances[i], &got = back.meshes[b].instances[i];
      EXPECT_EQ(got.prototype, want.prototype);
      EXPECT_EQ(got.tag, want.tag);
      // The file holds matrices in float32, as glTF readers do.
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          EXPECT_EQ(static_cast<float>(got.transform[c][r]), static_cast<float>(want.transform[c][r])) << b << " " << i;
    }
  }
  // Files without placed meshes read as before; with them, read_glb says why not.
  EXPECT_THROW(read_glb(file), IoError);
}

TEST_F(GltfInstances, PassesTheKhronosValidator) {
  const fs::path file = dir_ / "street.glb";
  write_glb(file, street());
  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", file);
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
  EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
  // The validator counts each mesh once: 2 buildings (12 triangles each), the
  // window (32) and the pillar (12), though they are placed 4 times each.
  EXPECT_EQ(v.report["info"]["totalTriangleCount"].get<int>(), 2 * 12 + 32 + 12);
}

// What a viewer shows: three.js applies the node matrices (decomposing each
// into translation, rotation and scale, so a shear written as one matrix
// would be lost) and every placed mesh lands where flatten() puts it.
TEST_F(GltfInstances, ThreeJsPlacesEveryInstanceWhereFlattenDoes) {
  const GltfScene scene = street();
  const fs::path file = dir_ / "street.glb";
  write_glb(file, scene);
  const test::NodeScriptRun v = test::run_gltf_script("load_gltf_three.mjs", file);
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  ASSERT_EQ(v.exit_code, 0);
  using Bounds = std::array<double, 6>;
  std::vector<Bounds> want, got;
  for (const GltfMeshData& building : scene.meshes)
    for (const GltfInstanceData& in : building.instances) {
      // The file is +Y up, each instance placed from its building's origin.
      const glm::dmat4 at_origin =
          glm::translate(glm::dmat4(1.0), glm::dvec3(building.origin[0], building.origin[1], building.origin[2]));
      PlacementResult one;
      one.add_instance({one.add_mesh({"", in.prototype == 0 ? window_ : pillar_}),
                        at_origin * in.transform * file_axes_matrix(UpAxis::Y), "", -1});
      const Box3 b = bounds(flatten(one));
      want.push_back({b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z});
    }
  for (const auto& m : v.report["meshes"]) {
    if (m["tag"] != "frame" && m["tag"] != "stone") continue;  // the buildings' own faces
    got.push_back({m["min"][0], m["min"][1], m["min"][2], m["max"][0], m["max"][1], m["max"][2]});
  }
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(got[i][static_cast<std::size_t>(k)], want[i][static_cast<std::size_t>(k)], 1e-4) << i << " " << k;
}

// Two shards, each with its own copies of the placed meshes, joined the way
// procex merge joins them: the same bytes as one run over both buildings.
TEST_F(GltfInstances, ShardsMergeIntoTheBytesOfOneRun) {
  write_glb(dir_ / "one.glb", street());
  GltfScene merged;
  for (int b : {1, 0}) {  // shards finish in any order; merge sorts by feature
    window_ = pillar_ = nullptr;  // each shard reads the meshes itself
    GltfSceneBuilder shard;
    shard.add(building(b), "b" + std::to_string(b), b);
    write_glb(dir_ / "shard.glb", shard.scene());
    append_scene(merged, read_glb_scene(dir_ / "shard.glb"));
  }
  EXPECT_EQ(merged.prototypes.size(), 4u);
  std::stable_sort(merged.meshes.begin(), merged.meshes.end(),
                   [](const GltfMeshData& a, const GltfMeshData& b) { return a.feature < b.feature; });
  write_glb(dir_ / "merged.glb", merged);
  EXPECT_TRUE(bytes(dir_ / "merged.glb") == bytes(dir_ / "one.glb"));
  EXPECT_EQ(read_glb_scene(dir_ / "merged.glb").prototypes.size(), 2u);  // equal placed meshes written once
}

// A matrix entry's float32 text, read as a double and rounded to float32,
// gives the float back: the shortest text does so for every float but
// 7.038531e-26, which is written with more digits.
TEST_F(GltfInstances, ReadAndWrittenAgainKeepsTheBytes) {
  GltfScene scene = street();
  scene.meshes[0].instances[0].transform[3][0] = 7.0385307e-26;  // in float: 0x15ae43fd
  scene.meshes[0].instances[1].transform[3][0] = -1.2345678e-21;
  write_glb(dir_ / "first.glb", scene);
  write_glb(dir_ / "second.glb", read_glb_scene(dir_ / "first.glb"));
  EXPECT_TRUE(bytes(dir_ / "second.glb") == bytes(dir_ / "first.glb"));
  EXPECT_EQ(static_cast<float>(read_glb_scene(dir_ / "second.glb").meshes[0].instances[0].transform[3][0]), 7.0385307e-26f);
}

// A building's matrices share most entries (a wall's windows, one rotation
// and scale), which the writer formats once a building: entries that repeat,
// and far more distinct ones than it keeps texts for, all read back.
TEST_F(GltfInstances, ABuildingsManyMatricesReadBackAsWritten) {
  PlacementResult r = building(0);
  const std::size_t w = r.add_mesh({"window", window_});
  Frame wall;
  for (int i = 0; i < 300; ++i) {
    const double turn = 0.3 * (i % 3);  // three walls
    wall.along = {std::cos(turn), std::sin(turn), 0};
    wall.normal = {std::sin(turn), -std::cos(turn), 0};
    wall.origin = {0.37 * i, 0.01 * i, 1 + 1e-5 * i};  // heights a few float steps apart
    FramePlacement fit;
    fit.scale = {1 + 0.001 * (i % 7), 1, 1};
    r.add_instance({w, place_at(wall, fit), "", 0});
  }
  GltfSceneBuilder builder;
  builder.add(r, "b0", 0);
  const GltfScene scene = builder.scene();
  write_glb(dir_ / "many.glb", scene);
  const GltfScene back = read_glb_scene(dir_ / "many.glb");
  const std::vector<GltfInstanceData>& want = scene.meshes.at(0).instances;
  const std::vector<GltfInstanceData>& got = back.meshes.at(0).instances;
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    for (int c = 0; c < 4; ++c)
      for (int row = 0; row < 4; ++row)
        ASSERT_EQ(static_cast<float>(got[i].transform[c][row]), static_cast<float>(want[i].transform[c][row]))
            << i << " " << c << " " << row;
}

TEST_F(GltfInstances, UnusedPlacedMeshesAreNotWritten) {
  GltfScene scene = street();
  scene.prototypes.push_back(scene.prototypes[0]);
  scene.prototypes.back().building = "spare";
  write_glb(dir_ / "spare.glb", scene);
  write_glb(dir_ / "plain.glb", street());
  EXPECT_TRUE(bytes(dir_ / "spare.glb") == bytes(dir_ / "plain.glb"));
}

TEST_F(GltfInstances, BadInstancesAreRefusedByTheWriter) {
  GltfScene scene = street();
  scene.meshes[0].instances[1].prototype = 7;
  try {
    write_glb(dir_ / "bad.glb", scene);
    FAIL() << "an instance of a missing placed mesh was written";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("instance 1 of building 'b0' names placed mesh 7"), std::string::npos) << e.what();
  }
  scene = street();
  scene.meshes[1].instances[0].transform[1] = glm::dvec4(0.0);
  EXPECT_THROW(write_glb(dir_ / "bad.glb", scene), IoError);
  EXPECT_FALSE(fs::exists(dir_ / "bad.glb"));
}

}  // namespace
}  // namespace procex

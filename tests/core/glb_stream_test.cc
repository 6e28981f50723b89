// GlbStreamWriter: a .glb streamed a few buildings at a time has the bytes
// write_glb writes for the whole scene in memory, however the buildings are
// split into parts and windows, with placed meshes (shared, unused, equal
// ones in several parts), their own materials and images, buildings with
// and without texture coordinates or triangles; and it passes the Khronos
// validator.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "base/read_file.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "tests/support/gltf_scripts.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

// A square of two triangles at x tagged `tag`, with texture coordinates or not.
GltfPrimitiveData square(const std::string& tag, float x, bool uvs) {
  GltfPrimitiveData p;
  p.tag = tag;
  p.positions = {x, 0, 0, x + 1, 0, 0, x + 1, 1, 0, x, 1, 0};
  p.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  p.indices = {0, 1, 2, 0, 2, 3};
  if (uvs) p.uvs = {0, 0, 1, 0, 1, 1, 0, 1};
  return p;
}

GltfMeshData building(int i, std::vector<GltfPrimitiveData> primitives) {
  GltfMeshData b;
  b.building = "b" + std::to_string(i);
  b.feature = i;
  b.origin = {100.0 * i, 0, -50.5 * i};
  b.properties = {{"height", std::to_string(3 + i)}, {"name", "\"house " + std::to_string(i) + "\""}};
  if (i % 2 == 0) b.parameters = {{"levels", "2"}};
  b.primitives = std::move(primitives);
  return b;
}

class GlbStream : public test::ScratchDirTest {
 protected:
  // The placed meshes every part carries: a textured sign (its own material
  // and image, under the tag the buildings' walls have), a plain post
  // without texture coordinates, and one no building places.
  std::vector<GltfMeshData> placed() {
    GltfMeshData sign, post, unused;
    sign.building = "sign";
    sign.primitives = {square("wall", 0, true)};
    GltfMaterialData& m = sign.primitives[0].material.emplace();
    m.colour = {0.2, 0.4, 0.6};
    m.image = std::make_shared<const std::string>(
        read_file(fs::path(PROCEX_SAMPLES) / "meshes" / "door_planks.png", std::size_t{1} << 20));
    post.building = "post";
    post.primitives = {square("stone", 0, false)};
    unused.building = "unused";
    unused.primitives = {square("glass", 0, true)};
    return {unused, sign, post};
  }

  // Twelve buildings: walls and roofs with texture coordinates, some with
  // instances (a translation, a shear, a mirror), one with only instances,
  // one with no triangles, one tagged with a tag only a later building uses.
  GltfScene city() {
    GltfScene scene;
    scene.prototypes = placed();
    scene.extras = {{"shard", "{\"index\":0}"}};
    for (int i = 0; i < 12; ++i) {
      std::vector<GltfPrimitiveData> prims = {square("wall", 0, true), square(i == 7 ? "chimney" : "roof", 2, true)};
      if (i == 4) prims.clear();
      if (i == 9) prims = {square("wall", 0, true)}, prims[0].indices.clear();
      GltfMeshData& b = scene.meshes.emplace_back(building(i, std::move(prims)));
      if (i % 3 == 1) {
        b.instances.push_back({2, glm::translate(glm::dmat4(1.0), {1.0, 2.0, 3.0}), "post"});
        glm::dmat4 shear(1.0);
        shear[1][0] = 0.5;
        b.instances.push_back({1, shear, ""});
      }
      if (i == 4) b.instances.push_back({1, glm::scale(glm::dmat4(1.0), {-1.0, 1.0, 1.0}), "mirrored"});
    }
    return scene;
  }

  // The scene streamed in parts of `per_part` buildings (each with every
  // placed mesh), `per_window` parts per add.
  std::string streamed(const GltfScene& scene, std::size_t per_part, std::size_t per_window, const std::string& name) {
    fs::remove(dir_ / name);
    GlbStreamWriter writer(dir_ / name, scene.extras);
    std::vector<GltfScene> window;
    for (std::size_t first = 0; first < scene.meshes.size(); first += per_part) {
      GltfScene& part = window.emplace_back();
      part.prototypes = scene.prototypes;
      for (std::size_t i = first; i < std::min(scene.meshes.size(), first + per_part); ++i)
        part.meshes.push_back(scene.meshes[i]);
      if (window.size() == per_window) writer.add(std::move(window)), window.clear();
    }
    writer.add(std::move(window));
    EXPECT_FALSE(fs::exists(dir_ / name));  // nothing before finish
    writer.finish();
    return bytes(dir_ / name);
  }

  std::string bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

};

TEST_F(GlbStream, HasTheBytesOfTheSceneWrittenInMemory) {
  const GltfScene scene = city();
  write_glb(dir_ / "memory.glb", scene);
  const std::string expected = bytes(dir_ / "memory.glb");
  ASSERT_GT(expected.size(), 1000u);
  for (const auto& [per_part, per_window] : {std::pair{1, 1}, {1, 5}, {3, 2}, {12, 1}, {5, 7}})
    EXPECT_EQ(streamed(scene, per_part, per_window, "streamed.glb"), expected) << per_part << " " << per_window;
  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", dir_ / "streamed.glb");
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
  EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
}

// Placed meshes only a later part places come before every building's mesh
// in the file, and move the numbers of what was streamed before them.
TEST_F(GlbStream, APlacedMeshFirstPlacedLateComesFirst) {
  GltfScene scene = city();
  for (GltfMeshData& b : scene.meshes)
    if (std::stoi(b.building.substr(1)) < 10) b.instances.clear();
  write_glb(dir_ / "memory.glb", scene);
  EXPECT_EQ(streamed(scene, 1, 1, "late.glb"), bytes(dir_ / "memory.glb"));
  const GltfScene back = read_glb_scene(dir_ / "late.glb");
  ASSERT_EQ(back.prototypes.size(), 2u);
  EXPECT_EQ(back.prototypes[0].building, "post");
}

TEST_F(GlbStream, NoBuildingsGiveWriteGlbsEmptyScene) {
  GltfScene empty;
  empty.extras = {{"crs", "\"EPSG:32632\""}};
  write_glb(dir_ / "memory.glb", empty);
  GlbStreamWriter writer(dir_ / "empty.glb", empty.extras);
  writer.add({});
  writer.finish();
  EXPECT_EQ(bytes(dir_ / "empty.glb"), bytes(dir_ / "memory.glb"));
}

// What write_glb refuses the stream refuses, naming the building, and it
// writes nothing.
TEST_F(GlbStream, RefusesWhatWriteGlbRefuses) {
  GltfScene scene = city();
  scene.meshes[5].primitives[0].indices[1] = 99;
  {
    GlbStreamWriter writer(dir_ / "bad.glb", {});
    try {
      writer.add({scene});
      ADD_FAILURE() << "an index past its vertices was written";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("mesh 'b5'"), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(fs::exists(dir_ / "bad.glb"));
  scene = city();
  scene.meshes[1].instances[0].prototype = 7;
  GlbStreamWriter writer(dir_ / "bad.glb", {});
  EXPECT_THROW(writer.add({scene}), IoError);
  EXPECT_THROW(GlbStreamWriter(dir_ / "bad.glb", {{"crs", "not json"}}), IoError);
}

}  // namespace
}  // namespace procex

// Meshes placed on a building travel with it through the nodes: Transform
// moves them (and the resolved anchors), Merge keeps them, Export writes them
// as instanced nodes in .glb and flattened into the building in OBJ and PLY.
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/mesh_read.h"
#include "core/io/up_axis.h"
#include "core/placement/box.h"
#include "core/placement/place_mesh.h"
#include "nodes/support/mesh_summary.h"
#include "nodes/values.h"
#include "tests/app/command_test.h"
#include "tests/nodes/hand_anchors.h"
#include "tests/nodes/node_runner.h"
#include "tests/support/gltf_scripts.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::run_node;

const Footprint kPlan = make_footprint({{{0, 0}, {10, 0}, {10, 6}, {0, 6}}}, 45);

PlaceableMesh window() {
  return {"window", std::make_shared<const Mesh>(read_mesh_file(fs::path(PROCEX_TEST_DATA) / "mesh_window_frame.obj"))};
}

// A hipped block with its anchors resolved by hand and a window in the middle of each wall.
MeshSet block_with_windows() {
  const auto r = run_node("Extrude", {}, {{"footprint", Value::make(kPlan)}});
  EXPECT_TRUE(r.ok()) << r.messages();
  MeshSet set = r.outputs.at(0).get<MeshSet>();
  TaggedMesh& part = set.parts.at(0);
  part.anchors = test::wall_anchors(kPlan, "sill", 0.2, 0.5);
  MeshPlacementSpec spec;
  spec.anchor = "sill";
  EXPECT_EQ(place_mesh(part.placed, window(), part.anchors, spec).instances, 4u);
  return set;
}

Box3 instance_bounds(const TaggedMesh& part, std::size_t i) {
  PlacementResult one;
  one.meshes = part.placed.meshes;
  one.instances = {part.placed.instances.at(i)};
  return bounds(flatten(one));
}

// A fresh folder per test, as the command tests have.
using PlacedMeshes = test::CommandTest;
using test::read_text;

TEST_F(PlacedMeshes, TransformMovesInstancesAndAnchors) {
  const MeshSet before = block_with_windows();
  const auto moved = run_node("Transform", {{"translate", Value::make(Vec3{100, 0, 5})}, {"rotate", Value::make(90.0)},
                                            {"scale", Value::make(2.0)}},
                              {{"mesh", Value::make(before)}});
  ASSERT_TRUE(moved.ok()) << moved.messages();
  const TaggedMesh &a = before.parts[0], &b = moved.outputs[0].get<MeshSet>().parts[0];
  ASSERT_EQ(b.placed.instances.size(), 4u);
  // (x, y, z) -> (100 - 2y, 2x, 5 + 2z)
  for (std::size_t i = 0; i < 4; ++i) {
    const Box3 was = instance_bounds(a, i), is = instance_bounds(b, i);
    EXPECT_NEAR(is.lo.x, 100 - 2 * was.hi.y, 1e-9);
    EXPECT_NEAR(is.hi.y, 2 * was.hi.x, 1e-9);
    EXPECT_NEAR(is.lo.z, 5 + 2 * was.lo.z, 1e-9);
  }
  const ResolvedAnchor& front = b.anchors.at(0);  // edge 0: from (0, 0) to (10, 0), facing -y
  EXPECT_NEAR(glm::distance(front.frame.origin, glm::dvec3(100, 10, 5.4)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(front.frame.normal, glm::dvec3(1, 0, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(front.frame.along, glm::dvec3(0, 1, 0)), 0, 1e-12);
  EXPECT_NEAR(glm::distance(front.span_to, glm::dvec3(100, 20, 5.4)), 0, 1e-12);
  EXPECT_NE(Value::make(before).content_hash(), moved.outputs[0].content_hash());
}

TEST_F(PlacedMeshes, SummaryCountsThemApart) {
  const MeshSet set = block_with_windows();
  const MeshSummary with = summarize(set);
  MeshSet bare = set;
  bare.parts[0].placed = {};
  const MeshSummary without = summarize(bare);
  EXPECT_EQ(with.placed, (std::map<std::string, std::size_t>{{"window", 4}}));
  EXPECT_TRUE(without.placed.empty());
  EXPECT_EQ(with.faces, without.faces);
  EXPECT_EQ(with.volume, without.volume);
}

TEST_F(PlacedMeshes, HashSeesInstancesAndAnchors) {
  const MeshSet with = block_with_windows();
  MeshSet without = with, fewer = with, unanchored = with;
  without.parts[0].placed = {};
  fewer.parts[0].placed.instances.pop_back();
  unanchored.parts[0].anchors[2].present = false;
  const Hash128 h = Value::make(with).content_hash();
  EXPECT_EQ(h, Value::make(block_with_windows()).content_hash());  // the same file read again
  for (const MeshSet* other : {&without, &fewer, &unanchored}) EXPECT_NE(h, Value::make(*other).content_hash());
}

TEST_F(PlacedMeshes, MergeAndExportGlbInstances) {
  const Value one = Value::make(block_with_windows());
  const auto moved = run_node("Transform", {{"translate", Value::make(Vec3{20, 0, 0})}}, {{"mesh", one}});
  const auto merged = run_node("Merge", {}, {{"mesh_1", one}, {"mesh_2", moved.outputs[0]}});
  ASSERT_TRUE(merged.ok()) << merged.messages();
  ASSERT_EQ(merged.outputs[0].get<MeshSet>().parts.size(), 2u);
  const auto r = run_node("Export", {{"file", Value::make(std::string("street.glb"))}}, {{"mesh", merged.outputs[0]}}, dir_);
  ASSERT_TRUE(r.ok()) << r.messages();
  // Both parts have no building id: one glTF building, eight window instances of one placed mesh.
  const GltfScene scene = read_glb_scene(dir_ / "street.glb");
  ASSERT_EQ(scene.prototypes.size(), 1u);
  EXPECT_EQ(scene.prototypes[0].building, "window");
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].instances.size(), 8u);
  // In glTF's frame (+Y up), from the building node's origin.
  const GltfMeshData& building = scene.meshes[0];
  const glm::dmat4 from_origin =
      glm::translate(glm::dmat4(1.0), -glm::dvec3(building.origin[0], building.origin[1], building.origin[2]));
  EXPECT_EQ(building.instances[4].transform,
            from_origin * to_file_axes(merged.outputs[0].get<MeshSet>().parts[1].placed.instances[0].transform, UpAxis::Y));
  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", dir_ / "street.glb");
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
  EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
}

TEST_F(PlacedMeshes, ExportFlattensIntoObjAndPly) {
  const MeshSet set = block_with_windows();
  const std::size_t building_faces = set.parts[0].mesh->n_faces(), window_faces = window().mesh->n_faces();
  const Value value = Value::make(set);
  for (const char* name : {"block.obj", "block.ply"}) {
    const auto r = run_node("Export", {{"file", Value::make(std::string(name))}}, {{"mesh", value}}, dir_);
    ASSERT_TRUE(r.ok()) << r.messages();
  }
  const Mesh obj = read_mesh_file(dir_ / "block.obj");
  EXPECT_EQ(obj.n_faces(), building_faces + 4 * window_faces);
  std::map<std::string, std::size_t> per_tag;
  for (const auto f : obj.faces()) ++per_tag[face_tag(obj, f)];
  EXPECT_EQ(per_tag["frame"], 4 * window_faces);  // the window's own material, kept
  EXPECT_EQ(per_tag["roof"], 4u);
  const std::string ply = read_text(dir_ / "block.ply");
  EXPECT_NE(ply.find("element face " + std::to_string(building_faces + 4 * window_faces) + "\n"), std::string::npos);
}

}  // namespace
}  // namespace procex

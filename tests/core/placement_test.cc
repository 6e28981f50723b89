// Placement results and their flattening: closed parts stay closed, mirrored
// instances keep facing out, tags and source edges follow the rules.
#include <filesystem>
#include <memory>

#include <cmath>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/io/mesh_read.h"
#include "core/io/mesh_write.h"
#include "core/mesh/validate.h"
#include "core/placement/placement.h"
#include "core/placement/placement_error.h"
#include "tests/core/mesh_fixtures.h"

namespace procex {
namespace {

std::shared_ptr<const Mesh> read(const std::string& name) {
  return std::make_shared<const Mesh>(read_mesh_file(std::filesystem::path(PROCEX_TEST_DATA) / name));
}

glm::dmat4 translation(double x, double y, double z) { return glm::translate(glm::dmat4(1.0), {x, y, z}); }

TEST(Placement, AddMeshStoresEachMeshOncePerName) {
  PlacementResult r;
  const auto pillar = read("mesh_pillar.obj");
  EXPECT_EQ(r.add_mesh({"pillar", pillar}), 0u);
  EXPECT_EQ(r.add_mesh({"window", read("mesh_window_frame.obj")}), 1u);
  EXPECT_EQ(r.add_mesh({"pillar", pillar}), 0u);
  // The same file placed under another name keeps that name (its faces are tagged by it).
  EXPECT_EQ(r.add_mesh({"column", pillar}), 2u);
  EXPECT_EQ(r.meshes[2].name, "column");
  EXPECT_EQ(r.meshes[2].mesh, pillar);
  EXPECT_EQ(r.meshes.size(), 3u);
  EXPECT_THROW(r.add_mesh({"nothing", nullptr}), PlacementError);
}

TEST(Placement, BadInstancesAreRefused) {
  PlacementResult r;
  r.add_mesh({"pillar", read("mesh_pillar.obj")});
  EXPECT_THROW(r.add_instance({1, glm::dmat4(1.0), {}, -1}), PlacementError);  // no mesh 1
  glm::dmat4 flat(1.0);
  flat[1][1] = 0.0;
  EXPECT_THROW(r.add_instance({0, flat, {}, -1}), PlacementError);
  glm::dmat4 projective(1.0);
  projective[0][3] = 0.5;
  EXPECT_THROW(r.add_instance({0, projective, {}, -1}), PlacementError);
  glm::dmat4 nan(1.0);
  nan[3][0] = std::nan("");
  try {
    r.add_instance({0, nan, {}, -1});
    FAIL() << "a non-finite transform was accepted";
  } catch (const PlacementError& e) {
    EXPECT_NE(std::string(e.what()).find("instance 0 (pillar)"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(r.instances.empty());
}

// A 10 x 6 x 4 block with window frames (closed rings, genus 1) on its front
// and a pillar beside it: everything closed, volumes add up.
TEST(Placement, FlattenKeepsClosedPartsClosed) {
  PlacementResult r;
  r.building = std::make_shared<const Mesh>(build_mesh(test::box({0, 0, 0}, {10, 6, 4})));
  const std::size_t window = r.add_mesh({"window", read("mesh_window_frame.obj")});
  const std::size_t pillar = r.add_mesh({"pillar", read("mesh_pillar.obj")});
  // The window's back on the front wall (y = 0) facing -y: rotate z -> -y.
  const glm::dmat4 to_front = glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0));
  for (double x : {2.0, 5.0, 8.0}) r.add_instance({window, translation(x, -0.001, 1) * to_front, "", 0});
  r.add_instance({pillar, translation(12, 3, 0) * to_front, "column", -1});
  const Mesh m = flatten(r);
  EXPECT_EQ(m.n_faces(), r.building->n_faces() + 3 * 16 + 6);
  const ValidationReport v = validate(m);
  EXPECT_TRUE(v.ok()) << testing::PrintToString(v.problems);
  EXPECT_NEAR(v.volume, 240 + 3 * 0.05 + 0.48, 1e-9);
}

// A mirroring transform (negative determinant) turns a solid inside out
// unless its faces are reversed: the flattened pillar still faces out.
TEST(Placement, MirroredInstancesKeepFacingOut) {
  PlacementResult r;
  const std::size_t pillar = r.add_mesh({"pillar", read("mesh_pillar.obj")});
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), {-2, 1, 1});
  ASSERT_LT(linear_determinant(mirror), 0.0);
  r.add_instance({pillar, mirror, "", -1});
  const ValidationReport v = validate(flatten(r));
  EXPECT_TRUE(v.ok()) << testing::PrintToString(v.problems);
  EXPECT_NEAR(v.volume, 2 * 0.48, 1e-12);
  // Both faces at x = 0.4 and x = -0.4 point away from the pillar.
  const Mesh m = flatten(r);
  Mesh copy = m;
  copy.request_face_normals();
  copy.update_face_normals();
  for (const auto f : copy.faces()) {
    const auto n = copy.normal(f);
    const auto c = copy.calc_face_centroid(f);
    EXPECT_GT(n[0] * c[0] + n[1] * (c[1] - 1.5) + n[2] * (c[2] - 0.2), 0.0) << f.idx();
  }
}

TEST(Placement, FlattenedFacesCarryTagsEdgesAndInstances) {
  PlacementResult r;
  r.building = std::make_shared<const Mesh>(build_mesh(test::box({0, 0, 0}, {10, 6, 4})));
  const std::size_t dormer = r.add_mesh({"dormer", read("mesh_dormer_box.obj")});
  auto untagged = std::make_shared<Mesh>(build_mesh(test::box({0, 0, 0}, {1, 1, 1})));
  const std::size_t block = r.add_mesh({"block", untagged});
  r.add_instance({dormer, translation(20, 0, 0), "", 3});        // keeps wall / roof
  r.add_instance({dormer, translation(30, 0, 0), "lucarne", 4});  // all "lucarne"
  r.add_instance({block, translation(40, 0, 0), "", -1});         // the mesh's name
  const Mesh m = flatten(r);
  OpenMesh::FPropHandleT<int> instance;
  ASSERT_TRUE(m.get_property_handle(instance, kInstanceProperty));
  const int base = static_cast<int>(r.building->n_faces());
  for (const auto f : m.faces()) {
    const int i = m.property(instance, f);
    if (f.idx() < base) {
      EXPECT_EQ(i, -1);
      EXPECT_EQ(face_tag(m, f), face_tag(*r.building, f));
      continue;
    }
    const int local = (f.idx() - base) % 7;
    switch (i) {
      case 0:
        EXPECT_EQ(face_tag(m, f), local < 5 ? "wall" : "roof");
        EXPECT_EQ(source_edge(m, f), 3);
        break;
      case 1:
        EXPECT_EQ(face_tag(m, f), "lucarne");
        EXPECT_EQ(source_edge(m, f), 4);
        break;
      case 2:
        EXPECT_EQ(face_tag(m, f), "block");
        EXPECT_EQ(source_edge(m, f), -1);
        break;
      default:
        ADD_FAILURE() << "face " << f.idx() << " has instance " << i;
    }
  }
}

// OBJ and PLY have no instancing: they get the flattened mesh, which reads
// back as the same closed solid.
TEST(Placement, FlattenedResultsExportToObj) {
  PlacementResult r;
  r.building = std::make_shared<const Mesh>(build_mesh(test::box({0, 0, 0}, {10, 6, 4})));
  const std::size_t dormer = r.add_mesh({"dormer", read("mesh_dormer_box.obj")});
  r.add_instance({dormer, translation(2, 1, 4), "", 1});
  r.add_instance({dormer, translation(6, 1, 4) * glm::scale(glm::dmat4(1.0), {-1, 1, 1}), "", 1});
  const Mesh flat = flatten(r);
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "procex_placement_flat.obj";
  write_obj(file, flat);
  const Mesh back = read_mesh_file(file);
  std::filesystem::remove(file);
  EXPECT_EQ(back.n_faces(), flat.n_faces());
  EXPECT_EQ(back.n_vertices(), flat.n_vertices());
  const ValidationReport v = validate(back);
  EXPECT_TRUE(v.closed && v.manifold && v.oriented) << testing::PrintToString(v.problems);
  EXPECT_NEAR(v.volume, 240 + 2 * 2.496, 1e-9);
}

}  // namespace
}  // namespace procex

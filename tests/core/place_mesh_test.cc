// Placing meshes at resolved anchors of a 10 x 6 m block, 4 m high:
//
//        e2 (facing +y)
//   (0,6) +-----------+ (10,6)
//         |           |
//      e3 |           | e1 (facing +x)
//         |           |
//   (0,0) +-----------+ (10,0)
//        e0 (facing -y)
//
// The anchors are resolved by hand as the sweep would: frames on each wall,
// spans the wall's width at the anchor's height.
#include <filesystem>
#include <memory>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/io/mesh_read.h"
#include "core/mesh/validate.h"
#include "core/placement/box.h"
#include "core/placement/place_mesh.h"
#include "core/placement/placement_error.h"
#include "tests/core/mesh_fixtures.h"

namespace procex {
namespace {

const glm::dvec3 kCorners[4] = {{0, 0, 0}, {10, 0, 0}, {10, 6, 0}, {0, 6, 0}};

// The anchor `name` at height z on every edge, `fraction` along it; absent on `absent_edge`.
std::vector<ResolvedAnchor> resolve(const std::string& name, double z, double fraction, int absent_edge = -1) {
  std::vector<ResolvedAnchor> out;
  for (int e = 0; e < 4; ++e) {
    ResolvedAnchor& a = out.emplace_back();
    a.name = name;
    a.edge_id = e;
    a.present = e != absent_edge;
    if (!a.present) {
      a.reason = "edge gone";
      continue;
    }
    const glm::dvec3 from = kCorners[e] + glm::dvec3(0, 0, z), to = kCorners[(e + 1) % 4] + glm::dvec3(0, 0, z);
    a.frame.along = glm::normalize(to - from);
    a.frame.up = {0, 0, 1};
    a.frame.normal = glm::cross(a.frame.along, a.frame.up);
    a.frame.origin = from + fraction * (to - from);
    a.span_from = from;
    a.span_to = to;
  }
  return out;
}

PlaceableMesh read(const std::string& name) {
  return {name, std::make_shared<const Mesh>(read_mesh_file(std::filesystem::path(PROCEX_TEST_DATA) / ("mesh_" + name + ".obj")))};
}

Box3 instance_bounds(const PlacementResult& r, std::size_t i) {
  PlacementResult one;
  one.add_instance({one.add_mesh(r.meshes[r.instances[i].mesh]), r.instances[i].transform, "", -1});
  return bounds(flatten(one));
}

void expect_near(const glm::dvec3& got, const glm::dvec3& want) {
  EXPECT_LE(glm::length(got - want), 1e-12) << vector_text(got) << " vs " << vector_text(want);
}

TEST(PlaceMesh, RowOfWindowsFittedToTheFacadeLength) {
  PlacementResult r;
  MeshPlacementSpec spec;
  spec.mode = MeshPlacementSpec::Mode::Row;
  spec.anchor = "sill";
  spec.columns.spacing = 2.5;
  spec.fit = true;
  spec.margin = 0.3;
  const PlaceMeshReport report = place_mesh(r, read("window_frame"), resolve("sill", 1, 0.5, 3), spec);
  EXPECT_EQ(report.instances, 4u + 2u + 4u);  // 10 m: 4 cells; 6 m: 2 (2.4 rounds down); e3 absent
  ASSERT_EQ(report.absent.size(), 1u);
  EXPECT_EQ(report.absent[0], "anchor 'sill' on edge 3 is absent: edge gone");
  // The first window of e0 fills its 2.5 m cell less 0.3 m each side, stands on the sill, 0.1 m deep.
  const Box3 b = instance_bounds(r, 0);
  expect_near(b.lo, {0.3, -0.1, 1});
  expect_near(b.hi, {2.2, 0, 2.5});
  EXPECT_EQ(r.instances[4].source_edge, 1);
}

TEST(PlaceMesh, SingleWithPivotAndOffset) {
  PlacementResult r;
  MeshPlacementSpec spec;
  spec.anchor = "sill";
  spec.offset = {0, 0.5, 0};
  spec.tag = "dormer";
  const PlaceMeshReport report = place_mesh(r, read("dormer_box"), resolve("sill", 1, 0.5), spec);
  ASSERT_EQ(report.instances, 4u);
  // e1: origin (10, 3, 1), along +y, out +x. The gable's apex (0, 1.6, 1.2)
  // is 1.6 + 0.5 up and 1.2 out.
  const glm::dvec4 apex = r.instances[1].transform * glm::dvec4(0, 1.6, 1.2, 1);
  expect_near(glm::dvec3(apex), {11.2, 3, 3.1});
  EXPECT_EQ(r.instances[1].tag, "dormer");
}

TEST(PlaceMesh, PillarsStretchFromGroundToEave) {
  std::vector<ResolvedAnchor> anchors = resolve("ground", 0, 0);
  for (const ResolvedAnchor& a : resolve("eave", 4, 0, 2)) anchors.push_back(a);
  PlacementResult r;
  MeshPlacementSpec spec;
  spec.mode = MeshPlacementSpec::Mode::Stretch;
  spec.anchor = "ground";
  spec.top_anchor = "eave";
  const PlaceMeshReport report = place_mesh(r, read("pillar"), anchors, spec);
  EXPECT_EQ(report.instances, 3u);
  ASSERT_EQ(report.absent.size(), 1u);
  EXPECT_NE(report.absent[0].find("edge 2: its top anchor 'eave' is absent there: edge gone"), std::string::npos) << report.absent[0];
  // The pillar on e1 (corner (10, 0)): 3 m stretched to 4 m, its back on the wall.
  const Box3 b = instance_bounds(r, 1);
  expect_near(b.lo, {10, -0.2, 0});
  expect_near(b.hi, {10.4, 0.2, 4});
}

TEST(PlaceMesh, GridOnEveryFacadeFlattensClosed) {
  PlacementResult r;
  r.building = std::make_shared<const Mesh>(build_mesh(test::box({0, 0, 0}, {10, 6, 4})));
  MeshPlacementSpec spec;
  spec.mode = MeshPlacementSpec::Mode::Grid;
  spec.anchor = "sill";
  spec.columns.spacing = 2.5;
  spec.rows.count = 2;
  spec.z_from = 0.25;
  spec.z_to = 3.75;
  spec.pivot = {0.5, 0.5, 0};
  const PlaceMeshReport report = place_mesh(r, read("window_frame"), resolve("sill", 1, 0.5), spec);
  EXPECT_EQ(report.instances, 2u * (4 + 2 + 4 + 2));
  EXPECT_TRUE(report.absent.empty());
  const ValidationReport v = validate(flatten(r), {.tolerance = -1.0, .check_self_intersections = false});
  EXPECT_TRUE(v.closed && v.manifold && v.oriented) << testing::PrintToString(v.problems);
  EXPECT_NEAR(v.volume, 240 + 24 * 0.05, 1e-9);
}

TEST(PlaceMesh, UnknownAnchorsAndBadSpecsNameTheAnchor) {
  PlacementResult r;
  MeshPlacementSpec spec;
  spec.anchor = "lintel";
  try {
    place_mesh(r, read("pillar"), resolve("sill", 1, 0.5), spec);
    FAIL() << "an unknown anchor was accepted";
  } catch (const PlacementError& e) {
    EXPECT_EQ(std::string(e.what()), "no anchor named 'lintel' was resolved (there are 'sill')");
  }
  spec.anchor = "sill";
  spec.mode = MeshPlacementSpec::Mode::Row;  // neither a count nor a spacing
  try {
    place_mesh(r, read("pillar"), resolve("sill", 1, 0.5), spec);
    FAIL() << "a row without count or spacing was accepted";
  } catch (const PlacementError& e) {
    EXPECT_NE(std::string(e.what()).find("anchor 'sill' on edge 0: a repetition needs a count"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(r.meshes.empty() && r.instances.empty());
}

}  // namespace
}  // namespace procex

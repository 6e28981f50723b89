#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/geom/error.h"
#include "core/io/polyjson.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "tests/core/mesh_fixtures.h"
#include "tests/support/data_files.h"

namespace procex {
namespace {

TEST(BuildMesh, CubeKeepsVerticesFacesAndProperties) {
  const Surface s = test::box({0, 0, 0}, {1, 2, 3});
  const Mesh mesh = build_mesh(s);
  ASSERT_EQ(mesh.n_vertices(), 8u);
  ASSERT_EQ(mesh.n_faces(), 6u);
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const auto& p = mesh.point(Mesh::VertexHandle(static_cast<int>(i)));
    EXPECT_EQ(glm::dvec3(p[0], p[1], p[2]), s.vertices[i]);
  }
  int sides = 0;
  for (const auto f : mesh.faces()) {
    EXPECT_EQ(mesh.valence(f), 4u);
    const SurfaceFace& sf = s.faces[f.idx()];
    EXPECT_EQ(face_kind(mesh, f), sf.kind);
    EXPECT_EQ(source_edge(mesh, f), sf.source_edge);
    sides += face_kind(mesh, f) == FaceKind::Side;
  }
  EXPECT_EQ(sides, 4);
  const ValidationReport r = validate(mesh);
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
  EXPECT_NEAR(r.volume, 6.0, 1e-12);
}

// Base and cap of the square ring have a courtyard hole; each becomes a few
// convex pieces over the same 16 vertices.
//
//   +-----------+
//   |  +-----+  |
//   |  |     |  |
//   |  +-----+  |
//   +-----------+
TEST(BuildMesh, SquareRingSplitsFacesWithHolesIntoConvexPieces) {
  const Surface s = test::square_ring();
  const Mesh mesh = build_mesh(s);
  EXPECT_EQ(mesh.n_vertices(), 16u);
  int base = 0, cap = 0;
  for (const auto f : mesh.faces()) {
    if (face_kind(mesh, f) == FaceKind::Base) ++base;
    if (face_kind(mesh, f) == FaceKind::Cap) ++cap;
    if (face_kind(mesh, f) != FaceKind::Side) {
      EXPECT_EQ(source_edge(mesh, f), -1);
    }
  }
  // A ring needs at least 4 convex pieces; Hertel-Mehlhorn keeps it near that.
  EXPECT_GE(base, 4);
  EXPECT_LE(base, 8);
  EXPECT_EQ(base, cap);
  const ValidationReport r = validate(mesh);
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
  EXPECT_NEAR(r.volume, (100.0 - 16.0) * 2.0, 1e-9);
}

// The thresholded-image case: 24 loops nested 6 deep, 13 polygons with holes.
TEST(BuildMesh, NestedContoursExtrudeToAValidSolid) {
  const auto shapes = read_polyjson_file(synthetic_file("b_image_contours"));
  const Surface s = test::extrude(shapes[0].loops, 0.0, 5.0);
  const Mesh mesh = build_mesh(s);
  const ValidationReport r = validate(mesh);
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
  double area = 0.0;
  const LoopNesting nesting = loop_nesting(shapes[0].loops);
  for (const auto& loop : shapes[0].loops) area += 0.5 * twice_signed_area(loop);
  EXPECT_GT(area, 0.0);
  EXPECT_NEAR(r.volume, 5.0 * area, 1e-9 * std::abs(area));
  EXPECT_EQ(*std::max_element(nesting.depth.begin(), nesting.depth.end()), 6);
}

// Every footprint of the synthetic city (828 courtyards, collinear runs)
// extrudes to a closed, valid prism.
TEST(BuildMesh, EveryCityFootprintExtrudesToAValidPrism) {
  const auto shapes = read_polyjson_file(synthetic_file("d_city_6000"));
  ASSERT_EQ(shapes.size(), 6000u);
  int holes = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    holes += static_cast<int>(shapes[i].loops.size()) - 1;
    const Mesh mesh = build_mesh(test::extrude(shapes[i].loops, 0.0, 3.0));
    ValidationOptions options;
    options.check_self_intersections = i % 10 == 0;  // the expensive part, on a tenth
    const ValidationReport r = validate(mesh, options);
    ASSERT_TRUE(r.ok()) << "shape " << i << ": " << ::testing::PrintToString(r.problems);
  }
  EXPECT_EQ(holes, 828);
}

TEST(BuildMesh, RefusedFacesNameFaceKindEdgeAndVertices) {
  Surface s = test::box({0, 0, 0}, {1, 1, 1});
  s.faces.push_back(s.faces[3]);  // the same wall twice
  try {
    build_mesh(s);
    FAIL() << "expected MeshError";
  } catch (const MeshError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("face 6 (side, source edge 1)"), std::string::npos) << what;
    EXPECT_NE(what.find("[1, 2, 6, 5]"), std::string::npos) << what;
  }

  Surface out_of_range = test::box({0, 0, 0}, {1, 1, 1});
  out_of_range.faces[0].loops[0][2] = 99;
  EXPECT_THROW(build_mesh(out_of_range), MeshError);

  Surface too_small = test::box({0, 0, 0}, {1, 1, 1});
  too_small.faces[4].loops[0].resize(2);
  EXPECT_THROW(build_mesh(too_small), MeshError);

  Surface repeated = test::box({0, 0, 0}, {1, 1, 1});
  repeated.faces[2].loops[0][1] = repeated.faces[2].loops[0][0];
  EXPECT_THROW(build_mesh(repeated), MeshError);

  Surface nan = test::box({0, 0, 0}, {1, 1, 1});
  nan.vertices[3].x = NAN;
  EXPECT_THROW(build_mesh(nan), MeshError);
}

}  // namespace
}  // namespace procex

#include "core/mesh/validate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/geom/error.h"
#include "core/geom/footprint.h"
#include "core/sweep/sweep.h"
#include "tests/core/mesh_fixtures.h"

namespace procex {
namespace {

bool mentions(const ValidationReport& r, const std::string& text) {
  for (const auto& p : r.problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST(Validate, ClosedBoxPassesEveryCheck) {
  const ValidationReport r = validate(build_mesh(test::box({0, 0, 0}, {2, 3, 4})));
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
  EXPECT_TRUE(r.closed && r.manifold && r.oriented && r.planar && r.self_intersection_free);
  EXPECT_NEAR(r.volume, 24.0, 1e-12);
  EXPECT_EQ(r.max_planarity_error, 0.0);
  EXPECT_TRUE(r.problems.empty());
}

TEST(Validate, MissingFaceIsNotClosed) {
  Surface s = test::box({0, 0, 0}, {1, 1, 1});
  s.faces.erase(s.faces.begin() + 1);  // the cap
  const ValidationReport r = validate(build_mesh(s));
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.manifold);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(mentions(r, "not closed")) << ::testing::PrintToString(r.problems);
}

// OpenMesh cannot link a flipped face to its neighbours, so a reader gives it
// its own copies of the vertices; validation still sees it through the
// shared positions.
TEST(Validate, FlippedFaceIsNotOriented) {
  Mesh mesh = build_mesh([] {
    Surface s = test::box({0, 0, 0}, {1, 1, 1});
    s.faces.erase(s.faces.begin() + 1);
    return s;
  }());
  std::vector<Mesh::VertexHandle> copies;
  for (int v : {4, 5, 6, 7}) {
    const Mesh::Point p = mesh.point(Mesh::VertexHandle(v));  // a copy: add_vertex may reallocate the points
    copies.push_back(mesh.add_vertex(p));
  }
  std::reverse(copies.begin(), copies.end());
  ASSERT_TRUE(mesh.add_face(copies).is_valid());
  const ValidationReport r = validate(mesh);
  EXPECT_FALSE(r.oriented);
  EXPECT_TRUE(mentions(r, "flipped")) << ::testing::PrintToString(r.problems);
  EXPECT_FALSE(r.ok());
}

TEST(Validate, InsideOutSolidHasNegativeVolume) {
  Surface s = test::box({0, 0, 0}, {1, 1, 1});
  for (auto& f : s.faces) std::reverse(f.loops[0].begin(), f.loops[0].end());
  const ValidationReport r = validate(build_mesh(s));
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_FALSE(r.oriented);
  EXPECT_NEAR(r.volume, -1.0, 1e-12);
  EXPECT_TRUE(mentions(r, "not positive"));
}

TEST(Validate, NonPlanarFaceIsReportedWithItsError) {
  Surface s = test::box({0, 0, 0}, {1, 1, 1});
  s.vertices[6].z = 1.1;  // lifts one corner of the cap: the cap and two walls bend
  const ValidationReport r = validate(build_mesh(s));
  EXPECT_TRUE(r.closed);
  EXPECT_FALSE(r.planar);
  EXPECT_NEAR(r.max_planarity_error, 0.025, 0.01);
  EXPECT_TRUE(mentions(r, "face 1 is off its plane")) << ::testing::PrintToString(r.problems);

  ValidationOptions loose;
  loose.tolerance = 0.1;
  EXPECT_TRUE(validate(build_mesh(s), loose).planar);
}

// A roof is held to ten times the clustering scale it closed at
// (Surface::tolerance_relative), never closer than kMeshDistanceRelative.
TEST(Validate, ARoofIsHeldToTenTimesTheScaleItWasMadeAt) {
  Surface s = test::box({0, 0, 0}, {1, 1, 1});
  const double diagonal = std::sqrt(3.0);
  s.vertices[6].z += 2e-5 * diagonal;  // the cap and two walls off their planes by about a quarter of that
  const auto planar_made_at = [&s](double made) {
    s.tolerance_relative = made;
    return validate(build_mesh(s), roof_validation(s)).planar;
  };
  EXPECT_FALSE(planar_made_at(0.0));
  EXPECT_FALSE(planar_made_at(1e-8));
  EXPECT_FALSE(planar_made_at(1e-7));
  EXPECT_TRUE(planar_made_at(1e-6));
  EXPECT_TRUE(planar_made_at(1e-5));
}

TEST(Validate, OverlappingBoxesIntersect) {
  const Surface s = test::combine(test::box({0, 0, 0}, {2, 2, 2}), test::box({1, 1, 1}, {3, 3, 3}));
  const ValidationReport r = validate(build_mesh(s));
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_FALSE(r.self_intersection_free);
  EXPECT_TRUE(mentions(r, "intersect")) << ::testing::PrintToString(r.problems);

  ValidationOptions skip;
  skip.check_self_intersections = false;
  EXPECT_TRUE(validate(build_mesh(s), skip).ok());
}

TEST(Validate, CoplanarOverlapIntersects) {
  // Two boxes on the same floor, overlapping: their bases lie in one plane.
  const Surface s = test::combine(test::box({0, 0, 0}, {2, 2, 1}), test::box({1, 1, 0}, {3, 3, 0.5}));
  EXPECT_FALSE(validate(build_mesh(s)).self_intersection_free);
}

// A double cone over n points of a circle, joined in steps of `winding`
// points (n odd): over a pentagram (5, 2) its rim winds twice round the axis,
// so the surface is closed, 2-manifold (one fan round every vertex), planar
// and of positive volume, yet each face passes through others along a
// segment from the apex they share. Every crossing pair shares a vertex.
Surface bipyramid(int n, int winding) {
  Surface s;
  s.vertices.push_back({0, 0, 1});   // apex above
  s.vertices.push_back({0, 0, -1});  // apex below
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * (winding * k % n) / n;
    s.vertices.push_back({std::cos(a), std::sin(a), 0.0});
  }
  for (int k = 0; k < n; ++k) {
    const auto p = static_cast<std::uint32_t>(2 + k), q = static_cast<std::uint32_t>(2 + (k + 1) % n);
    s.faces.push_back({FaceKind::Side, k, {{0, p, q}}, {}});
    s.faces.push_back({FaceKind::Side, k, {{1, q, p}}, {}});
  }
  return s;
}

Surface pentagram_bipyramid() { return bipyramid(5, 2); }

TEST(Validate, FoldThroughASharedVertexIntersects) {
  const ValidationReport r = validate(build_mesh(pentagram_bipyramid()));
  EXPECT_TRUE(r.closed && r.manifold && r.planar) << ::testing::PrintToString(r.problems);
  EXPECT_GT(r.volume, 0.0);
  EXPECT_FALSE(r.self_intersection_free);
  EXPECT_TRUE(mentions(r, "intersect")) << ::testing::PrintToString(r.problems);
  EXPECT_FALSE(r.ok());
}

// The same double cone over a pentagon (winding once) is valid: faces that
// share an apex meet only there or along their common edge.
TEST(Validate, ConvexFanRoundASharedVertexIsValid) {
  Surface s = pentagram_bipyramid();
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 5.0;
    s.vertices[2 + k] = {std::cos(a), std::sin(a), 0.0};
  }
  const ValidationReport r = validate(build_mesh(s));
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
}

TEST(Validate, SeparateAndTouchingBoxesDoNotIntersect) {
  EXPECT_TRUE(validate(build_mesh(test::combine(test::box({0, 0, 0}, {1, 1, 1}), test::box({2, 0, 0}, {3, 1, 1})))).ok());
  // Face to face contact is not an intersection.
  const ValidationReport touching =
      validate(build_mesh(test::combine(test::box({0, 0, 0}, {1, 1, 1}), test::box({1, 0.25, 0.25}, {2, 0.75, 0.75}))));
  EXPECT_TRUE(touching.self_intersection_free) << ::testing::PrintToString(touching.problems);
}

// A tetrahedron on vertices a, b, c, d, its faces wound consistently.
Surface tetrahedron(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
  Surface s;
  s.vertices = {a, b, c, d};
  for (const std::vector<std::uint32_t>& f : {std::vector<std::uint32_t>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}})
    s.faces.push_back({FaceKind::Side, 0, {f}, {}});
  return s;
}

// Two solids whose faces each pass through the other's plane, a face of one
// (in y = 0) meeting the plane z = 0 from x = 10 to 11.6 and a face of the
// other (in z = 0) meeting y = 0 from x = 11.8: they do not meet. The first
// face's tip lies within the tolerance of z = 0 at x = 12, and taking it as
// where the face meets that plane (what the check did) made the two overlap
// by 0.2 (a 176-vertex jittered star's roof was reported so, its faces 0.74 mm
// apart where their planes met).
TEST(Validate, FacesThatCrossEachOthersPlanesApartDoNotIntersect) {
  const double tol = 2e-5;  // the crossings are tens of thousands of it apart
  ValidationOptions options;
  options.tolerance = tol;
  const Surface near_tip = tetrahedron({0, 0, 1}, {10, 0, -2 * tol}, {12, 0, 0.5 * tol}, {6, -3, 0});
  const Surface wedge = tetrahedron({11.8, 0, 0}, {20, 5, 0}, {20, -5, 0}, {16, 0, -3});
  const ValidationReport apart = validate(build_mesh(test::combine(near_tip, wedge)), options);
  EXPECT_TRUE(apart.closed && apart.self_intersection_free) << ::testing::PrintToString(apart.problems);
  // Moved 0.4 further, the second face reaches x = 11.4: now they cross.
  const Surface deeper = tetrahedron({11.4, 0, 0}, {20, 5, 0}, {20, -5, 0}, {16, 0, -3});
  const ValidationReport crossing = validate(build_mesh(test::combine(near_tip, deeper)), options);
  EXPECT_FALSE(crossing.self_intersection_free);
}

// OpenMesh cannot close a mesh around a vertex joining two fans (build_mesh
// refuses it), but an open one can have such a vertex: two triangles sharing
// only vertex 0.
TEST(Validate, VertexJoiningTwoFansIsNotManifold) {
  Mesh mesh;
  std::vector<Mesh::VertexHandle> v;
  for (const auto& p : {Mesh::Point(0, 0, 0), Mesh::Point(1, 0, 0), Mesh::Point(0, 1, 0), Mesh::Point(-1, 0, 0),
                        Mesh::Point(0, -1, 0)})
    v.push_back(mesh.add_vertex(p));
  ASSERT_TRUE(mesh.add_face(v[0], v[1], v[2]).is_valid());
  ASSERT_TRUE(mesh.add_face(v[0], v[3], v[4]).is_valid());
  const ValidationReport r = validate(mesh);
  EXPECT_FALSE(r.manifold);
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(mentions(r, "vertex 0 joins several separate fans")) << ::testing::PrintToString(r.problems);

  // Closing both boxes around a shared corner is refused when building.
  Surface s = test::combine(test::box({0, 0, 0}, {1, 1, 1}), test::box({1, 1, 1}, {2, 2, 2}));
  for (auto& f : s.faces)
    for (auto& loop : f.loops)
      for (auto& id : loop)
        if (id == 8) id = 6;
  EXPECT_THROW(build_mesh(s), MeshError);
}

// Three triangles hinged on one edge (a book of three pages). OpenMesh cannot
// link a third face to an edge, so the third page has its own copies of the
// hinge; welded, the edge has three faces.
TEST(Validate, AnEdgeOfThreeFacesIsNotManifold) {
  Mesh mesh;
  const auto add = [&](const Mesh::Point& p) { return mesh.add_vertex(p); };
  const auto a = add({0, 0, 0}), b = add({0, 0, 1}), c = a, d = b;
  ASSERT_TRUE(mesh.add_face(a, b, add({1, 0, 0})).is_valid());
  ASSERT_TRUE(mesh.add_face(d, c, add({0, 1, 0})).is_valid());
  ASSERT_TRUE(mesh.add_face(add({0, 0, 0}), add({0, 0, 1}), add({-1, -1, 0})).is_valid());
  const ValidationReport r = validate(mesh);
  EXPECT_FALSE(r.manifold);
  EXPECT_TRUE(mentions(r, "has 3 faces")) << ::testing::PrintToString(r.problems);
}

// Welded ids name each position by the order of its first vertex, and
// positions are equal as numbers (-0.0 is 0.0), as when they were looked up in
// a hash map: a box whose cap is flipped, the cap's corners copies of the
// walls' written with -0.0 where the walls have 0.0, and a third page hinged
// on a wall's edge through copies too. The problems are main's at 1272093.
TEST(Validate, WeldedVerticesAreNamedInTheOrderOfTheirFirstCopy) {
  Surface s = test::box({0, 0, 0}, {1, 1, 1});
  s.faces.erase(s.faces.begin() + 1);
  Mesh mesh = build_mesh(s);
  std::vector<Mesh::VertexHandle> copies;
  for (int v : {4, 5, 6, 7}) {
    Mesh::Point p = mesh.point(Mesh::VertexHandle(v));  // a copy: add_vertex may reallocate the points
    for (int k = 0; k < 3; ++k)
      if (p[k] == 0.0) p[k] = -0.0;
    copies.push_back(mesh.add_vertex(p));
  }
  std::reverse(copies.begin(), copies.end());
  ASSERT_TRUE(mesh.add_face(copies).is_valid());
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({-0.0, 0, 1});
  ASSERT_TRUE(mesh.add_face(a, b, mesh.add_vertex({-1, -1, 0.5})).is_valid());
  const ValidationReport r = validate(mesh);
  const std::vector<std::string> welded(r.problems.end() - 6, r.problems.end());
  EXPECT_EQ(welded, (std::vector<std::string>{
                        "edge between welded vertices 0 and 4 has 3 faces",
                        "faces 4 and 6 both run along the edge from welded vertex 0 to 4: one of them is flipped",
                        "faces 4 and 5 both run along the edge from welded vertex 4 to 7: one of them is flipped",
                        "faces 1 and 5 both run along the edge from welded vertex 5 to 4: one of them is flipped",
                        "faces 2 and 5 both run along the edge from welded vertex 6 to 5: one of them is flipped",
                        "faces 3 and 5 both run along the edge from welded vertex 7 to 6: one of them is flipped"}));
  EXPECT_EQ(r.problems.size(), 17u) << ::testing::PrintToString(r.problems);
}

// Two boxes touching along an edge, each with its own copies of the edge's
// ends (as the sweep gives two parts of a solid touching along a line):
// welded, the edge has four faces, two each way, alternating round it, so the
// surface is a closed 2-manifold of positive volume. A box inside the
// other's corner has its faces leave the edge the same way as the other's:
// they overlap, and welded the edge is not manifold.
TEST(Validate, BoxesTouchingAlongAnEdgeAreOneSolidUnlessTheyOverlap) {
  const ValidationReport touching =
      validate(build_mesh(test::combine(test::box({0, 0, 0}, {1, 1, 1}), test::box({1, 1, 0}, {2, 2, 1}))));
  EXPECT_TRUE(touching.ok()) << ::testing::PrintToString(touching.problems);
  EXPECT_DOUBLE_EQ(touching.volume, 2.0);

  const ValidationReport inside =
      validate(build_mesh(test::combine(test::box({0, 0, 0}, {1, 1, 1}), test::box({0.5, 0.5, 0}, {1, 1, 1}))));
  EXPECT_FALSE(inside.manifold);
  EXPECT_TRUE(mentions(inside, "has 4 faces")) << ::testing::PrintToString(inside.problems);
}

// A 4096-sided prism: 4098 faces, one of them with 4096 vertices.
TEST(Validate, LargeRegularPrismIsValid) {
  std::vector<glm::dvec2> circle;
  for (int k = 0; k < 4096; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 4096.0;
    circle.push_back({100.0 * std::cos(t), 100.0 * std::sin(t)});
  }
  const ValidationReport r = validate(build_mesh(test::extrude({circle}, 0.0, 10.0)));
  EXPECT_TRUE(r.ok()) << ::testing::PrintToString(r.problems);
}

// A fan too large to test pair by pair (65 faces round each apex) is tested
// round its apex: winding once it is valid, twice its faces pass through each
// other from the apex.
TEST(Validate, LargeFanRoundASharedVertex) {
  const ValidationReport once = validate(build_mesh(bipyramid(65, 1)));
  EXPECT_TRUE(once.ok()) << ::testing::PrintToString(once.problems);
  const ValidationReport twice = validate(build_mesh(bipyramid(65, 2)));
  EXPECT_TRUE(twice.closed && twice.manifold && twice.planar) << ::testing::PrintToString(twice.problems);
  EXPECT_FALSE(twice.self_intersection_free);
  EXPECT_TRUE(mentions(twice, "intersect")) << ::testing::PrintToString(twice.problems);
}

// The roof at 45 degrees over a regular n-gon, swept: n triangles meet at
// the apex, so the box of each holds it and every two boxes overlap; its base
// is split into triangles fanned from one corner.
Mesh regular_roof(int n) {
  std::vector<glm::dvec2> ring;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * std::numbers::pi * k / n;
    ring.push_back({100.0 * std::cos(a), 100.0 * std::sin(a)});
  }
  return build_mesh(sweep(make_footprint({ring}, 45.0)));
}

// The search's work, counted rather than timed: roofs over 1,024 and 8,192
// sides both validate, and the larger costs less than `most` times the pairs
// (searched although proven apart over their bases: height_field.h).
void expect_pairs_grow_less_than(Mesh (*roof)(int), std::size_t most) {
  const ValidationReport small = validate(roof(1024), {.search_proven_pairs = true});
  const ValidationReport large = validate(roof(8192), {.search_proven_pairs = true});
  EXPECT_TRUE(small.ok()) << ::testing::PrintToString(small.problems);
  EXPECT_TRUE(large.ok()) << ::testing::PrintToString(large.problems);
  EXPECT_GT(small.triangle_pairs_tested, 1024u);
  EXPECT_LT(large.triangle_pairs_tested, most * small.triangle_pairs_tested)
      << small.triangle_pairs_tested << " pairs at 1024 sides, " << large.triangle_pairs_tested << " at 8192";
}

// 8 times the sides may cost about 8 log 8k / log 1k (10.4) times the pairs,
// not 64 (every pair of sides).
TEST(Validate, PairsTestedRoundAnApexGrowAsNLogN) { expect_pairs_grow_less_than(regular_roof, 16); }

// The roof at 45 degrees over a spiky plan, whose slivers' axis-aligned
// boxes overlap by the thousand.
Mesh spiky_roof(int n) {
  return build_mesh(sweep(make_footprint({test::spiky_plan(n, static_cast<std::uint64_t>(n))}, 45.0)));
}

// Boxes turned along the slivers part them, and bundles of slivers are split
// across: 8 times the corners may cost 14 times the pairs (measured: 10.8;
// 20 with bundles split only along the axes, 52 without turned boxes).
TEST(Validate, PairsTestedAmongSliversGrowNearlyLinearly) { expect_pairs_grow_less_than(spiky_roof, 14); }

}  // namespace
}  // namespace procex

// The sweep against an oracle over every real and synthetic footprint: with
// every edge at 45 degrees a procedural extrusion is the roof of the straight
// skeleton, so CGAL 5.5's create_interior_straight_skeleton_2 (exact
// constructions; inexact ones above kExactOracleVertices) fixes its topology
// and its vertices. Compared
// (tests/support/skeleton_oracle.h): the mesh validates, one roof face per
// footprint edge, the same pairs of edges meeting along ridges, and every
// skeleton node a roof vertex at the height of its time and back.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/io/polyjson.h"
#include "core/sweep/sweep.h"
#include "tests/support/cgal_skeleton.h"
#include "tests/support/sanitizers.h"
#include "tests/support/data_files.h"
#include "tests/support/generators/size_plans.h"
#include "tests/support/point_set.h"
#include "tests/support/roof_properties.h"
#include "tests/support/skeleton_oracle.h"
#include "tests/support/tangential_skeleton.h"

namespace procex {
namespace {

using testing::compare_with_cgal;
using testing::sweep_and_compare_with_cgal;

// Under the sanitizers (a Debug build, tens of times slower) every
// kSanitizedStride-th footprint of the large sets is compared.
constexpr std::size_t kSanitizedStride = kSanitized ? 40 : 1;

// ---- the oracle itself must be right, or the comparisons mean nothing ----

TEST(CgalOracle, SquareHasItsCentreAtHalfTheSide) {
  const Footprint square = make_footprint({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, 45.0);
  const CgalSkeleton ss = CgalSkeletonInput(square).skeleton();
  ASSERT_FALSE(ss.nodes.empty());
  for (const glm::dvec3& n : ss.nodes) {
    EXPECT_NEAR(n.x, 2.0, 1e-12);
    EXPECT_NEAR(n.y, 2.0, 1e-12);
    EXPECT_NEAR(n.z, 2.0, 1e-12);
  }
  // Four hips, no ridge between opposite sides: they meet only at the centre.
  const std::vector<std::pair<std::int32_t, std::int32_t>> expected{{0, 1}, {0, 3}, {1, 2}, {2, 3}};
  EXPECT_EQ(ridges_longer_than(ss, 1e-9), expected);
  ASSERT_EQ(ss.faces_per_edge.size(), 4u);
  for (const auto& [id, n] : ss.faces_per_edge) EXPECT_EQ(n, 1u) << "edge " << id;
}

//   +-----------+
//   |           |   a 10 x 4 rectangle: the ridge runs from (2, 2) to (8, 2)
//   +-----------+   at height 2 (half the width), between edges 0 and 2
TEST(CgalOracle, RectangleRidge) {
  const Footprint rect = make_footprint({{{0, 0}, {10, 0}, {10, 4}, {0, 4}}}, 45.0);
  CgalSkeleton ss = CgalSkeletonInput(rect).skeleton();
  std::sort(ss.nodes.begin(), ss.nodes.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  ASSERT_EQ(ss.nodes.size(), 2u);
  EXPECT_NEAR(glm::distance(ss.nodes[0], glm::dvec3(2, 2, 2)), 0.0, 1e-12);
  EXPECT_NEAR(glm::distance(ss.nodes[1], glm::dvec3(8, 2, 2)), 0.0, 1e-12);
  // The hips join every side to both ends, the ridge joins the long sides.
  const std::vector<std::pair<std::int32_t, std::int32_t>> expected{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}};
  EXPECT_EQ(ridges_longer_than(ss, 1e-9), expected);
}

// An island inside a hole is its own polygon; the hole belongs to the outer loop.
//   +---------------+
//   |  +---------+  |
//   |  |  +---+  |  |
//   |  |  +---+  |  |
//   |  +---------+  |
//   +---------------+
TEST(CgalOracle, SplitsNestedLoopsIntoPolygonsWithHoles) {
  const Footprint fp = make_footprint({{{0, 0}, {30, 0}, {30, 30}, {0, 30}},
                                       {{5, 5}, {5, 25}, {25, 25}, {25, 5}},
                                       {{12, 12}, {18, 12}, {18, 18}, {12, 18}}},
                                      45.0);
  const CgalSkeletonInput input(fp);
  EXPECT_EQ(input.polygon_count(), 2u);
  // The frame between outer and hole is 5 wide: its nodes stand at most 2.5 high.
  // The 6 x 6 island peaks at 3.
  double highest = 0.0;
  for (const glm::dvec3& n : input.skeleton().nodes) highest = std::max(highest, n.z);
  EXPECT_NEAR(highest, 3.0, 1e-12);
}

// A regular polygon's and a star's skeleton in closed form (one node at the
// centre, a bisector from every corner) is CGAL's, node, ridges and faces.
TEST(CgalOracle, ATangentialPlansClosedFormIsCgalsSkeleton) {
  for (const testing::NamedPlan& plan :
       {testing::regular_polygon(12, 10.0), testing::star(40, 10.0, 6.0), testing::regular_polygon(4, 3.0)}) {
    const Footprint fp = prepare_footprint(make_footprint(plan.loops, 45.0)).footprint;
    const std::optional<CgalSkeleton> closed = testing::tangential_skeleton(fp);
    ASSERT_TRUE(closed) << plan.name;
    const CgalSkeleton cgal = CgalSkeletonInput(fp).skeleton();
    ASSERT_EQ(closed->nodes.size(), 1u);
    ASSERT_FALSE(cgal.nodes.empty());
    for (const glm::dvec3& n : cgal.nodes) EXPECT_NEAR(glm::distance(n, closed->nodes[0]), 0.0, 1e-9) << plan.name;
    EXPECT_EQ(ridges_longer_than(*closed, 1e-9), ridges_longer_than(cgal, 1e-9)) << plan.name;
    EXPECT_EQ(closed->faces_per_edge, cgal.faces_per_edge) << plan.name;
  }
}

// A plan whose edges are not all at one distance from its centre has none:
// a rectangle, a random star-shaped plan, a star with its radii moved by a
// millimetre, a square with a hole.
TEST(CgalOracle, OnlyATangentialPlanHasAClosedForm) {
  std::mt19937_64 rng(7);
  const std::vector<std::vector<std::vector<glm::dvec2>>> plans{
      {{{0, 0}, {10, 0}, {10, 4}, {0, 4}}},
      testing::random_star_shaped(50, 10.0, rng).loops,
      testing::jittered_star(40, 100.0, 90.0, 1e-3, rng).loops,
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
  for (const auto& loops : plans) {
    const Footprint fp = prepare_footprint(make_footprint(loops, 45.0)).footprint;
    EXPECT_FALSE(testing::tangential_skeleton(fp)) << loops[0].size() << " vertices";
  }
}

// Not the sweep's output but roofs with one misplaced node or one wrong
// face: the comparison must report them, or a passing oracle test proves nothing.
TEST(CgalOracle, ComparisonNoticesAWrongRoof) {
  const Footprint rect = make_footprint({{{0, 0}, {10, 0}, {10, 4}, {0, 4}}}, 45.0);
  const Surface right = sweep(rect);
  ASSERT_TRUE(compare_with_cgal(rect, right).empty());

  Surface raised = right;
  for (glm::dvec3& v : raised.vertices)
    if (v.z > 1.0) v.z += 1e-3;
  EXPECT_FALSE(compare_with_cgal(rect, raised).empty());

  // The same vertices, but one end face's source edge named as the other's:
  // two faces for one edge, none for another, ridges between the wrong edges.
  Surface renamed = right;
  for (SurfaceFace& f : renamed.faces)
    if (f.kind == FaceKind::Side && f.source_edge == 1) f.source_edge = 3;
  EXPECT_FALSE(compare_with_cgal(rect, renamed).empty());
}

// check_case hands the oracle the roof it swept: compared as it is where
// CGAL's plan is the footprint itself and the options change no roof, and
// otherwise CGAL's plan is swept. A wrong roof handed in shows which.
TEST(CgalOracle, ARoofHandedInIsComparedOnlyWhereItIsCgalsPlansRoof) {
  const Footprint rect = make_footprint({{{0, 0}, {10, 0}, {10, 4}, {0, 4}}}, 45.0);
  Surface raised = sweep(rect);
  for (glm::dvec3& v : raised.vertices)
    if (v.z > 1.0) v.z += 1e-3;
  EXPECT_FALSE(sweep_and_compare_with_cgal(rect, {}, raised).empty());
  // A straight vertex, which CGAL's plan drops: that plan is swept.
  const Footprint straight = make_footprint({{{0, 0}, {5, 0}, {10, 0}, {10, 4}, {0, 4}}}, 45.0);
  for (const std::string& line : sweep_and_compare_with_cgal(straight, {}, raised)) ADD_FAILURE() << line;
  // Options of its own, whatever they are, mean CGAL's plan is swept again: a
  // cap, the ambiguity rule or an edit change the roof, a budget may close
  // another scale than sweep()'s, and anchors are taken as any other option.
  std::vector<SweepOptions> own(7);
  own[0].budget.max_seconds = 1000.0;
  own[1].budget.max_vertices = 1000;
  own[2].budget.max_events = 1000;
  own[3].max_height = 100.0;
  own[4].ambiguity = Ambiguity::MinimizeVolume;
  own[5].anchors.emplace_back().name = "door";
  own[6].plan_edits.emplace_back().name = "bay";
  for (const SweepOptions& options : own)
    for (const std::string& line : sweep_and_compare_with_cgal(rect, options, raised)) ADD_FAILURE() << line;
}

// Nodes match within the tolerance at either end, so a ridge's length may
// differ by up to twice the tolerance between roof and CGAL. A 4 x (4 + d)
// rectangle has a ridge d long; the square's hip roof, moved to stand midway,
// has its apex within d / 2 of both ends. For d of 1.5 tolerances, the roof
// without that ridge is as right as rounding can tell (grid seed 95959's
// neighbours: a CGAL ridge 1.06 tolerances long, a roof edge just short of
// one); for d of 100, the missing ridge is named.
TEST(CgalOracle, ARidgeOnlyAsLongAsTheTolerancesReachMayBeMissing) {
  for (const double tolerances : {1.5, 100.0}) {
    const Footprint square = make_footprint({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, 45.0);
    const double d = tolerances * testing::roof_tolerance(square);
    const Footprint rect = make_footprint({{{0, 0}, {4, 0}, {4, 4 + d}, {0, 4 + d}}}, 45.0);
    Surface apex = sweep(square);
    for (glm::dvec3& v : apex.vertices) v.y += d / 2;
    bool named = false;
    for (const std::string& p : compare_with_cgal(rect, apex))
      named = named || p.find("share a bisector, the roof's faces meet in no ridge") != std::string::npos;
    EXPECT_EQ(named, tolerances > 3.0) << tolerances << " tolerances";
    if (tolerances < 3.0) {
      EXPECT_TRUE(compare_with_cgal(rect, apex).empty());
    }
  }
}

// CGAL builds the skeleton of a plan far from the origin differently from
// the skeleton of the same plan at the origin (nodes metres apart at a
// rotated grid plan's coincident events, even with exact constructions), so
// the oracle moves the plan near the origin first. Moving it back must give
// the same nodes, and the same pairs of edges meeting, wherever it stands.
TEST(CgalOracle, APlanGivesTheSameSkeletonWhereverItStands) {
  // A rotated polyomino outline at (1e9, -1e9) (generated grid seed 9, minimised).
  const GeoJsonCollection read = read_geojson_file(std::string(PROCEX_TEST_DATA) + "/generated_grid_9_far.geojson");
  ASSERT_EQ(read.features.size(), 1u);
  const Footprint far = prepare_footprint(to_footprint(read.features[0], 45.0)).footprint;
  // The same plan near the origin: the move is exact (Sterbenz), so this is
  // the plan itself, not a neighbour.
  const glm::dvec2 by{999999980.0, -1e9};
  Footprint here = far;
  for (Loop& loop : here.loops)
    for (glm::dvec2& p : loop.points) p -= by;
  const CgalSkeleton there = CgalSkeletonInput(far).skeleton();
  const CgalSkeleton exact = CgalSkeletonInput(here).skeleton();
  ASSERT_EQ(there.nodes.size(), exact.nodes.size());
  EXPECT_EQ(ridges_longer_than(there, 1e-6), ridges_longer_than(exact, 1e-6));
  for (const glm::dvec3& n : exact.nodes) {
    double nearest = 1e300;
    for (const glm::dvec3& m : there.nodes) nearest = std::min(nearest, glm::distance(n + glm::dvec3(by, 0.0), m));
    EXPECT_LT(nearest, 1e-5) << "node (" << n.x << ", " << n.y << ", " << n.z << ")";
  }
}

// Events that coincide exactly (here two reflex corners meeting head-on while
// two collinear edges' coplanar faces close a third): CGAL and the sweep put
// the seam between the coplanar faces in different places, so nodes and
// ridges differ, but the surface is the same. The oracle then asks that the
// roof be the limit of generic neighbours that agree with CGAL in full.
TEST(CgalOracle, ExactCoincidencesAreJudgedByTheirGenericNeighbours) {
  const Footprint fp = make_footprint({{{1.4, 14.1}, {-4.2, 14.1}, {-3.5, 13.4}, {-4.9, 12}, {-2.8, 12.7}, {-1.4, 11.3}}}, 45.0);
  const Surface roof = sweep(fp);
  EXPECT_FALSE(compare_with_cgal(fp, roof).empty());  // a seam elsewhere than CGAL's
  for (const std::string& line : sweep_and_compare_with_cgal(fp)) ADD_FAILURE() << line;
  // A neighbour's roof is within the move of this one; a raised one is not.
  const Footprint near = make_footprint({{{1.4, 14.1}, {-4.2, 14.1001}, {-3.5, 13.4}, {-4.9, 12}, {-2.8, 12.7}, {-1.4, 11.3}}}, 45.0);
  EXPECT_LT(testing::largest_height_difference(roof, sweep(near), 4000, 1), 3e-4);
  Surface raised = roof;
  for (glm::dvec3& v : raised.vertices)
    if (v.z > 0.3) v.z += 1e-2;
  EXPECT_GT(testing::largest_height_difference(roof, raised, 4000, 1), 5e-3);
}

// The bottom of a narrow notch (both its corners reflex) has a face far wider
// than itself: tilting that 1 m edge by moving its ends 0.2 mm apart moves its
// face 7 m to the side by about 1.5 mm, more than compare_with_generic_neighbours
// allows for a neighbour's moved ends. Divided by the lever of each point the
// difference is within it, and a roof raised by 1 cm still is not.
TEST(CgalOracle, AWideFaceOfAShortEdgeMovesByItsLever) {
  const auto u_plan = [](double tilt) {
    return make_footprint({{{0, 0}, {30, 0}, {30, 24}, {15.5, 24}, {15.5, 20 + tilt}, {14.5, 20 - tilt}, {14.5, 24}, {0, 24}}}, 45.0);
  };
  const Footprint fp = u_plan(0.0), near = u_plan(1e-4);
  const Surface roof = sweep(fp), moved = sweep(near);
  const double allowed = 4.0 * 1e-4 * (1.0 + 1.0);  // 4 delta (1 + rise), as for a neighbour moved by 1e-4 at 45 degrees
  EXPECT_GT(testing::largest_height_difference(roof, moved, 4000, 1), allowed);
  EXPECT_LT(testing::largest_levered_height_difference(fp, roof, moved, 4000, 1), allowed);
  Surface raised = roof;
  for (glm::dvec3& v : raised.vertices)
    if (v.z > 0.3) v.z += 1e-2;
  EXPECT_GT(testing::largest_levered_height_difference(fp, roof, raised, 4000, 1), 5e-3);
}

// Above kExactOracleVertices the oracle builds CGAL's skeleton with inexact
// constructions. The tolerance it is then held to is the comparison's own
// (roof_tolerance, 1e-6 of the diagonal): on the plans of the size class, at a
// size the exact kernel still builds, the inexact nodes are the exact ones
// within a far smaller distance, and the same pairs of edges meet.
TEST(CgalOracle, TheInexactKernelsNodesAreTheExactOnesWithinTheTolerance) {
  std::mt19937_64 rng(7);
  for (const testing::NamedPlan& plan : {testing::star(200, 50.0, 31.0), testing::random_star_shaped(200, 50.0, rng)}) {
    const Footprint fp = make_footprint(plan.loops, 45.0);
    const double tol = testing::roof_tolerance(fp);
    const CgalSkeletonInput input(fp);
    const CgalSkeleton exact = input.skeleton(), inexact = input.skeleton(CgalConstructions::Inexact);
    EXPECT_EQ(ridges_longer_than(inexact, tol), ridges_longer_than(exact, tol)) << plan.name;
    EXPECT_EQ(inexact.faces_per_edge, exact.faces_per_edge) << plan.name;
    const testing::PointSet exact_nodes(exact.nodes), inexact_nodes(inexact.nodes);
    double worst = 0.0;
    for (const glm::dvec3& n : inexact.nodes) worst = std::max(worst, exact_nodes.nearest(n, tol));
    for (const glm::dvec3& n : exact.nodes) worst = std::max(worst, inexact_nodes.nearest(n, tol));
    EXPECT_LT(worst, 1e-3 * tol) << plan.name;
  }
}

// The child building the skeleton has a memory cap; a plan that needs more is
// a CgalOutOfMemory naming the cap, not a crash, and the oracle reports it as
// a problem with the plan's comparison.
TEST(CgalOracle, ASkeletonOverItsMemoryCapIsReportedAsSuch) {
  if (kSanitized) GTEST_SKIP() << "no memory cap under AddressSanitizer (cap_memory in tests/support/cgal_skeleton.cc)";
  const Footprint fp = make_footprint(testing::star(2000, 50.0, 31.0).loops, 45.0);
  try {
    CgalSkeletonInput(fp).skeleton(CgalConstructions::Exact, std::size_t{1} << 20);
    ADD_FAILURE() << "a skeleton of 2,000 vertices was built in 1 MB";
  } catch (const CgalOutOfMemory& e) {
    EXPECT_NE(std::string(e.what()).find("cap of 1 MB"), std::string::npos) << e.what();
  }
}

// The child building the skeleton has a CPU-time cap too; a skeleton that
// takes longer is a CgalNoSkeleton naming the cap, which the oracle weighs
// like a crash (by the plan's generic neighbours). CGAL's exact kernel takes
// seconds for a star of 2,000 vertices (its inexact one about 4 s, BENCHMARKS).
TEST(CgalOracle, ASkeletonPastItsTimeCapIsReportedAsSuch) {
  const Footprint fp = make_footprint(testing::star(2000, 50.0, 31.0).loops, 45.0);
  try {
    CgalSkeletonInput(fp).skeleton(CgalConstructions::Exact, kCgalChildMemory, 1);
    ADD_FAILURE() << "a skeleton of 2,000 vertices was built in one CPU second";
  } catch (const CgalNoSkeleton& e) {
    EXPECT_NE(std::string(e.what()).find("cap of 1 CPU seconds"), std::string::npos) << e.what();
  }
}

// CGAL 5.5.1 loops for ever on this polyomino turned by 45 degrees (generated
// grid seed 6912, minimised; CGAL issue 7470) with either kernel, or returns
// no skeleton: which, depends on the test binary (its heap's layout, as with
// CGAL issue 7203; AddressSanitizer finds a use after free in
// MergeCoincidentNodes). Either way the oracle answers within its cap, where
// it used to hang the test run.
TEST(CgalOracle, APlanCgalLoopsOnEndsWithinTheCap) {
  const GeoJsonCollection read = read_geojson_file(std::string(PROCEX_TEST_DATA) + "/cgal_loops_grid_6912.geojson");
  ASSERT_EQ(read.features.size(), 1u);
  const Footprint fp = to_footprint(read.features[0], 60.0);
  for (const CgalConstructions kernel : {CgalConstructions::Exact, CgalConstructions::Inexact})
    EXPECT_THROW(CgalSkeletonInput(fp).skeleton(kernel, kCgalChildMemory, 1), CgalNoSkeleton);
}

// ---- synthetic cases (shared/data/synthetic, see its README) ----

std::vector<std::string> synthetic_cases() {
  // Every single shape: a_* (regular polygons up to 4096), b, c_*, e_*; the
  // collection d_city_6000 has its own test below.
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(synthetic_file("x").parent_path())) {
    const std::string stem = e.path().stem().string();
    if (e.path().extension() == ".json" && stem.size() > 2 && stem[1] == '_' && stem[0] != 'd') names.push_back(stem);
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(SweepOracleData, SyntheticCasesArePresent) {
  // 5 circles + b + 14 c_* + 12 e_* in data/synthetic/ (manifest.json).
  EXPECT_EQ(synthetic_cases().size(), 32u);
}

class SweepOracleSynthetic : public ::testing::TestWithParam<std::string> {};

TEST_P(SweepOracleSynthetic, MatchesCgalSkeleton) {
  const std::vector<PolyShape> shapes = read_polyjson_file(synthetic_file(GetParam()));
  ASSERT_EQ(shapes.size(), 1u);
  const PreparedFootprint prepared = prepare_footprint(to_footprint(shapes[0], 45.0));
  for (const std::string& line : sweep_and_compare_with_cgal(prepared.footprint))
    ADD_FAILURE() << GetParam() << ": " << line;
}

INSTANTIATE_TEST_SUITE_P(Synthetic, SweepOracleSynthetic, ::testing::ValuesIn(synthetic_cases()),
                         [](const auto& info) { return info.param; });

// The 6000 generated city blocks (rotated, bevelled, with courtyards): every
// kCityStride-th one, in kCityParts parts so that ctest runs them side by
// side. All 6000 do not agree yet (shape 1: a node 4 mm off CGAL's and a
// missing ridge, with the sweep of 7887b95); the full set waits on branch
// generators for the engine.
constexpr std::size_t kCityBlocks = 6000, kCityParts = 6, kCityStride = kSanitized ? 40 : 20;

class SweepOracleCity : public ::testing::TestWithParam<std::size_t> {};

TEST_P(SweepOracleCity, MatchesCgalSkeleton) {
  const std::vector<PolyShape> shapes = read_polyjson_file(synthetic_file("d_city_6000"));
  ASSERT_EQ(shapes.size(), kCityBlocks);
  const std::size_t part = kCityBlocks / kCityParts;
  std::size_t disagreeing = 0;
  for (std::size_t i = GetParam() * part; i < (GetParam() + 1) * part; i += kCityStride) {
    const PreparedFootprint prepared = prepare_footprint(to_footprint(shapes[i], 45.0));
    const std::vector<std::string> problems = sweep_and_compare_with_cgal(prepared.footprint);
    disagreeing += problems.empty() ? 0 : 1;
    for (const std::string& line : problems) ADD_FAILURE() << "shape " << i << ": " << line;
  }
  std::cout << "d_city_6000 shapes " << GetParam() * part << ".." << (GetParam() + 1) * part - 1 << ": " << disagreeing
            << " disagree with CGAL\n";
}

INSTANTIATE_TEST_SUITE_P(City, SweepOracleCity, ::testing::Range(std::size_t{0}, kCityParts));

// ---- real OpenStreetMap footprints ----

class SweepOracleOsm : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(SweepOracleOsm, EveryFootprintMatchesCgalSkeleton) {
  const GeoJsonCollection corpus = read_geojson_file(GetParam());
  ASSERT_TRUE(corpus.errors.empty()) << corpus.errors.front().message;
  std::size_t compared = 0, refused = 0, disagreeing = 0;
  for (std::size_t i = 0; i < corpus.features.size(); i += kSanitizedStride) {
    const GeoJsonFeature& f = corpus.features[i];
    Footprint fp;
    try {
      fp = prepare_footprint(to_footprint(f, 45.0)).footprint;
    } catch (const InputError&) {
      ++refused;  // which refusals are right is sweep_corpus_test's business
      continue;
    }
    ++compared;
    const std::vector<std::string> problems = sweep_and_compare_with_cgal(fp);
    if (!problems.empty()) ++disagreeing;
    for (const std::string& line : problems) ADD_FAILURE() << "feature " << f.id << ": " << line;
  }
  std::cout << GetParam().filename().string() << ": compared " << compared << " footprints with CGAL, " << disagreeing
            << " disagree, " << refused << " refused by prepare_footprint\n";
  EXPECT_GT(compared, 50u / kSanitizedStride);
}

INSTANTIATE_TEST_SUITE_P(Osm, SweepOracleOsm, ::testing::ValuesIn(footprint_corpus_files()), [](const auto& info) {
  std::string name = info.param.stem().string();
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
});

}  // namespace
}  // namespace procex

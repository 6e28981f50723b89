// The generated suites' own tools must be right, or their passes mean
// nothing: each property check reports a roof broken on purpose, the
// generators give valid and reproducible plans, the shrinker minimises, and
// a fixture reads back as the case it was written from.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include "core/geom/prepare.h"
#include "core/geom/segment_intersections.h"
#include "core/io/geojson.h"
#include "core/sweep/sweep.h"
#include "tests/support/generators/check_case.h"
#include "tests/support/generators/grid_plans.h"
#include "tests/support/generators/run_generated.h"
#include "tests/support/generators/shrink.h"
#include "tests/support/generators/size_plans.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

const Footprint kRect = make_footprint({{{0, 0}, {10, 0}, {10, 4}, {0, 4}}}, 45.0);

TEST(RoofProperties, ARightRoofPassesEveryCheck) {
  const Surface roof = sweep(kRect);
  const double tol = roof_tolerance(kRect);
  EXPECT_TRUE(check_valid_mesh(roof).empty());
  EXPECT_TRUE(check_faces_on_planes(kRect, {}, roof, tol).empty());
  EXPECT_TRUE(check_inward_roof(kRect, {}, roof, tol, 1).empty());
  // A hip roof on 10 x 4 at 45 degrees: (W L H - (W + L) s H^2 + 4/3 s^2 H^3) with H = 2.
  EXPECT_NEAR(surface_volume(roof), 40.0 * 2 - 14.0 * 4 + 4.0 / 3.0 * 8, 1e-9);
  EXPECT_NEAR(volume_of_offset_areas(40.0, -28.0, 4.0, 2.0), 34.666666666666667, 1e-12);
}

TEST(RoofProperties, ARaisedRidgeIsOffItsPlanesAndTheEnvelope) {
  Surface roof = sweep(kRect);
  for (glm::dvec3& v : roof.vertices)
    if (v.z > 1.0) v.z += 0.01;
  const double tol = roof_tolerance(kRect);
  EXPECT_FALSE(check_faces_on_planes(kRect, {}, roof, tol).empty());
  EXPECT_FALSE(check_inward_roof(kRect, {}, roof, tol, 1).empty());
}

// A sliver along a diagonal is a small share of its bounding box, where the
// points are drawn: finding none there is no roof error (the shrinker had
// minimised real failures down to such slivers).
TEST(RoofProperties, ASliverMayGoUnsampled) {
  const Footprint sliver = make_footprint({{{-2.1, 6.4}, {-1.4, 8.5}, {3.5, 23.3}}}, 45.0);
  EXPECT_TRUE(check_inward_roof(sliver, {}, sweep(sliver), roof_tolerance(sliver), 1).empty());
}

TEST(RoofProperties, AFaceTurnedDownOrMissingBreaksTheTiling) {
  Surface roof = sweep(kRect);
  // Reverse one roof face: it looks down, and the plan no longer adds up.
  for (SurfaceFace& f : roof.faces)
    if (f.kind == FaceKind::Side && f.source_edge == 0) {
      std::reverse(f.loops[0].begin(), f.loops[0].end());
      break;
    }
  EXPECT_FALSE(check_inward_roof(kRect, {}, roof, roof_tolerance(kRect), 1).empty());
}

TEST(RoofProperties, TransformedRoofsMatchOnlyWhenTransformed) {
  const Surface roof = sweep(kRect);
  const double tol = roof_tolerance(kRect);
  for (const PlanTransform& t : {PlanTransform::rotation(90), PlanTransform::mirror(), PlanTransform::translation({5e5, 5e6}),
                                 PlanTransform::rotation(30).after(PlanTransform::scale(1e-3))}) {
    const Footprint moved = transformed(kRect, t);
    const Surface other = sweep(prepare_footprint(moved).footprint);
    EXPECT_TRUE(compare_transformed(roof, t, other, std::max(tol * t.height_scale(), roof_tolerance(moved))).empty()) << t.name;
    EXPECT_FALSE(compare_transformed(roof, {}, other, std::max(tol, roof_tolerance(moved))).empty()) << t.name;
  }
}

// Under eaves the soffit and the roof above it both lie over the plan: the
// height compared is the roof's, seen from above, whichever face the sweep
// made first (generated angles finding 947, where a mirror reversed them).
TEST(RoofProperties, HeightsAreTheRoofSeenFromAboveWhateverTheFaceOrder) {
  Footprint eaves = kRect;
  eaves.profiles = {{"soffit", {{0, 0}, {0, 3}, {0.5, 3}, {-4.5, 8}}, {"wall", "soffit", "roof"}}};
  for (EdgeSpec& e : eaves.loops[0].edges) e.profile = 0;
  const Surface roof = sweep(eaves);
  Surface reordered = roof;
  std::reverse(reordered.faces.begin(), reordered.faces.end());
  EXPECT_EQ(largest_height_difference(roof, reordered, 2000, 3), 0.0);
  Surface raised = reordered;
  for (glm::dvec3& v : raised.vertices) v.z += 0.01;
  EXPECT_NEAR(largest_height_difference(roof, raised, 2000, 3), 0.01, 1e-9);
}

TEST(RoofProperties, MirroringKeepsEachEdgeItsSpec) {
  Footprint fp = kRect;
  for (std::size_t i = 0; i < 4; ++i) fp.loops[0].edges[i].angle_deg = 10.0 * static_cast<double>(i + 1);
  const Footprint m = transformed(fp, PlanTransform::mirror());
  const Loop& loop = m.loops[0];
  for (std::size_t i = 0; i < 4; ++i) {
    // Edge i of the mirror runs between the mirrored ends of the original edge with its id.
    const Loop& orig = fp.loops[0];
    const std::size_t k = static_cast<std::size_t>(loop.edges[i].id);
    EXPECT_EQ(loop.edges[i].angle_deg, orig.edges[k].angle_deg);
    EXPECT_EQ(loop.points[i], glm::dvec2(-orig.points[(k + 1) % 4].x, orig.points[(k + 1) % 4].y));
    EXPECT_EQ(loop.points[(i + 1) % 4], glm::dvec2(-orig.points[k].x, orig.points[k].y));
  }
}

TEST(Generators, PlansAreValidFootprintsOfTheirSize) {
  std::size_t with_holes = 0;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    std::mt19937_64 rng(seed);
    for (const NamedPlan& plan : {polyomino_plan(rng), letter_plan(rng), with_collinear_vertices(letter_plan(rng), rng)}) {
      std::size_t n = 0;
      for (const auto& loop : plan.loops) n += loop.size();
      EXPECT_GE(n, 4u) << plan.name;
      EXPECT_LE(n, 400u) << plan.name;
      with_holes += plan.loops.size() > 1 ? 1 : 0;
      EXPECT_NO_THROW(prepare_footprint(make_footprint(plan.loops, 45.0))) << plan.name;
    }
  }
  EXPECT_GT(with_holes, 30u);
}

// The kernel of a counter-clockwise polygon (the points that see all of it):
// the box it lies in (lo to hi) clipped by the inner side of every edge's line.
std::vector<glm::dvec2> kernel(const std::vector<glm::dvec2>& polygon, glm::dvec2 lo, glm::dvec2 hi) {
  std::vector<glm::dvec2> k{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, clipped;
  for (std::size_t i = 0; i < polygon.size() && !k.empty(); ++i) {
    const glm::dvec2 a = polygon[i], d = polygon[(i + 1) % polygon.size()] - a;
    const auto inside = [&](glm::dvec2 p) { return d.x * (p.y - a.y) - d.y * (p.x - a.x); };
    clipped.clear();
    for (std::size_t j = 0; j < k.size(); ++j) {
      const glm::dvec2 p = k[j], q = k[(j + 1) % k.size()];
      const double sp = inside(p), sq = inside(q);
      if (sp >= 0.0) clipped.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) clipped.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    std::swap(k, clipped);
  }
  return k;
}

// Random simple polygons (2-opt untangled random points) are simple, counter-
// clockwise, about half reflex, and not star-shaped: no point sees them whole,
// unlike the size class's random polygons drawn round a centre.
TEST(Generators, RandomSimplePolygonsAreSimpleAndNoPointSeesThemWhole) {
  for (std::size_t n : {20u, 300u, 3000u}) {
    std::mt19937_64 rng(n);
    const std::vector<glm::dvec2> p = random_simple_polygon(n, 100.0, rng).loops.at(0);
    ASSERT_EQ(p.size(), n);
    EXPECT_FALSE(loop_crossing(p)) << n;
    double area2 = 0.0;
    std::size_t reflex = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec2 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
      area2 += b.x * c.y - c.x * b.y;
      if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0.0) ++reflex;
    }
    EXPECT_GT(area2, 0.0) << n;
    if (n >= 300) {
      EXPECT_GT(reflex, n * 2 / 5) << n;
      EXPECT_LT(reflex, n * 3 / 5) << n;
    }
    EXPECT_TRUE(kernel(p, {0, 0}, {100, 100}).empty()) << n;
  }
  // The clipping finds a star-shaped polygon's kernel.
  std::mt19937_64 rng(1);
  EXPECT_FALSE(kernel(random_star_shaped(300, 40.0, rng).loops.at(0), {-40, -40}, {40, 40}).empty());
}

TEST(Generators, ASeedGivesTheSameCaseEveryTime) {
  for (CaseClass cls : {CaseClass::Grid, CaseClass::Angles, CaseClass::Size, CaseClass::Stars, CaseClass::LargeStars,
                        CaseClass::RandomPolygons, CaseClass::LargeRandomPolygons, CaseClass::RandomPolygonsAngles,
                        CaseClass::RandomPolygonsWalls}) {
    for (std::uint64_t seed : {0u, 7u, 12345u}) {
      const GeneratedCase a = generate_case(cls, seed), b = generate_case(cls, seed);
      EXPECT_EQ(a.description, b.description);
      ASSERT_EQ(a.footprint.loops.size(), b.footprint.loops.size());
        for (std::size_t l = 0; l < a.footprint.loops.size(); ++l) {
        EXPECT_EQ(a.footprint.loops[l].points, b.footprint.loops[l].points);
      }
    }
  }
  EXPECT_NE(generate_case(CaseClass::Grid, 1).description, generate_case(CaseClass::Grid, 2).description);
}

// PROCEX_SEEDS reruns reported seeds; a value that is neither a seed nor a
// range is refused with the variable's name, not a bare std::stoull error.
TEST(Generators, SeedsAskedForAreASeedOrARange) {
  const char* before = std::getenv("PROCEX_SEEDS");
  const std::string kept = before != nullptr ? before : "";
  auto asked = [](const char* value) {
    setenv("PROCEX_SEEDS", value, 1);
    return seeds_asked();
  };
  EXPECT_EQ(asked("834"), (std::pair<std::size_t, std::size_t>(834, 835)));
  EXPECT_EQ(asked("800-899"), (std::pair<std::size_t, std::size_t>(800, 900)));
  EXPECT_EQ(asked(""), std::nullopt);
  for (const char* bad : {"abc", "8x", "-5", "12-", "9-3", "1-2-3"}) {
    try {
      asked(bad);
      ADD_FAILURE() << bad << " was taken";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("PROCEX_SEEDS='" + std::string(bad) + "'"), std::string::npos) << e.what();
    }
  }
  if (before != nullptr) setenv("PROCEX_SEEDS", kept.c_str(), 1);
  else unsetenv("PROCEX_SEEDS");
}

TEST(Shrink, DropsWhatTheFailureDoesNotNeedAndRounds) {
  // "Fails" while some vertex lies right of x = 7: the minimum keeps one
  // such vertex in a triangle, on whole numbers.
  GeneratedCase c;
  c.footprint = make_footprint({{{0.123, 0}, {10.4567, 0}, {10.2, 4.31}, {5, 6}, {0, 4.8}}}, 45.0);
  const auto fails = [](const GeneratedCase& k) {
    for (const glm::dvec2& p : k.footprint.loops[0].points)
      if (p.x > 7.0) return true;
    return false;
  };
  const GeneratedCase small = shrink(c, fails, 100);
  ASSERT_EQ(small.footprint.loops[0].points.size(), 3u);
  EXPECT_TRUE(fails(small));
  for (const glm::dvec2& p : small.footprint.loops[0].points) EXPECT_EQ(p, glm::round(p));
}

TEST(Shrink, ALongLoopIsHalvedWithinASmallBudget) {
  // The size class's budget is a few candidates of minutes each: a regular
  // 4,096-gon that "fails" while it keeps more than 200 vertices comes down to
  // 256 in 4 candidates (one vertex dropped per candidate would reach 4,092).
  std::vector<glm::dvec2> ring;
  for (int i = 0; i < 4096; ++i) ring.push_back({std::cos(i * 2.0 * M_PI / 4096), std::sin(i * 2.0 * M_PI / 4096)});
  GeneratedCase c;
  c.footprint = make_footprint({ring}, 45.0);
  std::size_t tried = 0;
  const auto fails = [&tried](const GeneratedCase& k) {
    ++tried;
    return k.footprint.loops[0].points.size() > 200;
  };
  const GeneratedCase small = shrink(c, fails, 4);
  EXPECT_EQ(tried, 4u);
  EXPECT_EQ(small.footprint.loops[0].points.size(), 256u);
  EXPECT_EQ(small.footprint.loops[0].edges.size(), 256u);
  EXPECT_EQ(small.footprint.loops[0].points[1], ring[16]);
}

TEST(Shrink, AFixtureReadsBackAsItsCase) {
  for (std::uint64_t seed : {3u, 25u, 60u, 70u}) {  // one angle, per-edge angles, profiles, plan edits
    const GeneratedCase c = generate_case(CaseClass::Angles, seed);
    const GeoJsonCollection read = parse_geojson(fixture_geojson(c, "none"));
    ASSERT_EQ(read.features.size(), 1u);
    const GeneratedCase back = case_from_fixture(read.features[0]);
    EXPECT_EQ(back.description, c.description);
    ASSERT_EQ(back.footprint.loops.size(), c.footprint.loops.size());
    for (std::size_t l = 0; l < c.footprint.loops.size(); ++l) {
      EXPECT_EQ(back.footprint.loops[l].points, c.footprint.loops[l].points);
      for (std::size_t i = 0; i < c.footprint.loops[l].edges.size(); ++i) {
        EXPECT_EQ(back.footprint.loops[l].edges[i].angle_deg, c.footprint.loops[l].edges[i].angle_deg);
        const int p = c.footprint.loops[l].edges[i].profile, q = back.footprint.loops[l].edges[i].profile;
        ASSERT_EQ(p >= 0, q >= 0);
        if (p >= 0) {
          EXPECT_EQ(back.footprint.profiles[static_cast<std::size_t>(q)].name,
                    c.footprint.profiles[static_cast<std::size_t>(p)].name);
        }
      }
    }
    EXPECT_EQ(back.options.max_height, c.options.max_height);
    EXPECT_EQ(back.options.plan_edits.size(), c.options.plan_edits.size());
  }
}

}  // namespace
}  // namespace procex::testing

// Roof overhangs: the slab a roof makes when run past its walls is a closed,
// oriented 2-manifold whose faces lie on the roof's planes (the underside),
// on those planes moved out by the thickness (the top) or stand vertical (the
// fascia); it reaches the given distances past the walls in plan, and its
// volume is what the roof's planes give in closed form for a gable, a hip, a
// mansard and a gambrel.
#include "core/mesh/roof_overhang.h"

#include <cmath>
#include <algorithm>
#include <functional>
#include <set>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/geom/polygon3.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"

namespace procex {
namespace {

using Roof = std::vector<std::vector<glm::dvec3>>;

// A rectangle x in [0, w], y in [0, l]; edges 0 and 2 (along x) take profile
// `ends`, edges 1 and 3 (along y) take `sides`.
Surface building(double w, double l, const Profile& sides, const Profile& ends) {
  Footprint fp = make_footprint({{{0, 0}, {w, 0}, {w, l}, {0, l}}}, 0);
  fp.profiles = {sides, ends};
  for (int e : {1, 3}) fp.loops[0].edges[e].profile = 0;
  for (int e : {0, 2}) fp.loops[0].edges[e].profile = 1;
  return sweep(fp);
}

Roof faces_tagged(const Surface& s, const std::set<std::string>& tags) {
  Roof roof;
  for (const SurfaceFace& f : s.faces)
    if (tags.count(f.tag)) {
      EXPECT_EQ(f.loops.size(), 1u) << "a roof face with a hole";
      roof.emplace_back();
      for (std::uint32_t v : f.loops[0]) roof.back().push_back(s.vertices[v]);
    }
  return roof;
}

struct Box {
  glm::dvec3 lo{HUGE_VAL}, hi{-HUGE_VAL};
};

Box box_of(const Surface& s) {
  Box b;
  for (const glm::dvec3& p : s.vertices) b.lo = glm::min(b.lo, p), b.hi = glm::max(b.hi, p);
  return b;
}

// A plane through a face: unit normal and offset.
struct FacePlane {
  glm::dvec3 n;
  double d;
};

FacePlane plane_of(const std::vector<glm::dvec3>& pts) {
  const glm::dvec3 n = glm::normalize(newell_normal(pts));
  return {n, glm::dot(n, pts[0])};
}

// Checks everything a slab must be and returns its volume: closed, 2-manifold,
// oriented, planar, free of self-intersections; each top face on a roof
// plane moved up by the thickness, each underside or soffit face on a roof
// plane facing down, each fascia face vertical.
double check_slab(const Roof& roof, const Surface& slab, double thickness) {
  const ValidationReport r = validate(build_mesh(slab));
  std::string problems;
  for (const auto& p : r.problems) problems += p + "\n";
  EXPECT_TRUE(r.ok()) << problems;
  std::vector<FacePlane> roof_planes;
  for (const auto& f : roof) roof_planes.push_back(plane_of(f));
  std::map<std::string, int> per_tag;
  for (const SurfaceFace& f : slab.faces) {
    ++per_tag[f.tag];
    std::vector<glm::dvec3> pts;
    for (std::uint32_t v : f.loops[0]) pts.push_back(slab.vertices[v]);
    const FacePlane p = plane_of(pts);
    if (f.tag == "fascia") {
      EXPECT_NEAR(p.n.z, 0.0, 1e-7);  // as near as the other faces lie to their planes
      continue;
    }
    const bool top = f.tag == "roof";
    EXPECT_TRUE(top || f.tag == "underside" || f.tag == "soffit") << f.tag;
    const bool on_a_plane = std::any_of(roof_planes.begin(), roof_planes.end(), [&](const FacePlane& q) {
      const glm::dvec3 n = top ? q.n : -q.n;
      const double d = top ? q.d + thickness : -q.d;
      if (glm::length(n - p.n) > 1e-7) return false;
      return std::all_of(pts.begin(), pts.end(), [&](glm::dvec3 x) { return std::abs(glm::dot(n, x) - d) < 1e-7; });
    });
    EXPECT_TRUE(on_a_plane) << f.tag << " face at (" << pts[0].x << ", " << pts[0].y << ", " << pts[0].z
                            << ") lies on no roof plane" << (top ? " moved up by the thickness" : "");
  }
  EXPECT_GT(per_tag["roof"], 0);
  EXPECT_GT(per_tag["fascia"], 0);
  EXPECT_GT(per_tag["underside"], 0);
  return r.volume;
}

// The integral of f over [a, b] by the midpoint rule (f piecewise linear with
// a few kinks: the error is far below the tests' tolerance).
double integral(const std::function<double(double)>& f, double a, double b) {
  const int n = 200000;
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += f(a + (i + 0.5) * (b - a) / n);
  return sum * (b - a) / n;
}

const Profile kGableEnd{"gable end", {{0, 0}, {0, 30}}, {"gable"}};

TEST(RoofOverhang, GableSlabIsTheExtendedRoofTimesItsThickness) {
  // 10 wide (x), 16 long (y), walls 3 m, slopes at 45 degrees to a ridge at 8 m.
  const Surface house = building(10, 16, {"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}}, kGableEnd);
  const Roof roof = faces_tagged(house, {"roof"});
  ASSERT_EQ(roof.size(), 2u);
  const Surface slab = roof_overhang(roof, {.eave = 0.5, .verge = 0.3, .thickness = 0.2});
  const double volume = check_slab(roof, slab, 0.2);
  // Both planes slope 1: the slab is 0.2 thick over a sloped area of sqrt(2) x its plan.
  EXPECT_NEAR(volume, 0.2 * std::sqrt(2.0) * 11.0 * 16.6, 1e-7);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.x, -0.5, 1e-9);  // the eaves reach 0.5 past the long walls
  EXPECT_NEAR(b.hi.x, 10.5, 1e-9);
  EXPECT_NEAR(b.lo.y, -0.3, 1e-9);  // the verges 0.3 past the gables
  EXPECT_NEAR(b.hi.y, 16.3, 1e-9);
  EXPECT_NEAR(b.lo.z, 3.0 - 0.5, 1e-9);  // the eave drops along the slope
  EXPECT_NEAR(b.hi.z, 8.0 + 0.2 * std::sqrt(2.0), 1e-9);
}

TEST(RoofOverhang, FlushVergesLeaveTheGablesBare) {
  const Surface house = building(10, 16, {"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}}, kGableEnd);
  const Roof roof = faces_tagged(house, {"roof"});
  const Surface slab = roof_overhang(roof, {.eave = 0.4, .verge = 0.0, .thickness = 0.1});
  EXPECT_NEAR(check_slab(roof, slab, 0.1), 0.1 * std::sqrt(2.0) * 10.8 * 16.0, 1e-7);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.y, 0.0, 1e-9);
  EXPECT_NEAR(b.hi.y, 16.0, 1e-9);
}

TEST(RoofOverhang, HipRoofRunsOutByTheEaveAllRound) {
  const Profile eave{"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  const Surface house = building(10, 16, eave, eave);
  const Roof roof = faces_tagged(house, {"roof"});
  ASSERT_EQ(roof.size(), 4u);
  // Every edge of a hip roof is level: the verge distance is never used.
  const Surface slab = roof_overhang(roof, {.eave = 0.5, .verge = 4.0, .thickness = 0.2});
  EXPECT_NEAR(check_slab(roof, slab, 0.2), 0.2 * std::sqrt(2.0) * 11.0 * 17.0, 1e-7);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.x, -0.5, 1e-9);
  EXPECT_NEAR(b.hi.y, 16.5, 1e-9);
}

TEST(RoofOverhang, HipRoofWithSteeperEnds) {
  // The hips are no longer the corners' bisectors: past the walls the hip
  // line runs on into one side's band, and each slab corner follows it.
  const Surface house = building(10, 16, {"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}},
                                 {"steep", {{0, 0}, {0, 3}, {-2, 8}}, {"wall", "roof"}});
  const Roof roof = faces_tagged(house, {"roof"});
  const Surface slab = roof_overhang(roof, {.eave = 0.6, .verge = 0.1, .thickness = 0.25});
  EXPECT_GT(check_slab(roof, slab, 0.25), 0.0);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.x, -0.6, 1e-9);
  EXPECT_NEAR(b.lo.y, -0.6, 1e-9);
  EXPECT_NEAR(b.lo.z, 3.0 - 0.6 * 2.5, 1e-9);  // the steep ends' eaves drop 2.5 per metre
}

TEST(RoofOverhang, PyramidAndOctagonMeetAtOnePoint) {
  // Four and eight planes through one apex: the slab must still close there.
  const Profile eave{"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  const Surface square = building(10, 10, eave, eave);
  const Roof pyramid = faces_tagged(square, {"roof"});
  EXPECT_NEAR(check_slab(pyramid, roof_overhang(pyramid, {.eave = 0.5, .verge = 0, .thickness = 0.2}), 0.2),
              0.2 * std::sqrt(2.0) * 11.0 * 11.0, 1e-7);
  std::vector<glm::dvec2> octagon;
  for (int i = 0; i < 8; ++i) octagon.push_back({10 * std::cos(i * M_PI / 4), 10 * std::sin(i * M_PI / 4)});
  Footprint fp = make_footprint({octagon}, 0);
  fp.profiles = {eave};
  for (auto& e : fp.loops[0].edges) e.profile = 0;
  const Roof roof = faces_tagged(sweep(fp), {"roof"});
  ASSERT_EQ(roof.size(), 8u);
  // The octagon run out by 0.5: its area grows by 0.5 x its perimeter and 8 corner kites.
  const double side = 2 * 10 * std::sin(M_PI / 8), apothem = 10 * std::cos(M_PI / 8);
  const double area = 4 * side * apothem + 0.5 * 8 * side + 0.25 * 8 * std::tan(M_PI / 8);
  EXPECT_NEAR(check_slab(roof, roof_overhang(roof, {.eave = 0.5, .verge = 0, .thickness = 0.2}), 0.2),
              0.2 * std::sqrt(2.0) * area, 1e-6);
}

// The slab over a roof whose every section at distance d from the nearest wall
// is `lower` up to the break and `upper` past it (two planes each): the top
// is those planes moved out by the thickness, cut where they meet.
struct TwoSlopes {
  double wall, run1, rise1, run2, rise2;  // from the wall top: in run1 up rise1, then in run2 up rise2
  double under(double d) const {
    return std::min(wall + d * rise1 / run1, wall + rise1 + (d - run1) * rise2 / run2);
  }
  double over(double d, double t) const {
    const double k1 = rise1 / run1, k2 = rise2 / run2;
    return std::min(wall + d * k1 + t * std::sqrt(1 + k1 * k1), wall + rise1 + (d - run1) * k2 + t * std::sqrt(1 + k2 * k2));
  }
};

TEST(RoofOverhang, MansardTwoSlopesAllRound) {
  // Walls to 3, a steep lower slope 1 in over 3 up, a shallow upper slope 3 in per 1 up.
  const TwoSlopes s{3, 1, 3, 3, 1};
  const Profile mansard{"mansard", {{0, 0}, {0, 3}, {-1, 6}, {-4, 7}}, {"wall", "mansard", "roof"}};
  const Surface house = building(20, 10, mansard, mansard);
  const Roof roof = faces_tagged(house, {"mansard", "roof"});
  ASSERT_EQ(roof.size(), 8u);
  const double e = 0.4, t = 0.15;
  const double volume = check_slab(roof, roof_overhang(roof, {.eave = e, .verge = 0.9, .thickness = t}), t);
  // Over the 20.8 x 10.8 plan, the points u from its edge form a ring of
  // length 2 (20.8 + 10.8) - 8u, at d = u - e from the walls.
  const double expected = integral(
      [&](double u) { return (s.over(u - e, t) - s.under(u - e)) * (2 * (20.8 + 10.8) - 8 * u); }, 0, 10.8 / 2);
  EXPECT_NEAR(volume, expected, 1e-6 * expected);
}

TEST(RoofOverhang, GambrelSidesGableEnds) {
  // 20 long (x), 10 wide (y): walls 3, 2 in over 2 up, then 3 in over 2 up.
  const TwoSlopes s{3, 2, 2, 3, 2};
  Footprint fp = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 0);
  fp.profiles = {{"gambrel", {{0, 0}, {0, 3}, {-2, 5}, {-5, 7}}, {"wall", "lower", "upper"}}, kGableEnd};
  for (int e : {0, 2}) fp.loops[0].edges[e].profile = 0;
  for (int e : {1, 3}) fp.loops[0].edges[e].profile = 1;
  const Roof roof = faces_tagged(sweep(fp), {"lower", "upper"});
  ASSERT_EQ(roof.size(), 4u);
  const double e = 0.5, v = 0.35, t = 0.2;
  const Surface slab = roof_overhang(roof, {.eave = e, .verge = v, .thickness = t});
  const double volume = check_slab(roof, slab, t);
  // A prism: the cross-section across the width, times the length with its verges.
  const double section =
      integral([&](double y) { const double d = std::min(y, 10 - y); return s.over(d, t) - s.under(d); }, -e, 10 + e);
  EXPECT_NEAR(volume, section * (20 + 2 * v), 1e-6 * volume);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.x, -v, 1e-9);
  EXPECT_NEAR(b.hi.x, 20 + v, 1e-9);
  EXPECT_NEAR(b.lo.y, -e, 1e-9);
  EXPECT_NEAR(b.lo.z, 3 - e, 1e-9);
}

std::string refusal(const Roof& roof, const RoofOverhang& o) {
  try {
    roof_overhang(roof, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RoofOverhang, HostileSizesAreRefusedByName) {
  const Profile eave{"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  const Roof roof = faces_tagged(building(10, 16, eave, eave), {"roof"});
  EXPECT_NE(refusal(roof, {.eave = -0.5}).find("eave must be a finite number of 0 or more, not -0.5"), std::string::npos);
  EXPECT_NE(refusal(roof, {.thickness = std::nan("")}).find("thickness must be a finite number above 0, not nan"),
            std::string::npos);
  EXPECT_NE(refusal(roof, {.thickness = 0}).find("thickness must be"), std::string::npos);
  EXPECT_NE(refusal(roof, {.verge = HUGE_VAL}).find("verge must be a finite number"), std::string::npos);
  EXPECT_NE(refusal(roof, {.thickness = 1e9}).find("thickness (1e+09 m) is more than 100 times the roof's extent"),
            std::string::npos);
}

// A plan of one or more loops (the first outer, counter-clockwise; the rest
// courtyards, clockwise), edge e of the whole taking profiles[kind[e]].
Surface building(const std::vector<std::vector<glm::dvec2>>& loops, const std::vector<Profile>& profiles,
                 const std::vector<int>& kind) {
  Footprint fp = make_footprint(loops, 0);
  fp.profiles = profiles;
  std::size_t e = 0;
  for (auto& loop : fp.loops)
    for (auto& edge : loop.edges) edge.profile = kind.at(e++);
  return sweep(fp);
}

const std::vector<glm::dvec2> kL{{0, 0}, {20, 0}, {20, 8}, {9, 8}, {9, 17}, {0, 17}};

TEST(RoofOverhang, LOfTwoGablesMeetingAtAValley) {
  // Wings 8 and 9 wide, gabled at their far ends (x = 20, y = 17), a hip at
  // the outer corner and a valley from the inner one; every slope 1, so the
  // slab is the thickness times sqrt 2 thick upright over its plan: the L run
  // out by 0.5 past the eaves and 0.3 past the gables, its bounding box less
  // the notch (x past 9.5, y past 8.5).
  const Profile eave{"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  const Roof roof = faces_tagged(building({kL}, {eave, kGableEnd}, {0, 1, 0, 0, 1, 0}), {"roof"});
  const Surface slab = roof_overhang(roof, {.eave = 0.5, .verge = 0.3, .thickness = 0.2});
  const double plan = (20.3 + 0.5) * (17.3 + 0.5) - (20.3 - 9.5) * (17.3 - 8.5);
  EXPECT_NEAR(check_slab(roof, slab, 0.2), 0.2 * std::sqrt(2.0) * plan, 1e-7);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.x, -0.5, 1e-9);
  EXPECT_NEAR(b.lo.y, -0.5, 1e-9);
  EXPECT_NEAR(b.hi.x, 20.3, 1e-9);
  EXPECT_NEAR(b.hi.y, 17.3, 1e-9);
  EXPECT_NEAR(b.lo.z, 3.0 - 0.5, 1e-9);
  EXPECT_NEAR(b.hi.z, 3.0 + 4.5 + 0.2 * std::sqrt(2.0), 1e-9);  // the wider wing's ridge
}

TEST(RoofOverhang, HippedLAndCourtyardRunOutAllRound) {
  // Slopes of 1 all round: the slab is 0.2 sqrt 2 upright over the plan run
  // out by the eave, A + e P + e^2 (convex corners - inward corners) for the L.
  const Profile eave{"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  const Roof l = faces_tagged(building({kL}, {eave}, {0, 0, 0, 0, 0, 0}), {"roof"});
  EXPECT_NEAR(check_slab(l, roof_overhang(l, {.eave = 0.5, .verge = 0.3, .thickness = 0.2}), 0.2),
              0.2 * std::sqrt(2.0) * (241 + 0.5 * 74 + 0.25 * (5 - 1)), 1e-7);
  // A 20 m square round an 8 m courtyard: the overhang runs into the
  // courtyard too, leaving it 7 m across.
  const Roof ring = faces_tagged(
      building({{{0, 0}, {20, 0}, {20, 20}, {0, 20}}, {{6, 6}, {6, 14}, {14, 14}, {14, 6}}}, {eave}, std::vector<int>(8, 0)),
      {"roof"});
  EXPECT_NEAR(check_slab(ring, roof_overhang(ring, {.eave = 0.5, .verge = 0.3, .thickness = 0.2}), 0.2),
              0.2 * std::sqrt(2.0) * (21 * 21 - 7 * 7), 1e-7);
}

TEST(RoofOverhang, ValleysOfMixedPitches) {
  // The L's wings pitched unlike (1 and 0.7), its gables and the inner walls
  // as before: the creases where unequal slopes meet run out, and the top's
  // corners are where the raised planes meet again.
  const Profile steep{"steep", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  const Profile low{"low", {{0, 0}, {0, 3}, {-10, 10}}, {"wall", "roof"}};
  const Roof roof = faces_tagged(building({kL}, {steep, low, kGableEnd}, {0, 2, 0, 1, 2, 1}), {"roof"});
  const Surface slab = roof_overhang(roof, {.eave = 0.4, .verge = 0.25, .thickness = 0.15});
  EXPECT_GT(check_slab(roof, slab, 0.15), 0.0);
  const Box b = box_of(slab);
  EXPECT_NEAR(b.lo.x, -0.4, 1e-9);
  EXPECT_NEAR(b.hi.x, 20.25, 1e-9);
  EXPECT_NEAR(b.hi.y, 17.25, 1e-9);
}

TEST(RoofOverhang, TUCrossAndStepPlansWithAPitchPerEdge) {
  // Plans with valleys (a T, a U, a cross, a Z of steps), each edge pitched
  // its own way, some gabled: every slab closed and on the roof's planes,
  // or refused by name where raised planes that met at one corner part or
  // an edge a few millimetres long (unequal pitches meeting almost at one
  // point) would turn over.
  // Each plan, and the edges at its wings' ends (gabled in variant 3).
  const std::vector<std::pair<std::vector<glm::dvec2>, std::set<std::size_t>>> plans{
      {{{0, 0}, {24, 0}, {24, 8}, {16, 8}, {16, 20}, {8, 20}, {8, 8}, {0, 8}}, {1, 4, 7}},
      {{{0, 0}, {22, 0}, {22, 18}, {15, 18}, {15, 7}, {7, 7}, {7, 18}, {0, 18}}, {2, 6}},
      {{{8, 0}, {16, 0}, {16, 8}, {24, 8}, {24, 16}, {16, 16}, {16, 24}, {8, 24}, {8, 16}, {0, 16}, {0, 8}, {8, 8}}, {0, 3, 6, 9}},
      {{{0, 0}, {10, 0}, {10, 5}, {18, 5}, {18, 13}, {26, 13}, {26, 21}, {12, 21}, {12, 13}, {4, 13}, {4, 8}, {0, 8}}, {5, 11}},
  };
  int refused = 0, built = 0;
  for (std::size_t k = 0; k < plans.size(); ++k)
    for (int variant = 0; variant < 4; ++variant) {
      const auto& [plan, ends] = plans[k];
      const std::size_t n = plan.size();
      std::vector<Profile> profiles;
      std::vector<int> kind;
      for (std::size_t i = 0; i < n; ++i) {
        const double run = variant == 0 ? 4 : 2.5 + 2 * (0.5 + 0.5 * std::sin(1.9 * i + variant));
        profiles.push_back({std::to_string(i), {{0, 0}, {0, 3}, {-run, 7}}, {"wall", "roof"}});
        kind.push_back(variant == 3 && ends.count(i) ? static_cast<int>(n) : static_cast<int>(i));
      }
      profiles.push_back(kGableEnd);
      const Roof roof = faces_tagged(building({plan}, profiles, kind), {"roof"});
      SCOPED_TRACE(testing::Message() << "plan " << k << ", variant " << variant);
      const RoofOverhang o{.eave = 0.3 + 0.2 * variant, .verge = 0.25, .thickness = 0.15};
      try {
        const Surface slab = roof_overhang(roof, o);
        EXPECT_GT(check_slab(roof, slab, 0.15), 0.0);
        ++built;
      } catch (const InputError& e) {
        const std::string why = e.what();
        EXPECT_TRUE(why.find("no longer meet at one point") != std::string::npos ||
                    why.find("a face there would turn inside out") != std::string::npos)
            << why;
        ++refused;
      }
    }
  EXPECT_GE(built, 12) << refused << " refused";
}

TEST(RoofOverhang, CutCornersMeetTheRoofsOwn) {
  // Building w49209637 of samples/footprints/sample_block.geojson, hipped at
  // 52 degrees: a corner cut from the planes fitted to the sweep's faces fell
  // 1.5e-5 m from the roof's own corner there, and the slab was open.
  std::vector<glm::dvec2> plan{{-171.674, -678.106}, {-170.49, -692.861}, {-158.662, -689.728}, {-133.549, -679.963},
                               {-132.558, -669.652}, {-149.582, -668.196}, {-172.245, -670.918}};
  const double run = 20 * std::tan(38 * M_PI / 180);
  const Roof roof = faces_tagged(building({plan}, {{"e", {{0, 0}, {0, 2.6}, {-run, 22.6}}, {"wall", "roof"}}}, std::vector<int>(7, 0)),
                                 {"roof"});
  EXPECT_GT(check_slab(roof, roof_overhang(roof, {.eave = 0.45, .verge = 0.45, .thickness = 0.18}), 0.18), 0.0);
}

TEST(RoofOverhang, RoofsItCannotRunOutAreRefusedSayingWhy) {
  const Profile eave{"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  // A U whose arms stand 0.6 m apart: eaves of 0.5 would fold the notch's end over.
  const Roof u = faces_tagged(
      building({{{0, 0}, {20, 0}, {20, 10}, {10.3, 10}, {10.3, 4}, {9.7, 4}, {9.7, 10}, {0, 10}}}, {eave}, std::vector<int>(8, 0)),
      {"roof"});
  EXPECT_NE(refusal(u, {.eave = 0.5}).find("would fold over itself: the overhang is too wide for the walls there"),
            std::string::npos)
      << refusal(u, {.eave = 0.5});
  EXPECT_EQ(refusal(u, {.eave = 0.2}), "accepted");
  // A ring opened by a slit 0.6 m wide, one side of it a metre taller in
  // plan: the eaves across the slit would run into each other.
  const Roof c = faces_tagged(building({{{0, 0}, {20, 0}, {20, 20}, {10.3, 20}, {10.3, 14}, {14, 14}, {14, 6}, {6, 6},
                                         {6, 14}, {9.7, 14}, {9.7, 21}, {0, 21}}},
                                       {eave}, std::vector<int>(12, 0)),
                              {"roof"});
  EXPECT_NE(refusal(c, {.eave = 0.5}).find("would run into another part of it"), std::string::npos) << refusal(c, {.eave = 0.5});
  EXPECT_EQ(refusal(c, {.eave = 0.2}), "accepted");
  // A T whose stem's west wall is a gable running up through the crossbar's roof.
  const Roof stepped = faces_tagged(
      building({{{0, 0}, {24, 0}, {24, 8}, {16, 8}, {16, 20}, {8, 20}, {8, 8}, {0, 8}}}, {eave, kGableEnd}, {0, 0, 0, 0, 0, 1, 0, 0}),
      {"roof"});
  EXPECT_NE(refusal(stepped, {}).find("doubles back at (8, "), std::string::npos) << refusal(stepped, {});
  const Surface l_shape = building({kL}, {eave}, {0, 0, 0, 0, 0, 0});
  // Walls given as roof.
  EXPECT_NE(refusal(faces_tagged(l_shape, {"roof", "wall"}), {}).find("is vertical or faces down"), std::string::npos);
  // A hip roof without one of its ends leaves a triangle of its outline (10 x 5 / 2) uncovered.
  Roof hip = faces_tagged(building(10, 16, eave, eave), {"roof"});
  const auto end = std::find_if(hip.begin(), hip.end(), [](const auto& f) { return f.size() == 3; });
  ASSERT_NE(end, hip.end());
  hip.erase(end);
  EXPECT_NE(refusal(hip, {}).find("the roof covers 135 m2 of its 160 m2 outline"), std::string::npos) << refusal(hip, {});
  EXPECT_NE(refusal({}, {}).find("there is no roof"), std::string::npos);
}


TEST(RoofOverhang, HipsOfMixedPitchesOnConvexPolygons) {
  // Irregular convex plans (points on an ellipse at uneven angles), each edge
  // its own pitch: corners where unequal slopes meet, hips that run on past
  // the walls into either side's band, ridges of any length.
  for (int n = 3; n <= 12; ++n)
    for (int variant = 0; variant < 3; ++variant) {
      std::vector<glm::dvec2> plan;
      for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * (i + 0.3 * std::sin(1.7 * i + variant)) / n;
        plan.push_back({12 * std::cos(a), 7 * std::sin(a)});
      }
      Footprint fp = make_footprint({plan}, 0);
      for (int i = 0; i < n; ++i) {
        const double run = 2 + 3 * (0.5 + 0.5 * std::sin(2.3 * i + variant));
        fp.profiles.push_back({std::to_string(i), {{0, 0}, {0, 3}, {-run, 3 + 4}}, {"wall", "roof"}});
        fp.loops[0].edges[i].profile = i;
      }
      const Roof roof = faces_tagged(sweep(fp), {"roof"});
      SCOPED_TRACE(testing::Message() << n << " sides, variant " << variant);
      const Surface slab = roof_overhang(roof, {.eave = 0.2 + 0.3 * variant, .verge = 0.25, .thickness = 0.15});
      EXPECT_GT(check_slab(roof, slab, 0.15), 0.0);
    }
}


TEST(RoofOverhang, FlatRoofSaltboxAndJerkinhead) {
  // A flat roof (a sweep's cap): a plain slab 0.2 thick over the plan run out by 0.5.
  const Roof flat{{{0, 0, 3}, {10, 0, 3}, {10, 10, 3}, {0, 10, 3}}};
  EXPECT_NEAR(check_slab(flat, roof_overhang(flat, {.eave = 0.5, .verge = 0.1, .thickness = 0.2}), 0.2), 11 * 11 * 0.2, 1e-9);
  // A saltbox: the long walls 3 and 5 m high under slopes of 1, so the ridge
  // is off centre and the gables' rakes unequal; the planes still slope alike.
  Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 16}, {0, 16}}}, 0);
  fp.profiles = {{"low", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}},
                 {"high", {{0, 0}, {0, 5}, {-10, 15}}, {"wall", "roof"}},
                 kGableEnd};
  fp.loops[0].edges[1].profile = 0, fp.loops[0].edges[3].profile = 1;
  fp.loops[0].edges[0].profile = fp.loops[0].edges[2].profile = 2;
  const Roof saltbox = faces_tagged(sweep(fp), {"roof"});
  EXPECT_NEAR(check_slab(saltbox, roof_overhang(saltbox, {.eave = 0.5, .verge = 0.3, .thickness = 0.2}), 0.2),
              0.2 * std::sqrt(2.0) * 11.0 * 16.6, 1e-7);
  // A jerkinhead: the gables rise to 6 m, then a steep hip closes them;
  // the gable sides mix rakes and a level hip edge, and run out by the verge.
  const Profile jerkin{"jerkin", {{0, 0}, {0, 6}, {-1, 8}}, {"gable", "roof"}};
  const Roof roof = faces_tagged(building(10, 16, {"eave", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}}, jerkin), {"roof"});
  ASSERT_EQ(roof.size(), 4u);
  const Surface slab = roof_overhang(roof, {.eave = 0.5, .verge = 0.3, .thickness = 0.2});
  EXPECT_GT(check_slab(roof, slab, 0.2), 0.0);
  EXPECT_NEAR(box_of(slab).lo.y, -0.3, 1e-9);
}

}  // namespace
}  // namespace procex

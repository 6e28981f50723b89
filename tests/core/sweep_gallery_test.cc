// The paper's fig. 22 gallery (and fig. 2, fig. 25) as tests: every result
// validates as a closed, oriented, planar 2-manifold, and a number is checked
// against an answer computed without the engine: volumes and roof heights of
// rectangles under one profile integrate the profile directly, faces are
// counted per tag.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/footprint.h"
#include "core/geom/profile.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/figure25.h"

namespace procex {
namespace {

std::vector<glm::dvec2> rectangle(double w, double d) { return {{0, 0}, {w, 0}, {w, d}, {0, d}}; }

// Edge i of the (single-loop) footprint follows profiles[assign[i]].
Footprint with_profiles(const std::vector<glm::dvec2>& pts, std::vector<Profile> profiles,
                        const std::vector<int>& assign) {
  Footprint fp = make_footprint({pts}, 45.0);
  fp.profiles = std::move(profiles);
  for (std::size_t i = 0; i < pts.size(); ++i) fp.loops[0].edges[i].profile = assign[i % assign.size()];
  return fp;
}

struct Closed {
  double volume = 0.0;
  double top = 0.0;
};

// A w x d rectangle (w >= d) with one profile on every edge: at height z the
// cross-section is the rectangle inset by the profile's inward offset i(z), so
// the volume is the integral of (w - 2i)(d - 2i), exact by Simpson's rule on
// each straight segment, up to where i reaches d / 2 (the ridge). Above its
// last point a profile carries on with its last slope, as the engine does.
Closed integrate_rectangle(double w, double d, const Profile& p) {
  Closed r;
  auto area = [&](double inset) { return (w - 2 * inset) * (d - 2 * inset); };
  std::vector<glm::dvec2> pts = p.points;
  const glm::dvec2 last = pts.back() - pts[pts.size() - 2];
  pts.push_back(pts.back() + last * (10.0 * d / std::max(std::abs(last.x), 1e-9)));
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double i0 = -pts[i].x, i1 = -pts[i + 1].x, z0 = pts[i].y, z1 = pts[i + 1].y;
    if (z1 == z0) continue;  // a horizontal run: the inset jumps
    double t1 = 1.0;
    if (i1 > d / 2) t1 = (d / 2 - i0) / (i1 - i0);
    const double za = z0, zb = z0 + t1 * (z1 - z0), ib = i0 + t1 * (i1 - i0);
    r.volume += (zb - za) / 6.0 * (area(i0) + 4.0 * area(0.5 * (i0 + ib)) + area(ib));
    r.top = zb;
    if (t1 < 1.0) break;
  }
  return r;
}

using testing::expect_valid;
using testing::faces_per_tag;

const Profile kHip{"hip", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}};
const Profile kGableEnd{"gable end", {{0, 0}, {0, 3}, {0, 30}}, {"wall", "gable"}};
const Profile kSoffit{"soffit", {{0, 0}, {0, 3}, {0.5, 3}, {-10, 13.5}}, {"wall", "soffit", "roof"}};
const Profile kSoffitGableEnd{"soffit gable end", {{0, 0}, {0, 3}, {0.5, 3}, {0.5, 30}}, {"wall", "soffit", "gable"}};

TEST(Gallery, HippedRoof) {
  const Surface s = sweep(with_profiles(rectangle(20, 10), {kHip}, {0}));
  const auto c = expect_valid(s);
  const Closed want = integrate_rectangle(20, 10, kHip);
  EXPECT_NEAR(c.volume, want.volume, 1e-6);
  EXPECT_NEAR(c.max_height, want.top, 1e-9);
  EXPECT_NEAR(want.volume, 600.0 + 100.0 * (60.0 - 10.0) / 12.0, 1e-9);  // walls + hip b^2(3a - b)/12
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"roof", 4}, {"wall", 4}}));
}

TEST(Gallery, StandardGable) {
  const Surface s = sweep(with_profiles(rectangle(20, 10), {kHip, kGableEnd}, {0, 1}));
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 20 * 10 * 3 + 0.5 * 10 * 5 * 20, 1e-6);
  EXPECT_NEAR(c.max_height, 8.0, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"gable", 2}, {"roof", 2}, {"wall", 4}}));
}

TEST(Gallery, OverhangingGable) {
  // Eaves and verges both reach out 0.5 at the top of the walls.
  const Surface s = sweep(with_profiles(rectangle(20, 10), {kSoffit, kSoffitGableEnd}, {0, 1}));
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 20 * 10 * 3 + 0.5 * 11 * 5.5 * 21, 1e-6);
  EXPECT_NEAR(c.max_height, 8.5, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"gable", 2}, {"roof", 2}, {"soffit", 4}, {"wall", 4}}));
  // The soffits face down, 3 m up, and reach 0.5 m beyond the walls.
  const Mesh mesh = build_mesh(s);
  double soffit_area = 0.0;
  for (const SurfaceFace& f : s.faces) {
    if (f.tag != "soffit") continue;
    glm::dvec3 n{0.0};
    const auto& loop = f.loops[0];
    for (std::size_t i = 0; i < loop.size(); ++i)
      n += glm::cross(s.vertices[loop[i]], s.vertices[loop[(i + 1) % loop.size()]]);
    EXPECT_LT(n.z, 0.0);
    soffit_area += 0.5 * glm::length(n);
  }
  EXPECT_NEAR(soffit_area, 21 * 11 - 20 * 10, 1e-9);
}

TEST(Gallery, HorizontalOverhangAllRound) {
  const Surface s = sweep(with_profiles(rectangle(20, 10), {kSoffit}, {0}));
  const auto c = expect_valid(s);
  const Closed want = integrate_rectangle(20, 10, kSoffit);
  EXPECT_NEAR(c.volume, want.volume, 1e-6);
  EXPECT_NEAR(c.volume, 600.0 + 121.0 * (63.0 - 11.0) / 12.0, 1e-6);
  EXPECT_NEAR(c.max_height, want.top, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"roof", 4}, {"soffit", 4}, {"wall", 4}}));
}

TEST(Gallery, LedgeSetsTheUpperStoreyBack) {
  const Profile ledge{"ledge", {{0, 0}, {0, 3}, {-1, 3}, {-1, 6}, {-6, 11}}, {"wall", "ledge", "wall", "roof"}};
  const Surface s = sweep(with_profiles(rectangle(20, 10), {ledge}, {0}));
  const auto c = expect_valid(s);
  const Closed want = integrate_rectangle(20, 10, ledge);
  EXPECT_NEAR(c.volume, want.volume, 1e-6);
  EXPECT_NEAR(c.max_height, want.top, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"ledge", 4}, {"roof", 4}, {"wall", 8}}));
  for (const SurfaceFace& f : s.faces) {
    if (f.tag != "ledge") continue;
    glm::dvec3 n{0.0};
    for (std::size_t i = 0; i < f.loops[0].size(); ++i)
      n += glm::cross(s.vertices[f.loops[0][i]], s.vertices[f.loops[0][(i + 1) % f.loops[0].size()]]);
    EXPECT_GT(n.z, 0.0);  // a ledge faces up
  }
}

// Neighbours stepping different ways at one height: the bottom edge steps
// out 1 m (a soffit), the right one in 1 m (a ledge), the others go straight
// on. Their flattened nested faces fold over each other at the corner
// between them; overlaid, the soffit is exactly the new section less the old
// ([0, 9] x [-1, 0]) and the ledge the old less the new ([9, 10] x [0, 10]).
TEST(Gallery, NeighboursSteppingOutAndInMeetAtACorner) {
  const Profile out{"out", {{0, 0}, {0, 3}, {1, 3}, {1, 5}}, {"wall", "soffit", "wall"}};
  const Profile in{"in", {{0, 0}, {0, 3}, {-1, 3}, {-1, 5}}, {"wall", "ledge", "wall"}};
  const Profile none{"none", {{0, 0}, {0, 5}}, {"wall"}};
  SweepOptions options;
  options.max_height = 5.0;
  const Surface s = sweep(with_profiles(rectangle(10, 10), {out, in, none}, {0, 1, 2, 2}), options);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 10.0 * 10.0 * 3.0 + 9.0 * 11.0 * 2.0, 1e-9);
  std::map<std::string, double> up;  // area seen from above, per tag
  for (const SurfaceFace& f : s.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        up[f.tag] += 0.5 * glm::cross(s.vertices[loop[i]], s.vertices[loop[(i + 1) % loop.size()]]).z;
  EXPECT_NEAR(up["soffit"], -9.0, 1e-9);  // faces down
  EXPECT_NEAR(up["ledge"], 10.0, 1e-9);   // faces up
  EXPECT_EQ(faces_per_tag(s).at("soffit"), 1);
  EXPECT_EQ(faces_per_tag(s).at("ledge"), 1);
}

TEST(Gallery, CurvedRoofOfSixteenSegments) {
  Profile curved{"curved", {{0, 0}, {0, 3}}, {"wall"}};
  const double r = 4.0;
  for (int i = 1; i <= 16; ++i) {
    const double a = M_PI / 2 * i / 16;
    curved.points.push_back({-r * (1 - std::cos(a)) , 3 + r * std::sin(a)});
    curved.tags.push_back("roof");
  }
  // The arc ends nearly flat, 4 m in; the last segment's slope closes the rest.
  const Surface s = sweep(with_profiles(rectangle(20, 12), {curved}, {0}));
  const auto c = expect_valid(s);
  const Closed want = integrate_rectangle(20, 12, curved);
  EXPECT_NEAR(c.volume, want.volume, 1e-6);
  EXPECT_NEAR(c.max_height, want.top, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"roof", 64}, {"wall", 4}}));
}

TEST(Gallery, Mansard) {
  const Profile mansard{"mansard", {{0, 0}, {0, 3}, {-1, 6}, {-4, 7}}, {"wall", "mansard", "roof"}};
  const Surface s = sweep(with_profiles(rectangle(20, 12), {mansard}, {0}));
  const auto c = expect_valid(s);
  const Closed want = integrate_rectangle(20, 12, mansard);
  EXPECT_NEAR(c.volume, want.volume, 1e-6);
  EXPECT_NEAR(c.max_height, want.top, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"mansard", 4}, {"roof", 4}, {"wall", 4}}));
}

TEST(Gallery, GambrelWithGableEnds) {
  const Profile gambrel{"gambrel", {{0, 0}, {0, 3}, {-2, 5}, {-5, 7}}, {"wall", "lower", "upper"}};
  const Surface s = sweep(with_profiles(rectangle(20, 10), {gambrel, kGableEnd}, {0, 1}));
  const auto c = expect_valid(s);
  // The cross-section across the long sides is the profile mirrored: its area
  // times the length.
  const double section = 10 * 3 + (10 + 6) / 2.0 * 2 + (6 + 0) / 2.0 * 2;
  EXPECT_NEAR(c.volume, section * 20, 1e-6);
  EXPECT_NEAR(c.max_height, 7.0, 1e-9);
  EXPECT_EQ(faces_per_tag(s),
            (std::map<std::string, int>{{"gable", 2}, {"lower", 2}, {"upper", 2}, {"wall", 4}}));
}

TEST(Gallery, EightFacesMeetOnAnOctagon) {
  std::vector<glm::dvec2> octagon;
  const double radius = 10.0;
  for (int i = 0; i < 8; ++i) octagon.push_back({radius * std::cos(M_PI / 4 * i), radius * std::sin(M_PI / 4 * i)});
  const Surface s = sweep(make_footprint({octagon}, 45.0));
  const auto c = expect_valid(s);
  const double inradius = radius * std::cos(M_PI / 8);
  const double area = 2.0 * std::sqrt(2.0) * radius * radius;
  EXPECT_NEAR(c.max_height, inradius, 1e-9);
  EXPECT_NEAR(c.volume, area * inradius / 3.0, 1e-6);
  // All eight faces share one apex vertex.
  std::map<std::uint32_t, int> uses;
  for (const SurfaceFace& f : s.faces)
    for (auto v : f.loops[0])
      if (std::abs(s.vertices[v].z - inradius) < 1e-9) ++uses[v];
  ASSERT_EQ(uses.size(), 1u);
  EXPECT_EQ(uses.begin()->second, 8);
}

TEST(Gallery, Figure2HouseOnAnLShape) {
  // Walls, an eave that steps out, a fascia, and a 40 degree pitched roof.
  const double pitch = 40.0 * M_PI / 180.0, rise = 6.0;
  const Profile house{"house",
                      {{0, 0}, {0, 3}, {0.4, 3}, {0.4, 3.2}, {0.4 - rise / std::tan(pitch), 3.2 + rise}},
                      {"wall", "soffit", "fascia", "roof"}};
  const std::vector<glm::dvec2> l_shape = {{0, 0}, {20, 0}, {20, 8}, {8, 8}, {8, 20}, {0, 20}};
  const Surface s = sweep(with_profiles(l_shape, {house}, {0}));
  const auto c = expect_valid(s);
  // The ridges run along the middle of the 8 m arms, widened by the eaves.
  EXPECT_NEAR(c.max_height, 3.2 + (4.0 + 0.4) * std::tan(pitch), 1e-9);
  const auto tags = faces_per_tag(s);
  EXPECT_EQ(tags.at("wall"), 6);
  EXPECT_EQ(tags.at("soffit"), 6);
  EXPECT_EQ(tags.at("fascia"), 6);
  EXPECT_EQ(tags.at("roof"), 6);
}

// Fig. 25 analogue (tests/support/figure25.h): 24 nested loops, 552
// vertices, three profiles.
TEST(Gallery, TwentyFourNestedLoopsThreeProfiles) {
  const Footprint fp = testing::figure25_analogue();
  std::size_t vertices = 0;
  for (const Loop& loop : fp.loops) vertices += loop.points.size();
  ASSERT_EQ(fp.loops.size(), 24u);
  ASSERT_EQ(vertices, 552u);
  const Surface s = sweep(fp);
  const auto c = expect_valid(s);
  EXPECT_GT(c.volume, 0.0);
  const auto tags = faces_per_tag(s);
  for (const char* tag : {"wall", "soffit", "mansard", "roof"}) EXPECT_GT(tags.count(tag), 0u) << tag;
}

}  // namespace
}  // namespace procex

// Regression: a split event on a steep plane is checked at its own height.
//
// OSM way 178328540 (tests/data/geojson_osm_bay_nearly_parallel_sides.geojson)
// is a long row house whose south wall has small bays with sides 2e-4 rad
// from parallel (inside is above):
//
//   ------+     +------
//         |     |         a bay 1 m deep, 3.3 m wide: its sides close on each
//         +-----+         other at once, over their whole length
//
// Under the corpus test's mansard profile (slope 3 above 6 m) the reflex
// corner at one side of a bay's mouth runs into the far side 4e-6 above the
// other mouth corner's candidate (which misses its span), and both came in one
// height batch (delta2 = 7.8e-6). Checked at the batch's height instead of
// its own, the far side's plane was 3 * 4e-6 from the split point, more than
// delta3, and the split was dropped: the bay's sides crossed over, the loop
// turned inside out and the sweep ran away. Now the roof closes, and it is
// the straight skeleton's.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/prepare.h"
#include "core/geom/tolerances.h"
#include "core/io/geojson.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "tests/support/cgal_skeleton.h"
#include "tests/support/house_profiles.h"
#include "tests/support/validation_text.h"

namespace procex {
namespace {

Footprint row_house_with_bays() {
  const GeoJsonCollection file =
      read_geojson_file(std::string(PROCEX_TEST_DATA) + "/geojson_osm_bay_nearly_parallel_sides.geojson");
  EXPECT_TRUE(file.errors.empty());
  EXPECT_EQ(file.features.size(), 1u);
  return prepare_footprint(to_footprint(file.features.at(0), 45.0)).footprint;
}

Footprint with_house_profile(Footprint fp, int profile) {
  fp.profiles = house_profiles();
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.profile = profile;
  return fp;
}

// With one profile on every edge the cross-section at height z is the
// footprint offset inward by the profile's inward offset there: the straight
// skeleton at time offset(z). Where the profile rises inward, height(t) is its inverse.
double inward_offset(const Profile& p, double z) {
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    const glm::dvec2 a = p.points[i], b = p.points[i + 1];
    if (z <= b.y && b.y > a.y) return -(a.x + (b.x - a.x) * (z - a.y) / (b.y - a.y));
  }
  const glm::dvec2 a = p.points[p.points.size() - 2], b = p.points.back();
  return -(b.x + (b.x - a.x) * (z - b.y) / (b.y - a.y));
}

double height_at_offset(const Profile& p, double t) {
  for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
    const glm::dvec2 a = p.points[i], b = p.points[i + 1];
    if (-b.x >= t && b.x < a.x) return a.y + (b.y - a.y) * (-t - a.x) / (b.x - a.x);
  }
  const glm::dvec2 a = p.points[p.points.size() - 2], b = p.points.back();
  return b.y + (b.y - a.y) * (-t - b.x) / (b.x - a.x);
}

TEST(SweepSteepSplit, MansardProfileOffsetsInvertEachOther) {
  const Profile mansard = house_profiles()[kMansard];
  EXPECT_DOUBLE_EQ(inward_offset(mansard, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(inward_offset(mansard, 4.5), 0.5);
  EXPECT_DOUBLE_EQ(inward_offset(mansard, 6.5), 2.5);
  EXPECT_DOUBLE_EQ(inward_offset(mansard, 8.0), 7.0);  // past the last point, at its slope
  for (double t : {0.25, 1.0, 2.5, 7.0}) EXPECT_NEAR(inward_offset(mansard, height_at_offset(mansard, t)), t, 1e-12);
}

// Expects the surface above height `from` to be the straight skeleton's roof:
// every vertex there, at the offset its height maps to, is a skeleton node,
// and every node past the offset at `from` is a vertex. Returns the number of
// nodes compared.
std::size_t expect_skeleton_roof(const Surface& surface, const std::vector<glm::dvec3>& nodes, double from,
                                 const std::function<double(double)>& offset, double tol) {
  auto near_one = [&](const glm::dvec3& p, const std::vector<glm::dvec3>& set) {
    return std::any_of(set.begin(), set.end(), [&](const glm::dvec3& q) { return glm::distance(p, q) <= tol; });
  };
  std::vector<glm::dvec3> ours;
  for (const glm::dvec3& p : surface.vertices)
    if (p.z > from + tol) ours.push_back({p.x, p.y, offset(p.z)});
  std::size_t compared = 0;
  for (const glm::dvec3& n : nodes) {
    if (n.z <= offset(from) + tol) continue;
    ++compared;
    EXPECT_TRUE(near_one(n, ours)) << "skeleton node (" << n.x << ", " << n.y << ") at time " << n.z
                                   << " is no roof vertex";
  }
  for (const glm::dvec3& p : ours)
    EXPECT_TRUE(near_one(p, nodes)) << "roof vertex (" << p.x << ", " << p.y << ") at offset " << p.z
                                    << " is no skeleton node";
  return compared;
}

double highest(const std::vector<glm::dvec3>& points) {
  double z = 0.0;
  for (const glm::dvec3& p : points) z = std::max(z, p.z);
  return z;
}

void expect_valid(const Surface& surface) {
  ValidationOptions vo;
  vo.check_self_intersections = true;
  const ValidationReport v = validate(build_mesh(surface), vo);
  EXPECT_TRUE(v.ok()) << describe(v);
}

TEST(SweepSteepSplit, RowHouseWithBaysClosesUnderTheMansard) {
  const Footprint fp = with_house_profile(row_house_with_bays(), kMansard);
  const Surface surface = sweep(fp);
  expect_valid(surface);

  // The roof's top is where the skeleton's last node stands (about 7.14 m),
  // and above the mansard's break the roof is the skeleton's.
  const Profile& mansard = fp.profiles[kMansard];
  const std::vector<glm::dvec3> nodes = CgalSkeletonInput(fp).skeleton().nodes;
  ASSERT_FALSE(nodes.empty());
  const double tol = 1e-6 * length_scale(fp);
  const double break_height = mansard.points[2].y;
  EXPECT_NEAR(highest(surface.vertices), height_at_offset(mansard, highest(nodes)), tol);
  EXPECT_GT(highest(surface.vertices), break_height);
  const auto offset = [&](double z) { return inward_offset(mansard, z); };
  EXPECT_GT(expect_skeleton_roof(surface, nodes, break_height, offset, tol), 10u);
}

// The same footprint with every edge at a constant 70 degrees (slope 2.7)
// ran away too: the roof is the skeleton's, at height time / tan(70).
TEST(SweepSteepSplit, RowHouseWithBaysClosesAt70Degrees) {
  Footprint fp = row_house_with_bays();
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.angle_deg = 70.0;
  const Surface surface = sweep(fp);
  expect_valid(surface);

  const double slope = std::tan(70.0 * M_PI / 180.0);
  const std::vector<glm::dvec3> nodes = CgalSkeletonInput(fp).skeleton().nodes;
  ASSERT_FALSE(nodes.empty());
  const double tol = 1e-6 * length_scale(fp);
  EXPECT_NEAR(highest(surface.vertices), highest(nodes) / slope, tol);
  const auto offset = [&](double z) { return slope * z; };
  EXPECT_GT(expect_skeleton_roof(surface, nodes, 0.0, offset, tol), 10u);
}

// The other house profiles close over the same footprint too.
TEST(SweepSteepSplit, RowHouseWithBaysClosesUnderEveryHouseProfile) {
  for (int profile = 0; profile < kHouseProfileCount; ++profile) {
    SCOPED_TRACE(house_profiles()[static_cast<std::size_t>(profile)].name);
    expect_valid(sweep(with_house_profile(row_house_with_bays(), profile)));
  }
}

}  // namespace
}  // namespace procex

// A step whose plan meets the plan below only at a point (generated angles
// finding 541, built in code): a triangle 1 m wide at its top whose long side
// ledges in by exactly 1 m at 3 m, while the other two sides step out. Above
// the step the plan touches the triangle below at its top corner only, so in
// exact terms the solid is two parts pinched at that point. The sweep gives
// each part's fan of faces its own copy of the vertex (core/sweep/
// surface_output.h): the mesh validates, and the two copies sit at one point,
// one used only by faces below the step, the other only by faces above it.
// A step whose plan meets the plan below along a line (generated angles
// findings 62 and 308) is two parts touching along an edge: it has two faces
// each way, paired round it (core/geom/round_edge.h), and each part its own
// copies of the edge's ends.
#include <map>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

TEST(SweepPinch, AStepTouchingThePlanBelowAtAPointGivesEachPartItsOwnVertex) {
  Footprint fp = make_footprint({{{1, 0}, {1, 4}, {0, 4}}}, 45.0);
  fp.profiles = {{"ledge", {{0, 0}, {0, 3}, {-1, 3}, {-1, 6}, {-6, 11}}, {"wall", "ledge", "wall", "roof"}},
                 {"soffit", {{0, 0}, {0, 3}, {0.5, 3}, {-4.5, 8}}, {"wall", "soffit", "roof"}}};
  fp.loops[0].edges[0].profile = 0;
  fp.loops[0].edges[1].profile = 1;
  fp.loops[0].edges[2].profile = 1;
  SweepOptions options;
  options.max_height = 3.8;
  const Surface roof = sweep(fp, options);
  expect_valid(roof);
  for (const std::string& line : check_faces_on_planes(fp, options, roof, roof_tolerance(fp))) ADD_FAILURE() << line;

  std::map<std::vector<double>, std::vector<std::uint32_t>> at;
  for (std::uint32_t v = 0; v < roof.vertices.size(); ++v)
    at[{roof.vertices[v].x, roof.vertices[v].y, roof.vertices[v].z}].push_back(v);
  std::vector<std::uint32_t> copies;
  for (const auto& [p, vs] : at)
    if (vs.size() > 1) copies = vs;
  ASSERT_EQ(copies.size(), 2u) << "one point, the pinch, has two vertices";
  EXPECT_EQ(roof.vertices[copies[0]], glm::dvec3(0, 4, 3));
  // Each copy's faces lie on one side of the step.
  for (std::uint32_t copy : copies) {
    std::set<int> sides;
    for (const SurfaceFace& f : roof.faces)
      for (const auto& loop : f.loops)
        for (std::uint32_t v : loop)
          if (v == copy)
            for (std::uint32_t w : loop) {
              if (roof.vertices[w].z < 3.0 - 1e-9) sides.insert(-1);
              if (roof.vertices[w].z > 3.0 + 1e-9) sides.insert(1);
            }
    EXPECT_EQ(sides.size(), 1u) << "vertex " << copy << " is used by faces below and above the step";
  }
}

TEST(SweepPinch, AStepTouchingThePlanBelowAlongALineGivesEachPartItsOwnEdge) {
  // A 4 x 1 block whose front steps out by its whole depth at 3 m and whose
  // back ledges in by as much: above 3 m the plan is the strip in front,
  // touching the plan below along the front edge only.
  Footprint fp = make_footprint({{{0, 0}, {4, 0}, {4, 1}, {0, 1}}}, 45.0);
  fp.profiles = {{"out", {{0, 0}, {0, 3}, {1, 3}, {1, 6}}, {"wall", "soffit", "wall"}},
                 {"in", {{0, 0}, {0, 3}, {-1, 3}, {-1, 6}}, {"wall", "ledge", "wall"}},
                 {"side", {{0, 0}, {0, 6}}, {"wall"}}};
  const std::vector<int> profile_of_edge = {0, 2, 1, 2};
  for (std::size_t e = 0; e < 4; ++e) fp.loops[0].edges[e].profile = profile_of_edge[e];
  SweepOptions options;
  options.max_height = 6.0;
  const Surface roof = sweep(fp, options);
  expect_valid(roof);
  for (const std::string& line : check_faces_on_planes(fp, options, roof, roof_tolerance(fp))) ADD_FAILURE() << line;
  EXPECT_NEAR(surface_volume(roof), 2 * 4 * 1 * 3, 1e-9);

  std::map<std::vector<double>, int> at;
  for (const glm::dvec3& v : roof.vertices) ++at[{v.x, v.y, v.z}];
  EXPECT_EQ(roof.vertices.size(), 16u) << "two boxes of eight corners each";
  EXPECT_EQ((at[{0, 0, 3}]), 2) << "the touching edge's ends have a copy for each part";
  EXPECT_EQ((at[{4, 0, 3}]), 2);
  std::map<std::string, int> tags = faces_per_tag(roof);
  EXPECT_EQ(tags["soffit"], 1);
  EXPECT_EQ(tags["ledge"], 1);
}

}  // namespace
}  // namespace procex::testing

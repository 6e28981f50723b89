// A step whose plan meets the plan below only at a point (generated angles
// finding 541, built in code): a triangle 1 m wide at its top whose long side
// ledges in by exactly 1 m at 3 m, while the other two sides step out. Above
// the step the plan touches the triangle below at its top corner only, so in
// exact terms the solid is two parts pinched at that point. The sweep gives
// each part's fan of faces its own copy of the vertex (core/sweep/
// surface_output.h): the mesh validates, and the two copies sit at one point,
// one used only by faces below the step, the other only by faces above it.
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

}  // namespace
}  // namespace procex::testing

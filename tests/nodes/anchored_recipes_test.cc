// Recipes that place meshes at anchors the sweep resolves, end to end: the
// sample recipes (samples/windows_grid.pxg, buttresses.pxg, pillars.pxg) are
// loaded, edited through the graph and evaluated, and every placed mesh is
// checked against the footprint it stands on -- counts from the facades'
// lengths, positions on the wall planes, inside the walls -- on the fig. 2
// house, a rectangle, an L and an OpenStreetMap building, and after a
// footprint vertex moves (the persistence problem, paper 3.4).
#include <cmath>
#include <map>

#include <glm/trigonometric.hpp>

#include "core/io/geojson.h"
#include "tests/nodes/anchored_recipe.h"

namespace procex {
namespace {

using test::building;
using test::Extent;
using test::kSamples;
using test::messages;
using test::Recipe;
using test::Wall;
using test::walls_of;

// Instances tagged `tag` (windows_grid.pxg: the attic windows "attic_window",
// the grid's none), by the footprint edge they stand on.
std::map<std::int32_t, std::vector<const Instance*>> by_edge(const TaggedMesh& part, const std::string& tag) {
  std::map<std::int32_t, std::vector<const Instance*>> out;
  for (const Instance& in : part.placed.instances)
    if (in.tag == tag) out[in.source_edge].push_back(&in);
  return out;
}

// windows_grid.pxg: rows of 2 storeys, columns one per 2.5 m of the facade
// less 0.6 m at each corner, rounded down.
std::size_t columns_on(double length) { return static_cast<std::size_t>(std::floor((length - 1.2) / 2.5 + 1e-9)); }

// Every window of the grid lies on its facade's plane (its back on the wall,
// the rest out of it), within the facade's length and the 6 m walls.
void expect_grid_on_walls(const TaggedMesh& part, const std::vector<Wall>& walls, std::size_t rows) {
  const auto windows = by_edge(part, "");
  for (std::size_t e = 0; e < walls.size(); ++e) {
    SCOPED_TRACE("edge " + std::to_string(e));
    const auto it = windows.find(static_cast<std::int32_t>(e));
    const std::size_t count = it == windows.end() ? 0 : it->second.size();
    ASSERT_EQ(count, rows * columns_on(walls[e].length()));
    for (const Instance* in : it->second) {
      const Extent x = extent_on(walls[e], part.placed, *in);
      EXPECT_NEAR(x.out_lo, 0.0, 1e-9);  // on the wall plane
      EXPECT_GT(x.out_hi, 0.1);          // standing out of it
      EXPECT_GE(x.along_lo, 0.6 - 1e-9);
      EXPECT_LE(x.along_hi, walls[e].length() - 0.6 + 1e-9);
      EXPECT_GT(x.z_lo, 0.0);
      EXPECT_LT(x.z_hi, 6.0);
    }
  }
}

TEST(WindowsGrid, EveryFacadeOfTheHouseGetsItsGridAndEachGableAnAtticWindow) {
  Recipe r("windows_grid");
  const EvalResult result = r.run();
  const TaggedMesh& part = building(result);
  const std::vector<Wall> walls = walls_of(r.plan());
  ASSERT_EQ(walls.size(), 6u);
  expect_grid_on_walls(part, walls, 2);
  std::size_t total = 0;
  for (const Wall& w : walls) total += 2 * columns_on(w.length());
  EXPECT_EQ(total, 26u);  // 14, 6, 8, 5, 6 and 11 m facades: 5 + 1 + 2 + 1 + 1 + 3 columns, 2 storeys

  // The gables (edges 1 and 4, 6 m wide) rise to the ridge at 6 + 3 / tan(50 deg): the attic window
  // stands in the triangle, centred, on the gable's plane, every vertex under the roof.
  const auto attic = by_edge(part, "attic_window");
  ASSERT_EQ(attic.size(), 2u);
  const double slope = std::tan(glm::radians(50.0));
  for (const std::int32_t e : {1, 4}) {
    ASSERT_EQ(attic.at(e).size(), 1u);
    const Wall& gable = walls[static_cast<std::size_t>(e)];
    const Instance& in = *attic.at(e)[0];
    const Extent x = extent_on(gable, part.placed, in);
    EXPECT_NEAR(x.out_lo, 0.0, 1e-9);
    EXPECT_NEAR((x.along_lo + x.along_hi) / 2, 3.0, 1e-9);
    EXPECT_NEAR(x.z_lo, 6.3, 1e-9);
    const Mesh& m = *part.placed.meshes[in.mesh].mesh;
    for (const auto v : m.vertices()) {
      const auto p = m.point(v);
      const glm::dvec4 q = in.transform * glm::dvec4(p[0], p[1], p[2], 1.0);
      EXPECT_LT(std::abs(glm::dot(glm::dvec2(q) - gable.a, gable.dir()) - 3.0), 3.0 - (q.z - 6.0) * slope);
    }
  }
  for (const Diagnostic& d : result.diagnostics) EXPECT_NE(d.severity, Severity::kWarning) << d.to_string();
}

TEST(WindowsGrid, AtticWindowsAboveTheRidgeAreAbsentWarnings) {
  Recipe r("windows_grid");
  ASSERT_TRUE(r.g.set_exposed("attic_height", Value::make(9.0)));  // the ridge is at 8.52 m
  const EvalResult result = r.run();
  const TaggedMesh& part = building(result);
  EXPECT_TRUE(by_edge(part, "attic_window").empty());
  EXPECT_EQ(by_edge(part, "").size(), 6u);  // the grid is unchanged
  for (const std::int32_t e : {1, 4}) {
    const std::string extrude = "anchor 'attic' is absent on edge " + std::to_string(e) + ": ";
    const std::string placement = "anchor 'attic' on edge " + std::to_string(e) + " is absent: ";
    std::size_t found = 0;
    for (const Diagnostic& d : result.diagnostics)
      if (d.severity == Severity::kWarning &&
          (d.message.find(extrude) != std::string::npos || d.message.find(placement) != std::string::npos))
        ++found;
    EXPECT_EQ(found, 2u) << "edge " << e << "\n" << messages(result);
  }
}

// One window per facade per storey, in the middle of the facade: the same
// recipe on a rectangle, an L and an OpenStreetMap building.
class OneWindowPerFacade : public ::testing::Test {
 protected:
  Recipe r{"windows_grid"};
  NodeId grid = 0;
  void SetUp() override {
    grid = r.node("Mesh Placement", "anchor", "window");
    r.set(grid, "columns", std::int64_t{1});
    // Every edge walls and a hipped roof: no gables, so the attic anchor resolves
    // absent on every building (a warning) and places nothing.
    r.set(r.node("Assign Profiles"), "rules", std::string("* = wall_hip"));
  }
  void expect_one_per_storey(const std::vector<Vec2>& plan) {
    r.set(r.node("Footprint Polygon"), "points", plan);
    const EvalResult result = r.run();
    const TaggedMesh& part = building(result);
    const std::vector<Wall> walls = walls_of(plan);
    const auto windows = by_edge(part, "");
    ASSERT_EQ(windows.size(), walls.size()) << messages(result);
    for (std::size_t e = 0; e < walls.size(); ++e) {
      SCOPED_TRACE("edge " + std::to_string(e));
      const auto& on = windows.at(static_cast<std::int32_t>(e));
      ASSERT_EQ(on.size(), 2u);
      for (const Instance* in : on) {
        const Extent x = extent_on(walls[e], part.placed, *in);
        EXPECT_NEAR(x.out_lo, 0.0, 1e-6);
        EXPECT_NEAR((x.along_lo + x.along_hi) / 2, walls[e].length() / 2, 1e-6);
      }
      std::vector<double> storeys;
      for (const Instance* in : on) storeys.push_back(extent_on(walls[e], part.placed, *in).z_lo);
      std::sort(storeys.begin(), storeys.end());
      EXPECT_LT(storeys[0], 3.0);
      EXPECT_GT(storeys[1], 3.0);
    }
    EXPECT_TRUE(by_edge(part, "attic_window").empty());
  }
};

TEST_F(OneWindowPerFacade, OnARectangle) { expect_one_per_storey({{0, 0}, {12, 0}, {12, 8}, {0, 8}}); }

TEST_F(OneWindowPerFacade, OnAnL) { expect_one_per_storey({{0, 0}, {16, 0}, {16, 7}, {7, 7}, {7, 13}, {0, 13}}); }

TEST_F(OneWindowPerFacade, OnAnOpenStreetMapBuilding) {
  const GeoJsonCollection block = read_geojson_file(kSamples / "footprints" / "sample_block.geojson");
  // The first feature with more than four corners and no facade too short for a window.
  for (const GeoJsonFeature& f : block.features) {
    if (f.loops.size() != 1 || f.loops[0].size() < 5) continue;
    std::vector<Vec2> plan;
    for (const glm::dvec2& p : f.loops[0]) plan.push_back({p.x, p.y});
    const auto walls = walls_of(plan);
    if (std::any_of(walls.begin(), walls.end(), [](const Wall& w) { return w.length() < 3.0; })) continue;
    SCOPED_TRACE("feature " + f.id);
    expect_one_per_storey(plan);
    return;
  }
  FAIL() << "no suitable feature in sample_block.geojson";
}

// Moving one corner moves the windows of its two edges and no other.
TEST_F(OneWindowPerFacade, MovingACornerMovesTheWindowsOfItsEdgesOnly) {
  const std::vector<Vec2> before = {{0, 0}, {16, 0}, {16, 7}, {7, 7}, {7, 13}, {0, 13}};
  r.set(r.node("Footprint Polygon"), "points", before);
  const EvalResult first = r.run();
  const PlacementResult was = building(first).placed;
  std::vector<Vec2> after = before;
  after[2] = {18, 8};  // the corner between edges 1 and 2
  r.set(r.node("Footprint Polygon"), "points", after);
  const EvalResult second = r.run();
  const PlacementResult& is = building(second).placed;
  ASSERT_EQ(was.instances.size(), is.instances.size());
  for (std::size_t i = 0; i < is.instances.size(); ++i) {
    const std::int32_t e = is.instances[i].source_edge;
    ASSERT_EQ(e, was.instances[i].source_edge);
    const glm::dvec3 moved = glm::dvec3(is.instances[i].transform[3]) - glm::dvec3(was.instances[i].transform[3]);
    if (e == 1 || e == 2) {
      EXPECT_GT(glm::length(moved), 0.5) << "edge " << e;
    } else {
      EXPECT_LT(glm::length(moved), 1e-9) << "edge " << e;
    }
  }
  expect_one_per_storey(after);
}

}  // namespace
}  // namespace procex

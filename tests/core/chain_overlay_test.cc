// The overlay of closed chains: cells, windings and owners on small cases
// whose answers are known by hand (areas, cell counts, which group owns what).
#include "core/geom/chain_overlay.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

namespace procex {
namespace {

// Chains are built from loops of points; each loop is counter-clockwise
// around what it covers (clockwise: it covers negatively).
struct Input {
  std::vector<glm::dvec2> points;
  std::vector<OverlaySegment> segments;

  // One index per position, as the sweep's vertices are.
  std::uint32_t point(glm::dvec2 p) {
    const auto it = std::find(points.begin(), points.end(), p);
    if (it != points.end()) return static_cast<std::uint32_t>(it - points.begin());
    points.push_back(p);
    return static_cast<std::uint32_t>(points.size() - 1);
  }
  void loop(const std::vector<glm::dvec2>& ps, int group) {
    for (std::size_t i = 0; i < ps.size(); ++i) segments.push_back({point(ps[i]), point(ps[(i + 1) % ps.size()]), group});
  }
  ChainOverlay run(double near = 1e-9) const { return overlay_chains(points, segments, near); }
};

double area(const ChainOverlay& o, const OverlayCell& c) {
  double a = 0.0;
  for (std::size_t i = 0; i < c.loop.size(); ++i) {
    const glm::dvec2 p = o.points[c.loop[i]], q = o.points[c.loop[(i + 1) % c.loop.size()]];
    a += p.x * q.y - p.y * q.x;
  }
  return 0.5 * a;
}

// Signed area (outlines positive, holes negative) per (owner, winding).
std::map<std::pair<int, int>, double> areas(const ChainOverlay& o) {
  std::map<std::pair<int, int>, double> out;
  for (const OverlayCell& c : o.cells) out[{c.owner, c.winding}] += area(o, c);
  return out;
}

std::vector<glm::dvec2> square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<glm::dvec2> reversed(std::vector<glm::dvec2> ps) {
  std::reverse(ps.begin(), ps.end());
  return ps;
}

TEST(ChainOverlay, OneSquareIsOneCell) {
  Input in;
  in.loop(square(0, 0, 2, 1), 0);
  const ChainOverlay o = in.run();
  ASSERT_EQ(o.cells.size(), 1u);
  EXPECT_EQ(o.cells[0].winding, 1);
  EXPECT_EQ(o.cells[0].owner, 0);
  EXPECT_DOUBLE_EQ(area(o, o.cells[0]), 2.0);
}

TEST(ChainOverlay, CrossingSquaresOfOneSignSplitWhereTheyOverlap) {
  Input in;
  in.loop(square(0, 0, 2, 2), 0);
  in.loop(square(1, 1, 3, 3), 1);
  const ChainOverlay o = in.run();
  // Two crossings, four new pieces; the overlap winds twice.
  EXPECT_EQ(o.points.size(), 10u);
  const auto a = areas(o);
  EXPECT_DOUBLE_EQ(a.at({0, 1}), 3.0);
  EXPECT_DOUBLE_EQ(a.at({1, 1}), 3.0);
  EXPECT_DOUBLE_EQ(a.at({0, 2}), 1.0);  // the lowest group covering it owns it
  // Each square's edges are cut where the other crosses them.
  std::size_t cut = 0;
  for (const auto& chain : o.pieces) cut += chain.size() - 2;
  EXPECT_EQ(cut, 4u);
}

TEST(ChainOverlay, OppositeWindingsCancelWhereTheyFold) {
  // A ledge (counter-clockwise) and a soffit (clockwise) folded over one
  // another: only what each covers alone is left.
  Input in;
  in.loop(square(0, 0, 4, 1), 0);
  in.loop(reversed(square(3, 0, 5, 1)), 1);
  const ChainOverlay o = in.run();
  const auto a = areas(o);
  EXPECT_DOUBLE_EQ(a.at({0, 1}), 3.0);
  EXPECT_DOUBLE_EQ(a.at({1, -1}), 1.0);
  EXPECT_EQ(a.size(), 2u);
  for (const OverlayCell& c : o.cells) {
    // Every cycle runs with its cell on the left: outlines counter-clockwise.
    EXPECT_GT(area(o, c), 0.0);
  }
}

TEST(ChainOverlay, AnnulusKeepsItsHole) {
  // A ledge all round: the old outline counter-clockwise, the new one inside it clockwise.
  Input in;
  in.loop(square(0, 0, 10, 10), 0);
  in.loop(reversed(square(2, 2, 8, 8)), 0);
  const ChainOverlay o = in.run();
  ASSERT_EQ(o.cells.size(), 2u);  // the outline and the hole
  const auto a = areas(o);
  EXPECT_DOUBLE_EQ(a.at({0, 1}), 100.0 - 36.0);
  EXPECT_EQ(std::count_if(o.cells.begin(), o.cells.end(), [&](const OverlayCell& c) { return area(o, c) < 0.0; }),
            1);
}

TEST(ChainOverlay, IslandInsideAnotherGroupTakesItsWindingFromOutside) {
  // A square of group 1 inside a square of group 0, both counter-clockwise:
  // the inner part winds twice, found through a ray as the parts do not touch.
  Input in;
  in.loop(square(0, 0, 10, 10), 0);
  in.loop(square(4, 4, 6, 6), 1);
  const ChainOverlay o = in.run();
  const auto a = areas(o);
  EXPECT_DOUBLE_EQ(a.at({0, 1}), 96.0);
  EXPECT_DOUBLE_EQ(a.at({0, 2}), 4.0);
}

TEST(ChainOverlay, NeighboursSharingAnEdgeMeetVertexToVertex) {
  // Two faces side by side, one edge of the right one reaching past the
  // left's corner: the long edge is cut at that corner.
  Input in;
  in.loop(square(0, 0, 1, 1), 0);
  in.loop({{1, -1}, {2, -1}, {2, 1}, {1, 1}}, 1);
  const ChainOverlay o = in.run();
  EXPECT_EQ(o.points.size(), 7u);  // no new points: the corner (1, 0) cuts the edge
  bool cut_at_corner = false;
  for (const auto& chain : o.pieces)
    cut_at_corner |= chain.size() == 3 && o.points[chain[1]] == glm::dvec2(1, 0);
  EXPECT_TRUE(cut_at_corner);
  const auto a = areas(o);
  EXPECT_DOUBLE_EQ(a.at({0, 1}), 1.0);
  EXPECT_DOUBLE_EQ(a.at({1, 1}), 2.0);
}

TEST(ChainOverlay, NearlyParallelSegmentsAreCutAtTheEndsNotCrossed) {
  // The right square's left edge leans by less than `near` over its length:
  // it touches the left square's edge, it does not cross it somewhere
  // ill-conditioned.
  const double near = 1e-6;
  Input in;
  in.loop(square(0, 0, 1, 1), 0);
  in.loop({{1.0 - 0.4 * near, 0.5}, {2, 0.5}, {2, 2}, {1.0 + 0.4 * near, 2}}, 1);
  const ChainOverlay o = in.run(near);
  EXPECT_EQ(o.points.size(), 8u);
  const auto a = areas(o);
  EXPECT_NEAR(a.at({0, 1}), 1.0, 1e-6);
  EXPECT_NEAR(a.at({1, 1}), 1.5, 1e-6);
}

TEST(ChainOverlay, SegmentsThatOnlyCutCoverNothing) {
  // A wall's top (group -1) across a ledge: it cuts the ledge's outline where
  // they cross, and gets cut there too, but adds no cell.
  Input in;
  in.loop(square(0, 0, 2, 2), 0);
  in.segments.push_back({in.point({1, -1}), in.point({1, 3}), -1});
  const ChainOverlay o = in.run();
  EXPECT_EQ(o.points.size(), 8u);
  EXPECT_EQ(o.pieces.back().size(), 4u);
  ASSERT_EQ(o.cells.size(), 1u);
  EXPECT_DOUBLE_EQ(area(o, o.cells[0]), 4.0);
  EXPECT_EQ(o.cells[0].loop.size(), 6u);
}

}  // namespace
}  // namespace procex

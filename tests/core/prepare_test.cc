#include "core/geom/prepare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geom/error.h"
#include "core/geom/nesting.h"
#include "core/geom/tolerances.h"
#include "core/io/geojson.h"
#include "core/io/polyjson.h"

namespace procex {
namespace {

const std::string kData = PROCEX_TEST_DATA;

Footprint fixture(const std::string& name) {
  return to_footprint(read_polyjson_file(kData + "/footprint_" + name + ".json").at(0), 45.0);
}

// Runs prepare_footprint and returns the InputError it must throw.
InputError refusal(const Footprint& fp) {
  try {
    prepare_footprint(fp);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("none");
}

// vertices: the vertex the error may name (either end of the offending pair).
void expect_refused(const std::string& name, const std::string& message, int loop, std::vector<int> vertices) {
  SCOPED_TRACE(name);
  const InputError e = refusal(fixture(name));
  EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  EXPECT_EQ(e.loop(), loop) << e.what();
  EXPECT_NE(std::find(vertices.begin(), vertices.end(), e.vertex()), vertices.end()) << e.what();
}

TEST(PrepareFootprint, ValidFootprintPassesUnchanged) {
  const Footprint fp = make_footprint({{{0, 0}, {30, 0}, {30, 22}, {0, 22}}, {{8, 7}, {8, 15}, {22, 15}, {22, 7}}}, 40.0);
  const PreparedFootprint p = prepare_footprint(fp);
  EXPECT_TRUE(p.notes.empty());
  ASSERT_EQ(p.footprint.loops.size(), 2u);
  EXPECT_EQ(p.footprint.loops[1].points, fp.loops[1].points);
  EXPECT_EQ(p.footprint.loops[1].edges[2].id, 6);
}

TEST(PrepareFootprint, RefusesTooFewVertices) {
  expect_refused("fewer_than_3_vertices", "fewer than 3", 0, {0});
  expect_refused("duplicate_vertices_collapse_to_2", "2 distinct vertices", 0, {0});
  EXPECT_EQ(refusal(Footprint{}).loop(), -1);
}

TEST(PrepareFootprint, RefusesCollinearLoops) {
  expect_refused("collinear_zero_area", "loop 0 intersects itself", 0, {0, 1, 2});
}

TEST(PrepareFootprint, RefusesNonFiniteCoordinates) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 10}}, {{2, 2}, {3, 2}, {3, 3}}}, 45.0);
    fp.loops[1].points[2].y = bad;
    const InputError e = refusal(fp);
    EXPECT_EQ(e.loop(), 1);
    EXPECT_EQ(e.vertex(), 2);
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
  }
}

TEST(PrepareFootprint, RefusesBadAngles) {
  for (double bad : {std::nan(""), 90.5, -91.0, std::numeric_limits<double>::infinity()}) {
    Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, 45.0);
    fp.loops[0].edges[3].angle_deg = bad;
    const InputError e = refusal(fp);
    EXPECT_EQ(e.loop(), 0);
    EXPECT_EQ(e.vertex(), 3);
    EXPECT_NE(std::string(e.what()).find("outside [-90, 90]"), std::string::npos) << e.what();
  }
  // The ends of the range are fine: horizontal edges.
  Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, 90.0);
  fp.loops[0].edges[1].angle_deg = -90.0;
  EXPECT_NO_THROW(prepare_footprint(fp));
}

TEST(PrepareFootprint, RefusesMismatchedEdgeCount) {
  Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 10}}}, 45.0);
  fp.loops[0].edges.pop_back();
  EXPECT_NE(std::string(refusal(fp).what()).find("3 points but 2 edges"), std::string::npos);
}

TEST(PrepareFootprint, MergesZeroLengthEdges) {
  const PreparedFootprint p = prepare_footprint(fixture("zero_length_edge"));
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("loop 0 vertex 2"), std::string::npos) << p.notes[0];
  EXPECT_NE(p.notes[0].find("dropping edge id 1"), std::string::npos) << p.notes[0];
  const Loop& loop = p.footprint.loops[0];
  ASSERT_EQ(loop.points.size(), 4u);
  // The merged vertex keeps the outgoing edge of the dropped one.
  EXPECT_EQ(loop.edges[1].id, 2);
  EXPECT_EQ(loop.points[2], glm::dvec2(10, 10));
}

TEST(PrepareFootprint, MergesNearCoincidentVerticesAcrossTheLoopEnd) {
  const Footprint in = fixture("near_coincident_vertices");
  const PreparedFootprint p = prepare_footprint(in);
  EXPECT_EQ(p.notes.size(), 2u) << ::testing::PrintToString(p.notes);
  ASSERT_EQ(p.footprint.loops[0].points.size(), 4u);
  EXPECT_EQ(p.footprint.loops[0].edges.back().id, 4);
  EXPECT_LT(merge_distance(in), 1e-7);
}

TEST(PrepareFootprint, RefusesSelfIntersectingLoops) {
  expect_refused("bowtie", "loop 0 intersects itself", 0, {0, 2});
  expect_refused("spike", "loop 0 intersects itself", 0, {2, 3, 4});
  expect_refused("loop_touches_itself", "loop 0 intersects itself", 0, {1, 2, 4, 5});
}

// Apart only by rounding: a vertex 5e-18 off a non-adjacent edge (the edge
// runs on through it: a needle), and three vertices on one line in decimal
// whose binary area is ~1e-16. Both touch themselves at the rounding of
// their coordinates (~5e-14 here); swept, they made faces with no area or
// that cross (generated classes, grid seed 44 and angles seed 58, minimised).
TEST(PrepareFootprint, RefusesLoopsThatTouchThemselvesByRounding) {
  expect_refused("vertex_on_edge_by_rounding", "loop 0 intersects itself", 0, {0, 1, 3});
  expect_refused("collinear_by_rounding", "loop 0 intersects itself", 0, {0, 1, 2});
  // The same needle a micrometre wide is a shape.
  Footprint wide = fixture("vertex_on_edge_by_rounding");
  wide.loops[0].points[1].y += 1e-6;
  ASSERT_GT(1e-6, 1e6 * rounding_distance(wide));
  EXPECT_NO_THROW(prepare_footprint(wide));
}

TEST(PrepareFootprint, RefusesLoopsThatCrossOrTouch) {
  expect_refused("holes_crossing", "loops 1 and 2 cross or touch", 1, {1, 2});
  expect_refused("hole_crossing_outer", "loops 0 and 1 cross or touch", 0, {1});
  expect_refused("hole_touching_outer", "loops 0 and 1 cross or touch", 0, {0});
  expect_refused("hole_touching_outer_at_vertex", "loops 0 and 1 cross or touch", 0, {2, 3});
}

TEST(PrepareFootprint, FixesOrientationByNestingDepth) {
  const Footprint in = fixture("all_loops_reversed");
  const PreparedFootprint p = prepare_footprint(in);
  EXPECT_EQ(p.notes.size(), 3u) << ::testing::PrintToString(p.notes);
  const LoopNesting nesting = loop_nesting({p.footprint.loops[0].points, p.footprint.loops[1].points,
                                            p.footprint.loops[2].points});
  EXPECT_EQ(nesting.depth, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(nesting.parent, (std::vector<int>{-1, 0, 1}));
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(twice_signed_area(p.footprint.loops[i].points) > 0, nesting.depth[i] % 2 == 0) << "loop " << i;
  // Each edge keeps its spec: the edge between the same two points has the same id.
  for (std::size_t li = 0; li < 3; ++li) {
    const Loop &a = in.loops[li], &b = p.footprint.loops[li];
    const std::size_t n = a.points.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t j = (2 * n - 2 - k) % n;
      EXPECT_EQ(b.points[k], a.points[n - 1 - k]);
      EXPECT_EQ(b.edges[k].id, a.edges[j].id);
      EXPECT_EQ(b.points[(k + 1) % n], a.points[j]);
    }
  }
  const PreparedFootprint two = prepare_footprint(fixture("two_buildings_one_clockwise"));
  ASSERT_EQ(two.notes.size(), 1u);
  EXPECT_NE(two.notes[0].find("loop 1 ran clockwise"), std::string::npos);
}

// Squares inside squares, 0-3 deep, in each cell of a 24 x 24 grid, all in
// one outer square: the loops are found through a hierarchy of their boxes,
// and each must still find every loop around it (the depth) and the nearest
// (the parent), whatever node the outer square's box falls in.
TEST(LoopNesting, FindsEveryLoopAroundEachOfMany) {
  const auto square = [](double x, double y, double side) {
    return std::vector<glm::dvec2>{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  };
  std::vector<std::vector<glm::dvec2>> loops;
  std::vector<int> depth, parent;
  const int k = 24;
  for (int cell = 0; cell < k * k; ++cell) {
    if (cell == k * k / 2) {  // the outer square among the cells' loops, not first
      loops.push_back(square(-1.0, -1.0, 10.0 * k + 2.0));
      depth.push_back(0);
      parent.push_back(-1);
    }
    const double x = 10.0 * (cell % k), y = 10.0 * (cell / k);
    for (int d = 0; d <= cell % 4; ++d) {
      loops.push_back(square(x + d, y + d, 8.0 - 2.0 * d));
      depth.push_back(d + 1);
      parent.push_back(d == 0 ? -2 : static_cast<int>(loops.size()) - 2);  // -2: the outer square, below
    }
  }
  const int outer = static_cast<int>(std::find(depth.begin(), depth.end(), 0) - depth.begin());
  std::replace(parent.begin(), parent.end(), -2, outer);
  const LoopNesting nesting = loop_nesting(loops);
  EXPECT_EQ(nesting.depth, depth);
  EXPECT_EQ(nesting.parent, parent);
}

// The two invalid OSM rings of the Baltimore corpus are refused, naming the loop.
TEST(PrepareFootprint, RefusesTheInvalidOsmRings) {
  const GeoJsonCollection c = read_geojson_file(kData + "/geojson_osm_self_intersecting_baltimore.geojson");
  ASSERT_EQ(c.features.size(), 2u);
  for (const GeoJsonFeature& f : c.features) {
    const InputError e = refusal(to_footprint(f, 45.0));
    EXPECT_EQ(e.loop(), 0) << f.id;
    EXPECT_NE(std::string(e.what()).find("intersects itself"), std::string::npos) << e.what();
  }
}

// Every real footprint except the two invalid rings passes; ~9,500 of them.
TEST(PrepareFootprint, AcceptsTheValidRealCorpus) {
  std::size_t accepted = 0, refused = 0;
  for (const char* file : {"corpus_monaco.geojson", "corpus_manhattan_2015.geojson", "corpus_baltimore_2015.geojson"}) {
    const GeoJsonCollection c = read_geojson_file(std::string(PROCEX_DATA) + "/footprints/" + file);
    for (const GeoJsonFeature& f : c.features) {
      const bool valid = f.property_text("valid") == "true";
      try {
        const PreparedFootprint p = prepare_footprint(to_footprint(f, 45.0));
        EXPECT_TRUE(valid) << f.id;
        EXPECT_TRUE(p.notes.empty()) << f.id << ": " << ::testing::PrintToString(p.notes);
        ++accepted;
      } catch (const InputError& e) {
        EXPECT_FALSE(valid) << f.id << ": " << e.what();
        ++refused;
      }
    }
  }
  EXPECT_EQ(refused, 2u);
  EXPECT_EQ(accepted + refused, 9493u);
}

// Every synthetic case is valid input, including the nearly touching ones.
TEST(PrepareFootprint, AcceptsEverySyntheticCase) {
  const std::string dir = std::string(PROCEX_DATA) + "/synthetic/";
  for (const char* file : {"a_circle_4096.json", "b_image_contours.json", "c_ortho_0200.json", "d_city_6000.json",
                           "e_collinear_rect.json", "e_comb_equal_teeth.json", "e_grid_of_courtyards.json",
                           "e_near_touch_hole.json", "e_near_touch_reflex_pair.json", "e_near_touch_spike.json",
                           "e_nearly_collinear_zigzag.json", "e_plus_equal_arms.json", "e_unit_grid_ortho.json"}) {
    for (const PolyShape& s : read_polyjson_file(dir + file)) {
      const PreparedFootprint p = prepare_footprint(to_footprint(s));
      ASSERT_TRUE(p.notes.empty()) << file << ": " << ::testing::PrintToString(p.notes);
    }
  }
  // The 1.4e-10 edge is below the merge distance and is merged, with a note.
  const PreparedFootprint tiny = prepare_footprint(to_footprint(read_polyjson_file(dir + "e_tiny_edge.json")[0]));
  EXPECT_EQ(tiny.notes.size(), 1u);
  EXPECT_EQ(tiny.footprint.loops[0].points.size(), 5u);
}

TEST(Tolerances, ScaleWithTheFootprint) {
  const Footprint mm = make_footprint({{{0, 0}, {3000, 0}, {3000, 4000}}}, 45.0);
  const Footprint km = make_footprint({{{0, 0}, {0.003, 0}, {0.003, 0.004}}}, 45.0);
  EXPECT_DOUBLE_EQ(length_scale(mm), 5000.0);
  EXPECT_NEAR(merge_distance(mm) / merge_distance(km), 1e6, 1e-3);
  EXPECT_EQ(length_scale(Footprint{}), 0.0);
}

}  // namespace
}  // namespace procex

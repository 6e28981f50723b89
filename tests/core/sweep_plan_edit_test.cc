// Plan edits: forced and natural steps spliced into the cross-section at an
// anchor's height. Every result validates as a closed, oriented, planar
// 2-manifold; volumes and face counts are checked against numbers worked out
// by hand; edits that do not fit are absent with a reason, malformed ones are
// refused naming the edit.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/geom/footprint.h"
#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"

namespace procex {
namespace {

using testing::expect_valid;
using testing::faces_per_tag;

// A 20 x 10 box: every edge vertical, capped at 6 m.
Footprint box() { return make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 0.0); }

// A 20 x 10 house: walls to 3 m, then a 45 degree hip roof (ridge at 8 m).
const Profile kHip{"hip", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}};
Footprint house(std::vector<Profile> extra = {}) {
  Footprint fp = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 45.0);
  fp.profiles = {kHip};
  fp.profiles.insert(fp.profiles.end(), extra.begin(), extra.end());
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = 0;
  return fp;
}

EdgeSpec vertical(std::int32_t id) { return {0.0, id, -1}; }
EdgeSpec following(int profile, std::int32_t id) { return {0.0, id, profile}; }

PlanEdit forced(std::string name, double fraction, double height, std::vector<glm::dvec2> shape,
                std::vector<EdgeSpec> edges, std::vector<std::int32_t> on = {0}) {
  PlanEdit e;
  e.name = std::move(name);
  e.at = {"", {PlanAnchor::Mode::Fraction, fraction}, height, -1, std::move(on)};
  e.kind = PlanEdit::Kind::Forced;
  e.shape = std::move(shape);
  e.edges = std::move(edges);
  return e;
}

PlanEdit natural(std::string name, double fraction, double height, double width, double depth,
                 std::vector<EdgeSpec> edges, std::vector<std::int32_t> on = {0}) {
  PlanEdit e;
  e.name = std::move(name);
  e.at = {"", {PlanAnchor::Mode::Fraction, fraction}, height, -1, std::move(on)};
  e.kind = PlanEdit::Kind::Natural;
  e.width = width;
  e.depth = depth;
  e.edges = std::move(edges);
  return e;
}

Surface sweep_edits(const Footprint& fp, std::vector<PlanEdit> edits, std::optional<double> cap = {}) {
  SweepOptions o;
  o.max_height = cap;
  o.plan_edits = std::move(edits);
  return sweep(fp, o);
}

const std::vector<glm::dvec2> kBay{{-2, 0}, {-2, 1}, {2, 1}, {2, 0}};
const std::vector<glm::dvec2> kRecess{{-2, 0}, {-2, -1}, {2, -1}, {2, 0}};

TEST(PlanEdits, ForcedOrielFromTheFirstFloor) {
  // A 4 x 1 box stands out of the front wall from 2 m up to the 6 m cap.
  const Surface s = sweep_edits(box(), {forced("oriel", 0.5, 2.0, kBay, {vertical(10), vertical(11), vertical(12)})}, 6.0);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 20 * 10 * 6 + 4 * 1 * 4, 1e-9);
  ASSERT_EQ(s.plan_edits.size(), 1u);
  EXPECT_TRUE(s.plan_edits[0].present) << s.plan_edits[0].reason;
  EXPECT_NEAR(s.plan_edits[0].frame.origin.x, 10.0, 1e-12);
  EXPECT_NEAR(s.plan_edits[0].frame.origin.z, 2.0, 1e-12);
  // Its floor faces down, 2 m up, 4 x 1.
  int floors = 0;
  for (const SurfaceFace& f : s.faces) {
    if (f.tag != "step") continue;
    ++floors;
    for (auto v : f.loops[0]) EXPECT_NEAR(s.vertices[v].z, 2.0, 1e-12);
  }
  EXPECT_EQ(floors, 1);
  EXPECT_EQ(faces_per_tag(s).at(""), 4 + 3);
}

TEST(PlanEdits, ForcedRecessFacesUp) {
  const Surface s = sweep_edits(box(), {forced("loggia", 0.5, 2.0, kRecess, {vertical(10), vertical(11), vertical(12)})}, 6.0);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 20 * 10 * 6 - 4 * 1 * 4, 1e-9);
}

TEST(PlanEdits, ForcedStepOnTheFootprintChangesTheBase) {
  // At height 0 the step is part of the footprint: one base face, no step face.
  const Surface s = sweep_edits(box(), {forced("bay", 0.5, 0.0, kBay, {vertical(10), vertical(11), vertical(12)})}, 6.0);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, (20 * 10 + 4) * 6, 1e-9);
  EXPECT_EQ(faces_per_tag(s).count("step"), 0u);
  int bases = 0;
  for (const SurfaceFace& f : s.faces) bases += f.kind == FaceKind::Base;
  EXPECT_EQ(bases, 1);
}

TEST(PlanEdits, ButtressesOnEveryWallUnderAHipRoof) {
  // A 1 x 0.6 buttress at the middle of each wall, rising 2 m then leaning
  // back into the wall at 60 degrees: one edit selecting every edge.
  const Profile buttress{"buttress", {{0, 0}, {0, 2}, {-2, 2 + 2 / std::tan(M_PI / 3)}}, {"buttress", "buttress top"}};
  PlanEdit e = forced("buttress", 0.5, 0.0, {{-0.5, 0}, {-0.5, 0.6}, {0.5, 0.6}, {0.5, 0}},
                      {following(1, 10), following(1, 11), following(1, 12)}, {});
  const Surface s = sweep_edits(house({buttress}), {e});
  const auto c = expect_valid(s);
  ASSERT_EQ(s.plan_edits.size(), 4u);
  for (const ResolvedAnchor& r : s.plan_edits) EXPECT_TRUE(r.present) << r.reason;
  EXPECT_GT(c.volume, 600.0 + 100.0 * 50.0 / 12.0);
  EXPECT_NEAR(c.max_height, 8.0, 1e-9);
  EXPECT_EQ(faces_per_tag(s).at("buttress"), 12);
}

TEST(PlanEdits, NaturalBayGrowsOutOfTheWall) {
  // Grown from a sliver, a 4 x 1 bay from 2 m: the same solid as the forced one.
  const Surface s = sweep_edits(box(), {natural("bay", 0.5, 2.0, 4.0, 1.0, {vertical(10), vertical(11), vertical(12)})}, 6.0);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 20 * 10 * 6 + 4 * 1 * 4, 1e-6);
  // Its floor is one face: the sliver it grew from joined it.
  EXPECT_EQ(faces_per_tag(s).at("step"), 1);
}

TEST(PlanEdits, NaturalRecessGrowsIn) {
  const Surface s = sweep_edits(box(), {natural("recess", 0.5, 2.0, 4.0, -1.0, {vertical(10), vertical(11), vertical(12)})}, 6.0);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 20 * 10 * 6 - 4 * 1 * 4, 1e-6);
}

TEST(PlanEdits, NaturalStepOnTheFootprintIsPartOfTheBase) {
  const Surface s = sweep_edits(box(), {natural("bay", 0.5, 0.0, 4.0, 1.0, {vertical(10), vertical(11), vertical(12)})}, 6.0);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, (20 * 10 + 4) * 6, 1e-6);
  EXPECT_EQ(faces_per_tag(s).count("step"), 0u);
}

TEST(PlanEdits, StepsAtOneHeightAreSplicedBeforeAnyGrows) {
  // At the footprint: two natural bays side by side on the front and a forced
  // recess at the back; at 2 m a third bay between the first two.
  std::vector<PlanEdit> edits;
  for (double offset : {-5.0, 5.0}) {
    edits.push_back(natural("bay", 0.5, 0.0, 3.0, 1.0, {vertical(10), vertical(11), vertical(12)}));
    edits.back().offset = offset;
  }
  edits.push_back(forced("recess", 0.5, 0.0, {{-0.75, 0}, {-0.75, -0.8}, {0.75, -0.8}, {0.75, 0}},
                         {vertical(20), vertical(21), vertical(22)}, {2}));
  edits.push_back(natural("oriel", 0.5, 2.0, 2.0, 1.0, {vertical(30), vertical(31), vertical(32)}));
  const Surface s = sweep_edits(box(), edits, 6.0);
  const auto c = expect_valid(s);
  for (const ResolvedAnchor& r : s.plan_edits) EXPECT_TRUE(r.present) << r.name << ": " << r.reason;
  EXPECT_NEAR(c.volume, 20 * 10 * 6 + 2 * 3 * 1 * 6 - 1.5 * 0.8 * 6 + 2 * 1 * 4, 1e-6);
  int bases = 0;
  for (const SurfaceFace& f : s.faces) bases += f.kind == FaceKind::Base;
  EXPECT_EQ(bases, 1);
}

TEST(PlanEdits, NaturalStepStaysSimpleWhereItRunsIntoTheBuilding) {
  // A U-shaped footprint with a 4 m wide courtyard: a bay 6 m deep out of
  // the inner wall of the right arm (edge 3, x = 8) would cut through the
  // left arm; grown naturally it becomes a bridge that stops at its wall.
  const Footprint u = make_footprint({{{0, 0}, {12, 0}, {12, 10}, {8, 10}, {8, 4}, {4, 4}, {4, 10}, {0, 10}}}, 0.0);
  const Surface s = sweep_edits(u, {natural("bridge", 0.5, 2.0, 2.0, 6.0, {vertical(10), vertical(11), vertical(12)}, {3})}, 5.0);
  expect_valid(s);
  ASSERT_EQ(s.plan_edits.size(), 1u);
  EXPECT_TRUE(s.plan_edits[0].present) << s.plan_edits[0].reason;
}

TEST(PlanEdits, DormerOnAHipRoof) {
  // At the eaves (3 m), a 3 m wide dormer rises with vertical cheeks and front
  // to 4.5 m, then a 45 degree roof of its own.
  const Profile dormer{"dormer", {{0, 0}, {0, 1.5}, {-3, 4.5}}, {"dormer wall", "dormer roof"}};
  const Surface plain = sweep(house());
  const double house_volume = testing::check_surface(plain, 1e-6).volume;
  const Surface s = sweep_edits(house({dormer}), {natural("dormer", 0.5, 3.0, 3.0, 0.3,
                                                          {following(1, 10), following(1, 11), following(1, 12)})});
  const auto c = expect_valid(s);
  EXPECT_GT(c.volume, house_volume);
  EXPECT_NEAR(c.max_height, 8.0, 1e-9);
  EXPECT_EQ(faces_per_tag(s).at("dormer wall"), 3);
}

TEST(PlanEdits, RowOfDormersAndAnInverseDormer) {
  const Profile dormer{"dormer", {{0, 0}, {0, 1.5}, {-3, 4.5}}, {"dormer wall", "dormer roof"}};
  // One anchor mid-front, three copies 5 m apart: the later copies find their
  // place on the spans the earlier ones left.
  std::vector<PlanEdit> edits;
  for (double offset : {-5.0, 0.0, 5.0}) {
    edits.push_back(natural("dormer", 0.5, 3.0, 2.0, 0.3, {following(1, 10), following(1, 11), following(1, 12)}));
    edits.back().offset = offset;
  }
  // The inverse dormer: a recess into the back roof at the eaves, walls vertical for 1.2 m.
  const Profile inverse{"inverse", {{0, 0}, {0, 1.2}, {-3, 4.2}}, {"recess wall", "recess roof"}};
  edits.push_back(forced("inverse dormer", 0.5, 3.0, {{-1.5, 0}, {-1.5, -1.0}, {1.5, -1.0}, {1.5, 0}},
                         {following(2, 20), following(2, 21), following(2, 22)}, {2}));
  const Surface s = sweep_edits(house({dormer, inverse}), edits);
  expect_valid(s);
  ASSERT_EQ(s.plan_edits.size(), 4u);
  for (const ResolvedAnchor& r : s.plan_edits) EXPECT_TRUE(r.present) << r.reason;
  EXPECT_NEAR(s.plan_edits[0].frame.origin.x, 5.0, 1e-9);
  EXPECT_NEAR(s.plan_edits[2].frame.origin.x, 15.0, 1e-9);
  EXPECT_EQ(faces_per_tag(s).at("dormer wall"), 9);
  EXPECT_EQ(faces_per_tag(s).at("recess wall"), 3);
}

TEST(PlanEdits, EditsFollowTheFootprint) {
  // One bay in the middle of every wall at 1 m, on a rectangle and an L; then
  // the rectangle's corner (20, 10) moves to (26, 12): the bays of its two
  // edges move to their new middles, the others stay.
  auto bays = [](const Footprint& fp) {
    PlanEdit e = natural("bay", 0.5, 1.0, 1.0, 0.5, {vertical(10), vertical(11), vertical(12)}, {});
    const Surface s = sweep_edits(fp, {e}, 4.0);
    expect_valid(s);
    std::vector<glm::dvec3> at;
    for (const ResolvedAnchor& r : s.plan_edits) {
      EXPECT_TRUE(r.present) << r.reason;
      at.push_back(r.frame.origin);
    }
    return at;
  };
  const Footprint rect = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 0.0);
  const Footprint moved = make_footprint({{{0, 0}, {20, 0}, {26, 12}, {0, 10}}}, 0.0);
  const Footprint l = make_footprint({{{0, 0}, {12, 0}, {12, 4}, {4, 4}, {4, 12}, {0, 12}}}, 0.0);
  const auto a = bays(rect), b = bays(moved), c = bays(l);
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(b.size(), 4u);
  ASSERT_EQ(c.size(), 6u);
  EXPECT_EQ(a[0], glm::dvec3(10, 0, 1));
  EXPECT_EQ(b[0], a[0]);
  EXPECT_NEAR(b[1].x, 23.0, 1e-9);
  EXPECT_NEAR(b[1].y, 6.0, 1e-9);
  EXPECT_NEAR(b[2].x, 13.0, 1e-9);
  EXPECT_NEAR(b[2].y, 11.0, 1e-9);
  EXPECT_EQ(b[3], a[3]);
  EXPECT_NEAR(c[2].x, 8.0, 1e-9);  // the L's inner wall (12, 4) -> (4, 4)
  EXPECT_NEAR(c[2].y, 4.0, 1e-9);
}

TEST(PlanEdits, AStepThatDoesNotFitIsAbsent) {
  // 30 m wide on a 20 m wall; and on the roof at 7 m where the front edge is 10 m long.
  const Surface s = sweep_edits(house(), {natural("too wide", 0.5, 1.0, 30.0, 1.0, {vertical(10), vertical(11), vertical(12)}),
                                          forced("high", 0.5, 7.0, {{-6, 0}, {-6, 1}, {6, 1}, {6, 0}},
                                                 {vertical(10), vertical(11), vertical(12)})});
  expect_valid(s);
  ASSERT_EQ(s.plan_edits.size(), 2u);
  EXPECT_FALSE(s.plan_edits[0].present);
  EXPECT_NE(s.plan_edits[0].reason.find("does not fit"), std::string::npos) << s.plan_edits[0].reason;
  EXPECT_FALSE(s.plan_edits[1].present);
}

TEST(PlanEdits, AForcedStepThatWouldCrossTheBuildingIsAbsent) {
  // A U with a 4 m courtyard: a bay 6 m out of the inner wall of one arm
  // would run through the other arm's wall (edge 5, x = 4).
  const Footprint u = make_footprint({{{0, 0}, {12, 0}, {12, 10}, {8, 10}, {8, 4}, {4, 4}, {4, 10}, {0, 10}}}, 0.0);
  const Surface s = sweep_edits(u, {forced("through", 0.5, 2.0, {{-1, 0}, {-1, 6}, {1, 6}, {1, 0}},
                                           {vertical(10), vertical(11), vertical(12)}, {3}),
                                    forced("zigzag", 0.5, 2.0, {{-1, 0}, {1, 1}, {1, -1}, {-1, 1}, {1.5, 0}},
                                           {vertical(10), vertical(11), vertical(12), vertical(13)}, {0})},
                                5.0);
  expect_valid(s);
  ASSERT_EQ(s.plan_edits.size(), 2u);
  EXPECT_FALSE(s.plan_edits[0].present);
  EXPECT_NE(s.plan_edits[0].reason.find("crosses the building's outline (edge 5)"), std::string::npos)
      << s.plan_edits[0].reason;
  EXPECT_FALSE(s.plan_edits[1].present);
  EXPECT_NE(s.plan_edits[1].reason.find("crosses itself"), std::string::npos) << s.plan_edits[1].reason;
}

TEST(PlanEdits, AboveTheRoofIsAbsent) {
  const Surface s = sweep_edits(house(), {forced("sky", 0.5, 20.0, kBay, {vertical(10), vertical(11), vertical(12)})});
  ASSERT_EQ(s.plan_edits.size(), 1u);
  EXPECT_FALSE(s.plan_edits[0].present);
  EXPECT_FALSE(s.plan_edits[0].reason.empty());
}

TEST(PlanEdits, MalformedEditsAreRefusedByName) {
  auto refused = [](PlanEdit e, const std::string& words) {
    try {
      sweep_edits(box(), {std::move(e)}, 6.0);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InputError& err) {
      const std::string what = err.what();
      EXPECT_NE(what.find("plan edit 'bad'"), std::string::npos) << what;
      EXPECT_NE(what.find(words), std::string::npos) << what;
    }
  };
  const std::vector<EdgeSpec> three{vertical(1), vertical(2), vertical(3)};
  refused(forced("bad", 0.5, 1.0, {{-1, 0}, {-1, 1}, {1, 1}, {1, 0.5}}, three), "start and end on the edge");
  refused(forced("bad", 0.5, 1.0, {{1, 0}, {1, 1}, {-1, 1}, {-1, 0}}, three), "further along");
  refused(forced("bad", 0.5, 1.0, kBay, {vertical(1)}), "gives 1 edge specs");
  refused(forced("bad", 0.5, 1.0, {{-1, 0}, {NAN, 1}, {1, 0}}, {vertical(1), vertical(2)}), "not finite");
  refused(natural("bad", 0.5, 1.0, 0.0, 1.0, three), "width");
  refused(natural("bad", 0.5, 1.0, 2.0, 0.0, three), "depth");
  refused(natural("bad", 1.5, 1.0, 2.0, 1.0, three), "fraction");
  refused(natural("bad", 0.5, 1.0, 2.0, 1.0, {following(4, 1), vertical(2), vertical(3)}), "names profile 4");
  refused(natural("bad", 0.5, 1.0, 2.0, 1.0, three, {99}), "selects no edge");
}

}  // namespace
}  // namespace procex

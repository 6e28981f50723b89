// Repetition: counts and positions for N and every-d cases on spans of
// different lengths, rows between frames, rows on an anchor's span, grids.
#include <cmath>

#include <gtest/gtest.h>

#include "core/placement/placement_error.h"
#include "core/placement/repeat.h"

namespace procex {
namespace {

std::vector<double> positions(double length, const Repeat& r) {
  std::vector<double> out;
  for (const Slot& s : repeat_line(length, r)) out.push_back(s.position);
  return out;
}

void expect_positions(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size()) << testing::PrintToString(got);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << i;
}

Repeat count(int n, Repeat::Layout layout = Repeat::Layout::Cells) {
  Repeat r;
  r.count = n;
  r.layout = layout;
  return r;
}

Repeat every(double d, Repeat::Rounding rounding = Repeat::Rounding::Down, Repeat::Layout layout = Repeat::Layout::Cells) {
  Repeat r;
  r.spacing = d;
  r.rounding = rounding;
  r.layout = layout;
  return r;
}

//   |--x--|--x--|--x--|--x--|   10 m, 4 cells: items at cell centres
TEST(Repeat, CountCells) {
  expect_positions(positions(10, count(4)), {1.25, 3.75, 6.25, 8.75});
  EXPECT_DOUBLE_EQ(repeat_line(10, count(4))[0].pitch, 2.5);
  Repeat r = count(4);
  r.margin_start = 1.5;
  r.margin_end = 0.5;  // usable 10 m from 1.5
  expect_positions(positions(12, r), {2.75, 5.25, 7.75, 10.25});
}

//   x-----x-----x-----x-----x   10 m, 5 items from end to end
TEST(Repeat, CountEnds) {
  expect_positions(positions(10, count(5, Repeat::Layout::Ends)), {0, 2.5, 5, 7.5, 10});
  expect_positions(positions(10, count(1, Repeat::Layout::Ends)), {5});
  expect_positions(positions(10, count(2, Repeat::Layout::Ends)), {0, 10});
}

TEST(Repeat, SpacingCountFollowsTheFacadeLength) {
  // Down: never closer than 3 m; the cells stretch to fill the facade.
  const double lengths[] = {2.9, 6, 8.9, 9, 12, 14.9};
  const std::size_t counts[] = {0, 2, 2, 3, 4, 4};
  for (int i = 0; i < 6; ++i) {
    const auto slots = repeat_line(lengths[i], every(3));
    ASSERT_EQ(slots.size(), counts[i]) << lengths[i];
    for (const Slot& s : slots) EXPECT_GE(s.pitch, 3.0);
  }
  expect_positions(positions(10, every(3)), {10.0 / 6, 5, 10 - 10.0 / 6});
}

TEST(Repeat, RoundingRules) {
  using R = Repeat::Rounding;
  EXPECT_EQ(repeat_line(10, every(3, R::Nearest)).size(), 3u);   // 3.33
  EXPECT_EQ(repeat_line(11, every(3, R::Nearest)).size(), 4u);   // 3.67
  EXPECT_EQ(repeat_line(10.5, every(3, R::Nearest)).size(), 4u); // 3.5: halves round up
  EXPECT_EQ(repeat_line(10, every(3, R::Up)).size(), 4u);
  EXPECT_EQ(repeat_line(9, every(3, R::Up)).size(), 3u);
  EXPECT_EQ(repeat_line(9 + 1e-12, every(3, R::Up)).size(), 3u);  // within kRepeatCountRelative: exactly 3
  EXPECT_EQ(repeat_line(0.3, every(0.1, R::Down)).size(), 3u);    // 0.3 / 0.1 = 2.9999999999999996
  EXPECT_DOUBLE_EQ(repeat_line(10, every(3, R::Up))[0].pitch, 2.5);
}

// Without fill the pitch is exactly d and the group is centred:
//   |.5|--x--|--x--|--x--|.5|   10 m at 3 m
TEST(Repeat, ExactSpacingCentresTheGroup) {
  Repeat r = every(3);
  r.fill = false;
  expect_positions(positions(10, r), {2, 5, 8});
  r.layout = Repeat::Layout::Ends;
  expect_positions(positions(10, r), {0.5, 3.5, 6.5, 9.5});
}

TEST(Repeat, SpacingEnds) {
  const auto slots = repeat_line(10, every(3, Repeat::Rounding::Down, Repeat::Layout::Ends));
  expect_positions(positions(10, every(3, Repeat::Rounding::Down, Repeat::Layout::Ends)), {0, 10.0 / 3, 20.0 / 3, 10});
  EXPECT_DOUBLE_EQ(slots[0].pitch, 10.0 / 3);
  // Shorter than one interval: one item in the middle.
  const auto one = repeat_line(2, every(3, Repeat::Rounding::Down, Repeat::Layout::Ends));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_DOUBLE_EQ(one[0].position, 1);
  EXPECT_DOUBLE_EQ(one[0].pitch, 2);
}

TEST(Repeat, MarginsLongerThanTheLine) {
  Repeat r = count(3);
  r.margin_start = r.margin_end = 2;
  EXPECT_TRUE(repeat_line(3.9, r).empty());
  EXPECT_TRUE(repeat_line(4, r).empty());  // usable 0: no cells
  r.layout = Repeat::Layout::Ends;
  expect_positions(positions(4, r), {2});  // usable 0: one item
}

TEST(Repeat, BadRequestsAreRefused) {
  EXPECT_THROW(repeat_line(10, Repeat{}), PlacementError);  // neither count nor spacing
  EXPECT_THROW(repeat_line(10, count(-1)), PlacementError);
  EXPECT_THROW(repeat_line(std::nan(""), count(2)), PlacementError);
  EXPECT_THROW(repeat_line(10, every(-1)), PlacementError);
  EXPECT_THROW(repeat_line(1e6, every(1e-3)), PlacementError);  // a million items
}

Frame wall_frame(const glm::dvec3& origin) {
  Frame f;
  f.origin = origin;
  return f;  // along +x, up +z, normal -y
}

TEST(Repeat, BetweenTwoFrames) {
  const auto cells = repeat_between(wall_frame({0, 0, 2}), wall_frame({8, 0, 2}), count(4, Repeat::Layout::Ends));
  ASSERT_EQ(cells.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(cells[static_cast<std::size_t>(i)].frame.origin.x, 8.0 * i / 3, 1e-12);
    EXPECT_EQ(cells[static_cast<std::size_t>(i)].frame.origin.z, 2);
    EXPECT_EQ(cells[static_cast<std::size_t>(i)].column, i);
    EXPECT_EQ(cells[static_cast<std::size_t>(i)].frame.normal, glm::dvec3(0, -1, 0));
  }
}

ResolvedAnchor anchor_on_wall() {
  ResolvedAnchor a;
  a.name = "sill";
  a.edge_id = 0;
  a.present = true;
  a.frame = wall_frame({3, 0, 1});
  a.span_from = {10, 0, 1};  // given end first: ordered along the frame's `along` anyway
  a.span_to = {0, 0, 1};
  return a;
}

TEST(Repeat, OnAnAnchorsSpan) {
  const auto cells = repeat_on_span(anchor_on_wall(), count(5));
  ASSERT_EQ(cells.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(cells[static_cast<std::size_t>(i)].frame.origin.x, 1 + 2 * i, 1e-12);
    EXPECT_EQ(cells[static_cast<std::size_t>(i)].frame.origin.z, 1);
    EXPECT_EQ(cells[static_cast<std::size_t>(i)].width, 2);
    EXPECT_EQ(cells[static_cast<std::size_t>(i)].height, 0);
  }
  ResolvedAnchor absent = anchor_on_wall();
  absent.present = false;
  EXPECT_TRUE(repeat_on_span(absent, count(5)).empty());
}

TEST(Repeat, GridOnAWall) {
  // 10 m wide, rows between z 0 and 9: 4 columns every 2.5 m, 3 rows.
  const auto cells = repeat_grid(anchor_on_wall(), 0, 9, every(2.5), count(3));
  ASSERT_EQ(cells.size(), 12u);
  const Cell& c = cells[4 + 2];  // row 1, column 2
  EXPECT_EQ(c.row, 1);
  EXPECT_EQ(c.column, 2);
  EXPECT_NEAR(c.frame.origin.x, 6.25, 1e-12);
  EXPECT_NEAR(c.frame.origin.y, 0, 1e-12);
  EXPECT_NEAR(c.frame.origin.z, 4.5, 1e-12);
  EXPECT_DOUBLE_EQ(c.width, 2.5);
  EXPECT_DOUBLE_EQ(c.height, 3);
}

TEST(Repeat, GridRowsFollowASlope) {
  ResolvedAnchor a = anchor_on_wall();
  a.frame.origin = {5, 0, 0};
  a.frame.up = {0, 0.6, 0.8};
  a.frame.normal = {0, -0.8, 0.6};
  a.span_from = {0, 0, 0};
  a.span_to = {10, 0, 0};
  // z 0..4 is 5 m up the slope: two rows centred 1.25 and 3.75 m up it.
  const auto cells = repeat_grid(a, 0, 4, count(1), count(2));
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_NEAR(cells[0].frame.origin.y, 0.75, 1e-12);
  EXPECT_NEAR(cells[0].frame.origin.z, 1.0, 1e-12);
  EXPECT_NEAR(cells[1].frame.origin.y, 2.25, 1e-12);
  EXPECT_NEAR(cells[1].frame.origin.z, 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(cells[1].height, 2.5);
}

TEST(Repeat, GridErrors) {
  EXPECT_THROW(repeat_grid(anchor_on_wall(), 5, 1, count(2), count(2)), PlacementError);
  ResolvedAnchor flat = anchor_on_wall();
  flat.frame.up = {0, 1, 0};
  flat.frame.normal = {0, 0, 1};
  try {
    repeat_grid(flat, 0, 3, count(2), count(2));
    FAIL() << "a grid on a horizontal face was accepted";
  } catch (const PlacementError& e) {
    EXPECT_NE(std::string(e.what()).find("anchor 'sill' (edge 0)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace procex

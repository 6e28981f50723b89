// Which pixels a frame must redraw: nothing for an unchanged frame, the
// triangles that changed, whole lists whose shape changed, lists that came or
// went, images whose texture was redrawn; everything at first and on resize.
#include "app/studio/editor/frame_damage.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <glm/common.hpp>

namespace procex::studio {
namespace {

const Rect kScreen{{0, 0}, {800, 600}};

// A window's list of axis-aligned quads (two triangles each), one command.
DrawList quads(const std::string& owner, const std::vector<Rect>& rects, std::uint32_t col = 0xffffffff, std::uintptr_t texture = 1) {
  DrawList l;
  l.owner = owner;
  for (const Rect& r : rects) {
    const auto base = static_cast<std::uint16_t>(l.vertices.size());
    l.vertices.push_back({r.min.x, r.min.y, 0, 0, col});
    l.vertices.push_back({r.max.x, r.min.y, 0, 0, col});
    l.vertices.push_back({r.max.x, r.max.y, 0, 0, col});
    l.vertices.push_back({r.min.x, r.max.y, 0, 0, col});
    for (int k : {0, 1, 2, 0, 2, 3}) l.indices.push_back(static_cast<std::uint16_t>(base + k));
  }
  l.commands.push_back({kScreen, texture, 0, static_cast<std::uint32_t>(l.indices.size()), 0});
  return l;
}

// The damage, one rectangle expected: its bounds.
Rect only(const std::vector<Rect>& damage) {
  EXPECT_EQ(damage.size(), 1u);
  return damage.empty() ? Rect{} : damage[0];
}

TEST(FrameDamage, FirstFrameAndResizeRedrawEverythingAnUnchangedFrameNothing) {
  FrameDamage d;
  const DrawList w = quads("Nodes", {{{10, 10}, {100, 50}}, {{200, 10}, {300, 50}}});
  EXPECT_EQ(only(d.update({w}, kScreen)), kScreen);
  EXPECT_TRUE(d.update({w}, kScreen).empty());
  const Rect bigger{{0, 0}, {1024, 768}};
  EXPECT_EQ(only(d.update({w}, bigger)), bigger);
  d.reset();
  EXPECT_EQ(only(d.update({w}, bigger)), bigger);
}

TEST(FrameDamage, OnlyTheChangedQuadIsRedrawn) {
  FrameDamage d;
  DrawList w = quads("Nodes", {{{10, 10}, {100, 50}}, {{200, 10}, {300, 50}}});
  d.update({w}, kScreen);
  for (std::size_t v = 4; v < 8; ++v) w.vertices[v].col = 0xff0000ff;  // the second quad turns red
  EXPECT_EQ(only(d.update({w}, kScreen)), (Rect{{200, 10}, {300, 50}}));
}

TEST(FrameDamage, AMovedQuadDamagesWhereItWasAndWhereItIs) {
  FrameDamage d;
  d.update({quads("Nodes", {{{10, 10}, {100, 50}}})}, kScreen);
  const auto damage = d.update({quads("Nodes", {{{10, 110}, {100, 150}}})}, kScreen);
  ASSERT_FALSE(damage.empty());
  Rect all = damage[0];
  for (const Rect& r : damage) all = {glm::min(all.min, r.min), glm::max(all.max, r.max)};
  EXPECT_EQ(all, (Rect{{10, 10}, {100, 150}}));
}

TEST(FrameDamage, ListsThatChangeShapeComeOrGoAreRedrawnWhole) {
  FrameDamage d;
  const DrawList nodes = quads("Nodes", {{{10, 10}, {100, 50}}});
  d.update({nodes, quads("Status", {{{0, 580}, {200, 600}}})}, kScreen);
  // The status text grew a glyph: the list changed shape.
  EXPECT_EQ(only(d.update({nodes, quads("Status", {{{0, 580}, {200, 600}}, {{200, 580}, {210, 600}}})}, kScreen)), (Rect{{0, 580}, {210, 600}}));
  // A tooltip appears, then goes.
  const DrawList tip = quads("##Tooltip_00", {{{400, 300}, {500, 320}}});
  const DrawList status = quads("Status", {{{0, 580}, {200, 600}}, {{200, 580}, {210, 600}}});
  EXPECT_EQ(only(d.update({nodes, status, tip}, kScreen)), (Rect{{400, 300}, {500, 320}}));
  EXPECT_EQ(only(d.update({nodes, status}, kScreen)), (Rect{{400, 300}, {500, 320}}));
}

TEST(FrameDamage, AnImageWhoseTextureWasRedrawnIsRedrawn) {
  FrameDamage d;
  const DrawList preview = quads("Preview", {{{300, 100}, {700, 400}}}, 0xffffffff, 42);
  d.update({preview}, kScreen);
  EXPECT_TRUE(d.update({preview}, kScreen, {7}).empty());  // another texture
  EXPECT_EQ(only(d.update({preview}, kScreen, {42})), (Rect{{300, 100}, {700, 400}}));
}

TEST(FrameDamage, ClipRectanglesBoundTheDamage) {
  FrameDamage d;
  DrawList w = quads("Nodes", {{{10, 10}, {500, 50}}});
  w.commands[0].clip = {{0, 0}, {100, 600}};  // the canvas shows only its left part
  d.update({w}, kScreen);
  for (DrawVertex& v : w.vertices) v.col = 0xff00ff00;
  EXPECT_EQ(only(d.update({w}, kScreen)), (Rect{{10, 10}, {100, 50}}));
}

TEST(FrameDamage, ManySmallChangesMergeIntoAFewRectangles) {
  FrameDamage d;
  std::vector<Rect> dots;
  for (int i = 0; i < 20; ++i) dots.push_back({{10.0f + 30.0f * i, 10}, {20.0f + 30.0f * i, 20}});
  DrawList w = quads("Nodes", dots);
  d.update({w}, kScreen);
  for (DrawVertex& v : w.vertices) v.col = 0xff0000ff;
  const auto damage = d.update({w}, kScreen);
  EXPECT_LE(damage.size(), FrameDamage::kMaxRects);
  float covered = 0;
  for (const Rect& r : damage) covered += r.size().x * r.size().y;
  EXPECT_LT(covered, 610.0f * 12.0f);  // a strip, not the screen
  // Fractional positions round outwards to whole pixels.
  DrawList half = quads("Half", {{{10.5f, 10.25f}, {20.5f, 20.75f}}});
  d.update({w, half}, kScreen);
  for (DrawVertex& v : half.vertices) v.col = 0xff00ff00;
  EXPECT_EQ(only(d.update({w, half}, kScreen)), (Rect{{10, 10}, {21, 21}}));
  // Every dot is inside some rectangle.
  for (const Rect& dot : dots)
    EXPECT_TRUE(std::any_of(damage.begin(), damage.end(), [&](const Rect& r) { return r.contains(dot.min) && r.contains(dot.max); }));
}

}  // namespace
}  // namespace procex::studio

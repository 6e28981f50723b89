// Expressions in the inspector, driven by real X input: a parameter turned
// into an expression of an exposed parameter follows it in the preview; a bad
// expression is refused at its field and changes nothing; back to a value and
// undone; saved as {"expr": ...}.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "graph/pxg.h"
#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

// The preview's plan extents along x and y (the mesh is Z up).
std::array<double, 2> plan_extent(const json& map) {
  if (!map.contains("preview_bounds")) return {0, 0};
  const json& b = map["preview_bounds"];
  return {b[3].get<double>() - b[0].get<double>(), b[4].get<double>() - b[1].get<double>()};
}

bool extent_is(const json& map, double x, double y) {
  const auto e = plan_extent(map);
  return std::abs(e[0] - x) < 1e-6 && std::abs(e[1] - y) < 1e-6;
}

// Right click on `widget`, then a click on the menu's `item`.
json menu(Studio& studio, const json& map, const std::string& widget, const std::string& item) {
  const auto at = widget_centre(map, widget);
  xdo("mousemove " + std::to_string(at.first) + " " + std::to_string(at.second) + " sleep 0.3 click 3 sleep 0.3");
  const json now = studio.wait("the menu of " + widget, [&](const json& j) { return j["params"].contains(item); });  // listed once placed
  click(widget_centre(now, item));
  return now;
}

// Replaces the text of the focused field and presses Enter.
void type_and_enter(const std::string& text) {
  press("ctrl+a");
  xdo("type '" + text + "'");
  press("Return");
}

// A 14 x 11 m block whose width is exposed, its depth free for an expression.
void write_block(const fs::path& recipe) {
  std::ofstream(recipe) << R"({
  "format": "procex-graph", "version": 2, "metadata": {"name": "block"}, "inputs": [],
  "outputs": [{"name": "mesh", "type": "mesh", "doc": ""}],
  "nodes": [
    {"id": 1, "type": "Footprint Shape", "version": 1, "params": {"shape": "rectangle", "width": 14.0, "depth": 11.0}},
    {"id": 2, "type": "Extrude", "version": 1, "params": {}}
  ],
  "links": [{"from": "1.footprint", "to": "2.footprint"}, {"from": "2.mesh", "to": "@mesh"}],
  "exposed": [{"name": "width", "node": 1, "param": "width"}],
  "editor": {"nodes": {"1": {"x": 0, "y": 0}, "2": {"x": 260, "y": 20}}}
})";
}

TEST(StudioExpressions, AnExpressionFollowsAnExposedParameterAndABadOneIsRefused) {
  const fs::path dir = fresh_dir("expression");
  const fs::path recipe = dir / "block.pxg";
  write_block(recipe);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "1"});
  json map = studio.wait("the block evaluated", [](const json& j) { return j["settled"] && j["params"].contains("depth") && extent_is(j, 14, 11); });

  // Right click > Expression...: the field takes the keyboard.
  menu(studio, map, "depth", "expression_menu");
  map = studio.wait("the expression field", [](const json& j) { return j["params"].contains("depth.expression"); });
  std::uint64_t rev = revision(map);
  type_and_enter("width / 2");
  map = studio.wait("the depth from the width", [&](const json& j) { return revision(j) > rev && j["settled"] && extent_is(j, 14, 7); });
  EXPECT_EQ(map["errors"], 0);
  EXPECT_EQ(revision(map), rev + 1) << "one undo step";

  // The exposed width changes: the depth follows it.
  rev = revision(map);
  type_into_slider(widget_centre(map, "width"), "20");
  map = studio.wait("the width and the depth", [&](const json& j) { return revision(j) > rev && j["settled"] && extent_is(j, 20, 10); });

  // A bad expression: the reason at the field (node, parameter, column), the recipe as it was.
  rev = revision(map);
  click(widget_centre(map, "depth.expression"));
  type_and_enter("width +* 2");
  map = studio.wait("the refusal at the field", [](const json& j) { return j["params"].contains("depth.error"); });
  EXPECT_EQ(revision(map), rev);
  const std::string status = map["status"];
  EXPECT_NE(status.find("node 1 (Footprint Shape), parameter 'depth': column 8"), std::string::npos) << status;
  const auto red_text = [&](const Screen& s) {
    return s.count(window_origin(map), map["params"]["depth.error"], [](double r, double g, double b) { return r > 150 && g < 0.6 * r && b < 0.6 * r; });
  };
  const long red = red_text(screen_when([&](const Screen& s) { return red_text(s) >= 20; }));
  EXPECT_GE(red, 20) << "pixels of the error text";

  // Back to a value (the one the expression gave), then undone: the expression again.
  menu(studio, map, "depth.expression", "value_menu");
  map = studio.wait("a value again", [&](const json& j) { return revision(j) > rev && !j["params"].contains("depth.expression") && j["settled"]; });
  EXPECT_TRUE(extent_is(map, 20, 10));
  EXPECT_FALSE(map["params"].contains("depth.error"));
  rev = revision(map);
  press("ctrl+z");
  map = studio.wait("the expression back", [&](const json& j) { return revision(j) > rev && j["params"].contains("depth.expression") && j["settled"]; });
  save_and_quit(studio);

  std::ifstream in(recipe);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(R"("depth": {"expr": "width / 2"})"), std::string::npos) << text;
  const Graph g = load_pxg(recipe);
  const Node* shape = g.node(1);
  ASSERT_TRUE(shape);
  const auto depth = static_cast<std::uint32_t>(*shape->decl().param_index("depth"));
  ASSERT_TRUE(shape->expressions.count(depth));
  EXPECT_EQ(shape->expressions.at(depth)->text(), "width / 2");
  EXPECT_DOUBLE_EQ(shape->params[*shape->decl().param_index("width")].get<double>(), 20.0);
}

// An edit made by a key press goes to the evaluation in the frame that made it. Enter in a field
// commits it while the key is still down; the next X event is the key's release, so an edit left
// for the next frame would wait for it (or for the loop's idle wake-up). Here Enter is held until
// the preview shows the result, and every ui map read meanwhile (each written at a frame's end)
// must show the edit already sent (`sent`, the revision the evaluation thread was last given).
TEST(StudioExpressions, AnEditCommittedByEnterIsEvaluatedWhileTheKeyIsHeld) {
  const fs::path dir = fresh_dir("held_enter");
  const fs::path recipe = dir / "block.pxg";
  write_block(recipe);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "1"});
  json map = studio.wait("the block evaluated", [](const json& j) { return j["settled"] && j["params"].contains("depth") && extent_is(j, 14, 11); });
  menu(studio, map, "depth", "expression_menu");
  map = type_into_focused_field(studio, "the expression field", "width / 2");
  const std::uint64_t rev = revision(map);
  EXPECT_EQ(map["sent"], map["revision"]);
  xdo("keydown Return");
  std::size_t maps_read = 0, behind = 0;
  map = studio.wait("the depth from the width, Return still held", [&](const json& j) {
    ++maps_read;
    if (revision(j) > rev && j["sent"] != j["revision"]) ++behind;
    return revision(j) > rev && j["settled"] && extent_is(j, 14, 7);
  });
  xdo("keyup Return");
  EXPECT_EQ(behind, 0u) << "of " << maps_read << " ui maps read, " << behind << " showed the edit made but not yet sent to the evaluation";
  EXPECT_EQ(revision(map), rev + 1);
  EXPECT_EQ(map["errors"], 0);
}

}  // namespace
}  // namespace procex::studio

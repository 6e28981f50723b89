// Editing inside a group, driven by real X input: a double-click on a group
// node opens it (the canvas shows its graph under a breadcrumb bar, drawn on
// screen); a parameter set, a node moved, a node added from the Tab search
// and wired in there change the group and the preview; a group inside it
// opens too, and the breadcrumb's first step backs out to the recipe, where
// Ctrl+Z undoes the last edit made inside. The saved recipe holds the edited
// group. A group read from a library file is refused, saying why.
#include <array>
#include <cmath>
#include <string>

#include "graph/pxg.h"
#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

// The preview's plan extents along x and y and its top (the mesh is Z up).
std::array<double, 3> extent(const json& map) {
  if (!map.contains("preview_bounds")) return {0, 0, 0};
  const json& b = map["preview_bounds"];
  return {b[3].get<double>() - b[0].get<double>(), b[4].get<double>() - b[1].get<double>(), b[5].get<double>()};
}

bool near(double a, double b) { return std::abs(a - b) < 1e-3; }

// A point inside node `node`'s box, left of its first output pin (or right of its first input pin).
std::pair<int, int> inside_node(const json& map, std::uint64_t node, bool from_output) {
  const auto [x, y] = pin(map, node, 0, from_output);
  return {from_output ? x - 60 : x + 60, y};
}

TEST(StudioGroupEdit, OpensAGroupEditsInsideAndBacksOutByTheBreadcrumb) {
  const fs::path dir = fresh_dir("group_edit");
  const fs::path recipe = copy_test_recipe("grouped_house.pxg", dir);
  Studio studio(recipe, dir);
  json map = studio.wait("the house evaluated", [](const json& j) { return j["settled"] && j["preview_faces"] > 0; });
  const std::array<double, 3> house = extent(map);
  EXPECT_EQ(map["breadcrumb"], json::array({"grouped_house.pxg"}));
  EXPECT_FALSE(map["buttons"].contains("crumb_0")) << "no breadcrumb bar at the recipe itself";

  // Double-click the house: its graph (the plan group and the Extrude) on the canvas, under the breadcrumb.
  const auto in_house = [](const json& j) { return j["scope"] == json::array({1}) && j["buttons"].contains("crumb_0"); };
  map = double_click_and_wait(studio, map, [](const json& j) { return inside_node(j, 1, true); }, "the house opened", in_house);
  ASSERT_TRUE(in_house(map));
  EXPECT_EQ(map["breadcrumb"], json::array({"grouped_house.pxg", "house"}));
  EXPECT_EQ(map["node_positions"].size(), 2u);
  EXPECT_FALSE(map["dirty"].get<bool>()) << "opening a group changes nothing";
  {  // On screen: the first step is a button (ImGui's blue over the dark panel), the second light text.
    const json& step = map["buttons"]["crumb_0"];
    const auto blue = [&](const Screen& s) { return s.count(window_origin(map), step, [](double r, double, double b) { return b > r + 40; }); };
    const long half = static_cast<long>(step[2].get<double>() * step[3].get<double>() * 0.5);
    const Screen screen = screen_when([&](const Screen& s) { return blue(s) > half; });
    EXPECT_GT(blue(screen), half) << "pixels of the breadcrumb's button";
    EXPECT_GT(screen.count(window_origin(map), map["buttons"]["crumb_1"], [](double r, double g, double b) { return r > 180 && g > 180 && b > 180; }), 10)
        << "the group's name, in light text";
  }

  // The Extrude inside: select it, cap its height at 2 m.
  const auto extrude_selected = [](const json& j) { return j["selected"] == 2 && j["params"].contains("max_height"); };
  click(inside_node(map, 2, false));
  map = studio.wait("the Extrude selected", extrude_selected);
  std::uint64_t rev = revision(map);
  type_into_slider(widget_centre(map, "max_height"), "2");
  map = studio.wait("the preview capped", [&](const json& j) { return revision(j) > rev && j["settled"] && near(extent(j)[2], 2.0); });
  EXPECT_TRUE(map["dirty"].get<bool>());
  EXPECT_EQ(map["errors"], 0);

  // Moved down.
  const json before_move = map["node_positions"]["2"];
  rev = revision(map);
  const auto at = inside_node(map, 2, false);
  drag(at, {at.first, at.second + 70});
  map = studio.wait("the Extrude moved", [&](const json& j) { return revision(j) > rev && j["node_positions"]["2"] != before_move; });

  // A Footprint Shape from the Tab search, in the empty lower left of the canvas, wired into the Extrude.
  const json& c = map["canvas"];
  const int ax = map["window"][0].get<int>() + static_cast<int>(c[0].get<double>() + c[2].get<double>() * 0.1);
  const int ay = map["window"][1].get<int>() + static_cast<int>(c[1].get<double>() + c[3].get<double>() * 0.8);
  const auto added = [](const json& j) { return j["node_positions"].size() == 3u && j["selected"] == 3 && pins_shown(j, 3); };
  xdo("mousemove " + std::to_string(ax) + " " + std::to_string(ay));
  studio.wait("the canvas has the keyboard", [](const json& j) { return j["keyboard"]["canvas"] == true; });
  press("Tab");
  type_into_focused_field(studio, "the node search", "footprint sh");
  press("Return");
  map = studio.wait("the Footprint Shape added", added);
  rev = revision(map);
  drag(pin(map, 3, 0, true), pin(map, 2, 0, false));
  map = studio.wait("the rectangle extruded", [&](const json& j) {
    return revision(j) > rev && j["settled"] && near(extent(j)[0], 12.0) && near(extent(j)[1], 10.0);
  });
  EXPECT_NEAR(extent(map)[2], 2.0, 1e-3);

  // The plan group inside the house, then back out to the recipe by the breadcrumb's first step.
  const auto in_plan = [](const json& j) { return j["scope"] == json::array({1, 1}) && j["buttons"].contains("crumb_2"); };
  map = double_click_and_wait(studio, map, [](const json& j) { return inside_node(j, 1, true); }, "the plan opened", in_plan);
  ASSERT_TRUE(in_plan(map));
  EXPECT_EQ(map["breadcrumb"], json::array({"grouped_house.pxg", "house", "plan"}));
  const auto at_recipe = [](const json& j) { return j["scope"].empty() && !j["buttons"].contains("crumb_0") && j["selected"] == 1; };
  click(button_centre(map, "crumb_0"));
  map = studio.wait("back at the recipe", at_recipe);
  ASSERT_TRUE(at_recipe(map));
  EXPECT_EQ(map["node_positions"].size(), 1u);

  // Ctrl+Z at the recipe undoes the wiring made inside the house: the L plan again, still capped.
  rev = revision(map);
  press("ctrl+z");
  map = studio.wait("the wiring undone", [&](const json& j) {
    return revision(j) > rev && j["settled"] && near(extent(j)[0], house[0]) && near(extent(j)[1], house[1]);
  });
  EXPECT_NEAR(extent(map)[2], 2.0, 1e-3);
  save_and_quit(studio);

  const Graph g = load_pxg(recipe);
  const Graph& body = *g.groups().at("house").type->body;
  ASSERT_TRUE(body.node(2));
  EXPECT_EQ(body.node(2)->params[*body.node(2)->decl().param_index("max_height")].get<double>(), 2.0);
  EXPECT_NE(body.node(2)->editor.y, 20.0) << "moved";
  ASSERT_TRUE(body.node(3));
  EXPECT_EQ(body.node(3)->type->name(), "Footprint Shape");
  EXPECT_EQ(body.source(PortRef{2, 0}), (PortRef{1, 0})) << "the wiring undone";
  EXPECT_EQ(g.nodes().size(), 1u);
}

}  // namespace
}  // namespace procex::studio

// Drives a real procex-studio window with real X input events (xdotool):
// add a node from the searchable menu, connect it with two drags, set two
// parameters, undo one, save with Ctrl+S, quit; then check the saved recipe
// and that the preview showed the edited result. Run under xvfb-run.
//
// The studio's --ui-map file says where pins and parameter widgets are on
// screen, and how far the studio has got (revision, settled, dirty).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "graph/pxg.h"
#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

// Pixels of the preview's anchor-marker yellow on screen now.
long anchor_marker_pixels(const json& map, const Screen& screen = capture_screen()) {
  // The marker's (1, 0.85, 0.1), lit: no tag colour is yellow with so little blue.
  return screen.count(window_origin(map), map["preview"], [](double red, double green, double blue) {
    return red > 80 && green > 0.65 * red && green < 1.05 * red && blue < 0.25 * red;
  });
}

TEST(StudioInteraction, AddConnectEditUndoSave) {
  const fs::path dir = fresh_dir("interaction");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir);
  json map = studio.wait("the house evaluated", [](const json& j) { return j["settled"] && j["preview_faces"] > 0; });
  const auto canvas = map["canvas"];
  const int wx = map["window"][0], wy = map["window"][1];

  // Add a Transform from the searchable menu (right click on empty canvas), high
  // enough to stay in view when the inspector takes its room for the new node.
  const int ax = wx + static_cast<int>(canvas[0].get<double>() + canvas[2].get<double>() * 0.45);
  const int ay = wy + static_cast<int>(canvas[1].get<double>() + canvas[3].get<double>() * 0.2);
  xdo("mousemove " + std::to_string(ax) + " " + std::to_string(ay) + " sleep 0.2 click 3 sleep 0.4 type Transform");
  press("Return");
  map = studio.wait("the Transform node", [](const json& j) { return j["selected"] == 3 && pins_shown(j, 3); });

  // Extrude's mesh into the Transform; the Transform into the graph output.
  std::uint64_t rev = revision(map);
  drag(pin(map, 2, 0, true), pin(map, 3, 0, false));
  map = studio.wait("the first link", [&](const json& j) { return revision(j) > rev; });
  rev = revision(map);
  drag(pin(map, 3, 0, true), pin(map, procex::kGraphOutputs, 0, false));
  map = studio.wait("the second link", [&](const json& j) { return revision(j) > rev; });

  // Two parameters, then undo the second.
  map = studio.wait("the inspector", [](const json& j) { return j["params"].contains("rotate") && j["params"].contains("scale"); });
  rev = revision(map);
  type_into_slider(widget_centre(map, "rotate"), "30");
  map = studio.wait("rotate set", [&](const json& j) { return revision(j) > rev; });
  rev = revision(map);
  type_into_slider(widget_centre(map, "scale"), "2");
  map = studio.wait("scale set", [&](const json& j) { return revision(j) > rev; });
  rev = revision(map);
  press("ctrl+z");
  map = studio.wait("undo", [&](const json& j) { return revision(j) > rev; });

  // Save, and the preview shows the edited recipe without errors.
  press("ctrl+s");
  map = studio.wait("saved", [](const json& j) { return !j["dirty"].get<bool>(); });
  map = studio.wait("the edited recipe evaluated", [](const json& j) { return j["settled"] && j["preview_faces"] > 0; });
  EXPECT_EQ(map["errors"], 0);
  press("ctrl+q");
  EXPECT_EQ(studio.wait_exit(20s), 0);

  const Graph g = load_pxg(recipe);
  ASSERT_EQ(g.nodes().size(), 3u);
  const Node* t = g.node(3);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->type->name(), "Transform");
  EXPECT_EQ(g.source({3, 0}), (PortRef{2, 0}));
  EXPECT_EQ(g.source({kGraphOutputs, 0}), (PortRef{3, 0}));
  EXPECT_DOUBLE_EQ(t->params[*t->decl().param_index("rotate")].get<double>(), 30.0);
  EXPECT_DOUBLE_EQ(t->params[*t->decl().param_index("scale")].get<double>(), 1.0);  // undone
}

// An edit autosaved, then the studio killed: the next start offers the edit back.
TEST(StudioInteraction, RecoversAutosavedEditsAfterACrash) {
  const fs::path dir = fresh_dir("recovery");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  fs::last_write_time(recipe, fs::file_time_type::clock::now() - std::chrono::minutes(1));
  {
    Studio studio(recipe, dir, {"--autosave", "1", "--select", "1"});
    json map = studio.wait("the house evaluated", [](const json& j) { return j["settled"] && j["params"].contains("width"); });
    const std::uint64_t rev = revision(map);
    type_into_slider(widget_centre(map, "width"), "23");
    studio.wait("width set", [&](const json& j) { return revision(j) > rev && j["dirty"].get<bool>(); });
    // Typing applies each digit ("2", then "23"): wait for an autosave of the whole value.
    // Only a finished autosave counts: a write still in its temporary file
    // (house-<hash>.pxg.tmp-...) is lost when the studio is killed before its rename.
    auto autosaved_23 = [&] {
      if (!fs::exists(dir / "home" / "autosave")) return false;
      for (const auto& f : fs::directory_iterator(dir / "home" / "autosave")) {
        if (f.path().extension() != ".pxg") continue;
        std::ifstream in(f.path());
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.find("\"width\": 23.0") != std::string::npos) return true;
      }
      return false;
    };
    const auto end = std::chrono::steady_clock::now() + 20s;
    while (!autosaved_23() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(100ms);
    EXPECT_TRUE(autosaved_23());
  }  // killed: no clean exit
  EXPECT_DOUBLE_EQ(load_pxg(recipe).node(1)->params[1].get<double>(), 14.0);  // the file itself is untouched
  Studio again(recipe, dir);
  json map = again.wait("the recovery prompt", [](const json& j) { return j["buttons"].contains("recover"); });  // listed once placed
  click(button_centre(map, "recover"));
  map = again.wait("recovered", [](const json& j) { return j["dirty"].get<bool>() && !j["buttons"].contains("recover"); });
  save_and_quit(again);
  EXPECT_DOUBLE_EQ(load_pxg(recipe).node(1)->params[1].get<double>(), 23.0);
  // Saving removed the autosave: nothing is offered next time.
  EXPECT_TRUE(fs::is_empty(dir / "home" / "autosave"));
}

bool has_pin(const json& map, std::uint64_t node, int port, bool output) {
  return std::any_of(map["pins"].begin(), map["pins"].end(),
                     [&](const json& p) { return p["node"] == node && p["port"] == port && p["output"] == output; });
}

// Variadic ports: the inspector's + and - change Merge's input count (pins
// follow), a connected input is never dropped (the status bar says why), undo.
TEST(StudioInteraction, ChangesAPortCountAndRefusesToDropAConnectedPort) {
  const fs::path dir = fresh_dir("ports");
  const fs::path recipe = dir / "merge.pxg";
  std::ofstream(recipe) << R"({
  "format": "procex-graph", "version": 2, "metadata": {"name": "merge"}, "inputs": [],
  "outputs": [{"name": "mesh", "type": "mesh", "doc": ""}],
  "nodes": [
    {"id": 1, "type": "Footprint Shape", "version": 1, "params": {"shape": "l"}},
    {"id": 2, "type": "Extrude", "version": 1, "params": {}},
    {"id": 3, "type": "Merge", "version": 2, "params": {"inputs": 2}}
  ],
  "links": [{"from": "1.footprint", "to": "2.footprint"}, {"from": "2.mesh", "to": "3.mesh_1"},
            {"from": "2.mesh", "to": "3.mesh_2"}, {"from": "3.mesh", "to": "@mesh"}],
  "editor": {"nodes": {"1": {"x": 0, "y": 0}, "2": {"x": 260, "y": 20}, "3": {"x": 520, "y": 20}}}
})";
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "3"});
  json map = studio.wait("the merge evaluated", [](const json& j) { return j["settled"] && j["params"].contains("inputs.add"); });
  EXPECT_FALSE(has_pin(map, 3, 2, false));
  map = click_and_wait(studio, map, [](const json& j) { return widget_centre(j, "inputs.add"); }, "a third input",
                    [](const json& j) { return has_pin(j, 3, 2, false); });
  map = click_and_wait(studio, map, [](const json& j) { return widget_centre(j, "inputs.remove"); }, "back to two inputs",
                    [](const json& j) { return !has_pin(j, 3, 2, false); });
  std::uint64_t rev = revision(map);
  click(widget_centre(map, "inputs.remove"));  // mesh_2 is connected
  map = studio.wait("the refusal", [](const json& j) { return j["status"].get<std::string>().find("'mesh_2'") != std::string::npos; });
  EXPECT_EQ(revision(map), rev);
  EXPECT_TRUE(has_pin(map, 3, 1, false));
  press("ctrl+z");
  map = studio.wait("the removal undone", [&](const json& j) { return revision(j) > rev && has_pin(j, 3, 2, false); });
  save_and_quit(studio);

  const Graph g = load_pxg(recipe);
  const Node* merge = g.node(3);
  ASSERT_TRUE(merge);
  EXPECT_EQ(merge->params[*merge->decl().param_index("inputs")].get<std::int64_t>(), 3);
  EXPECT_EQ(merge->decl().inputs().size(), 3u);
  EXPECT_EQ(g.source({3, 1}), (PortRef{2, 0}));
}

// The plan editor's Add hole / Delete hole on a Footprint Polygon: two
// holes, the first deleted after its corner was grabbed, undone.
TEST(StudioInteraction, AddsAndDeletesHoles) {
  const fs::path dir = fresh_dir("hole");
  const fs::path recipe = dir / "polygon.pxg";
  std::ofstream(recipe) << R"({
  "format": "procex-graph", "version": 2, "metadata": {"name": "polygon"}, "inputs": [],
  "outputs": [{"name": "mesh", "type": "mesh", "doc": ""}],
  "nodes": [
    {"id": 1, "type": "Footprint Polygon", "version": 2, "params": {"points": [[0, 0], [24, 0], [24, 9], [0, 9]]}},
    {"id": 2, "type": "Extrude", "version": 1, "params": {}}
  ],
  "links": [{"from": "1.footprint", "to": "2.footprint"}, {"from": "2.mesh", "to": "@mesh"}],
  "editor": {"nodes": {"1": {"x": 0, "y": 0}, "2": {"x": 260, "y": 20}}}
})";
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "1"});
  json map = studio.wait("the plan editor", [](const json& j) { return j["settled"] && j["buttons"].contains("add_hole"); });
  const std::size_t faces = map["preview_faces"];
  EXPECT_FALSE(map["buttons"].contains("delete_hole"));
  const auto add_hole = [](const json& j) { return button_centre(j, "add_hole"); };
  const auto delete_hole = [](const json& j) { return button_centre(j, "delete_hole"); };
  map = click_and_wait(studio, map, add_hole, "a courtyard", [&](const json& j) { return j["settled"] && j["preview_faces"] > faces; });
  const std::size_t one_hole = map["preview_faces"];
  map = click_and_wait(studio, map, add_hole, "two courtyards", [&](const json& j) { return j["settled"] && j["preview_faces"] > one_hole; });
  EXPECT_EQ(map["errors"], 0);
  press("ctrl+s");
  studio.wait("saved", [](const json& j) { return !j["dirty"].get<bool>(); });
  const auto holes_of = [&] { return load_pxg(recipe).node(1)->params[1].get<std::vector<std::vector<Vec2>>>(); };
  const auto two = holes_of();
  ASSERT_EQ(two.size(), 2u);
  map = click_and_wait(studio, map, delete_hole, "hole 2 deleted",  // the newest
                    [&](const json& j) { return j["settled"] && j["preview_faces"] == one_hole; });
  std::uint64_t rev = revision(map);
  press("ctrl+z");
  map = studio.wait("the deletion undone", [&](const json& j) { return revision(j) > rev && j["settled"] && j["preview_faces"] > one_hole; });
  // Pick hole 1 by its name, then delete it: hole 2 stays.
  map = studio.wait("both holes named", [](const json& j) { return j["buttons"].contains("hole_1") && j["buttons"].contains("hole_2"); });
  click(button_centre(map, "hole_1"));
  map = click_and_wait(studio, map, delete_hole, "hole 1 deleted", [&](const json& j) { return j["settled"] && j["preview_faces"] == one_hole; });
  save_and_quit(studio);
  EXPECT_EQ(holes_of(), std::vector<std::vector<Vec2>>{two[1]});
}

// The profile editor: a clicked segment's tag edited in place; a point
// double-clicked onto the soffit keeps one tag per segment.
TEST(StudioInteraction, EditsAProfileSegmentsTagAndKeepsTagsPerSegment) {
  const fs::path dir = fresh_dir("profile");
  const fs::path recipe = copy_test_recipe("overhang.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "2"});
  json map = studio.wait("the profile editor", [](const json& j) { return j["settled"] && j["buttons"].contains("segment_3"); });
  click(button_centre(map, "segment_3"));  // the soffit
  map = studio.wait("the tag field", [](const json& j) { return j["buttons"].contains("segment_tag"); });
  std::uint64_t rev = revision(map);
  click(button_centre(map, "segment_tag"));
  press("ctrl+a");
  xdo("type eave_soffit");
  press("Return");
  map = studio.wait("the tag set", [&](const json& j) { return revision(j) > rev && j["settled"]; });
  EXPECT_EQ(map["errors"], 0);
  rev = revision(map);
  // A double click on the soffit: the studio counts clicks by their X event times, so it registers
  // however slow its frames are; wait for the point it inserts.
  map = double_click_and_wait(studio, map, [](const json& j) { return button_centre(j, "segment_3"); }, "a point inserted",
                              [&](const json& j) { return revision(j) > rev && j["settled"] && j["buttons"].contains("segment_5"); });
  EXPECT_EQ(map["errors"], 0);  // the tags still match the segments: the profile evaluates
  save_and_quit(studio);
  const Graph saved = load_pxg(recipe);
  const Node* profile = saved.node(2);
  ASSERT_TRUE(profile);
  EXPECT_EQ(profile->params[1].get<std::vector<Vec2>>().size(), 7u);
  EXPECT_EQ(profile->params[2].get<std::vector<std::string>>(),
            (std::vector<std::string>{"wall", "ledge", "wall", "eave_soffit", "eave_soffit", "roof"}));
}

// The plan editor's Place anchor: a click on an edge adds an Anchor node wired
// into the Extrude (the preview shows its marker), then the anchor is
// dragged along the edge.
TEST(StudioInteraction, PlacesAnAnchorOnAnEdgeAndDragsItAlong) {
  const fs::path dir = fresh_dir("anchor");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "1"});
  json map = studio.wait("the plan editor", [](const json& j) { return j["settled"] && j["buttons"].contains("anchor_tool") && j["buttons"].contains("edge_0"); });
  EXPECT_EQ(map["preview_anchors"], 0);
  EXPECT_LT(anchor_marker_pixels(map), 5);
  click(button_centre(map, "anchor_tool"));
  map = studio.wait("the tool on", [](const json& j) { return j["anchor_tool"].get<bool>(); });
  std::uint64_t rev = revision(map);
  const auto anchor_key = [](const json& j) -> std::string {
    for (const auto& [name, r] : j["buttons"].items())
      if (name.starts_with("anchor_") && name.ends_with("_e0")) return name;
    return "";
  };
  click(button_centre(map, "edge_0"));
  map = studio.wait("the anchor placed and resolved",
                    [&](const json& j) { return revision(j) > rev && j["settled"] && !anchor_key(j).empty() && j["preview_anchors"] == 1; });
  EXPECT_EQ(map["errors"], 0);
  // The preview shows its marker (a frame or two after the result arrives).
  const long marker = anchor_marker_pixels(map, screen_when([&](const Screen& s) { return anchor_marker_pixels(map, s) >= 30; }));
  EXPECT_GE(marker, 30) << "pixels of the anchor marker in the preview";
  rev = revision(map);
  const auto at = button_centre(map, anchor_key(map));
  drag(at, {at.first - 40, at.second - 40});
  map = studio.wait("the anchor moved", [&](const json& j) { return revision(j) > rev && j["settled"]; });
  EXPECT_EQ(map["preview_anchors"], 1);
  save_and_quit(studio);

  const Graph g = load_pxg(recipe);
  const Node* anchor = nullptr;
  for (const auto& [id, n] : g.nodes())
    if (n.type->name() == "Anchor") anchor = &n;
  ASSERT_TRUE(anchor);
  EXPECT_EQ(anchor->params[*anchor->decl().param_index("edges")].get<std::string>(), "0");
  EXPECT_EQ(anchor->params[*anchor->decl().param_index("mode")].get<EnumValue>().choice, "fraction");
  const double position = anchor->params[*anchor->decl().param_index("position")].get<double>();
  EXPECT_GT(position, 0.05);
  EXPECT_LT(position, 0.45) << "dragged towards the edge's start from about its middle";
  const Node* extrude = g.node(2);
  EXPECT_EQ(extrude->params[*extrude->decl().param_index("anchors")].get<std::int64_t>(), 1);
  EXPECT_EQ(g.source({2, static_cast<std::uint32_t>(*extrude->decl().input_index("anchor_1"))}), (PortRef{anchor->id, 0}));
}

// The profile editor shows a Profile Offset's step as a handle: dragged up
// and out, it sets the offset's height and distance; undone in one step.
TEST(StudioInteraction, DragsAProfileOffsetHandle) {
  const fs::path dir = fresh_dir("offset");
  const fs::path recipe = copy_test_recipe("profile_offset.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "2"});
  json map = studio.wait("the offset handle", [](const json& j) { return j["settled"] && j["buttons"].contains("offset_5"); });
  std::uint64_t rev = revision(map);
  const auto at = button_centre(map, "offset_5");
  drag(at, {at.first + 25, at.second - 30});
  map = studio.wait("the offset moved", [&](const json& j) { return revision(j) > rev && j["settled"]; });
  EXPECT_EQ(map["errors"], 0);
  press("ctrl+s");
  map = studio.wait("saved", [](const json& j) { return !j["dirty"].get<bool>(); });
  const auto offset = [&](const char* name) {
    const Graph g = load_pxg(recipe);
    const Node* n = g.node(5);
    return n->params[*n->decl().param_index(name)].get<double>();
  };
  EXPECT_GT(offset("height"), 4.2);
  EXPECT_GT(offset("distance"), 0.9);
  rev = revision(map);
  press("ctrl+z");
  studio.wait("the drag undone", [&](const json& j) { return revision(j) > rev && j["settled"]; });
  save_and_quit(studio);
  EXPECT_DOUBLE_EQ(offset("height"), 4.0);
  EXPECT_DOUBLE_EQ(offset("distance"), 0.8);
}

// Waits for the house (started with --select 2) to evaluate, then gives the
// canvas the keyboard by a click on the selected Extrude, which keeps the selection.
json canvas_with_the_extrude_selected(Studio& studio) {
  const json map = studio.wait("the house evaluated", [](const json& j) { return j["settled"] && j["selected"] == 2; });
  const auto [ox, oy] = pin(map, 2, 0, true);
  click({ox - 50, oy});
  return studio.wait("the canvas has the keyboard", [](const json& j) { return j["keyboard"]["canvas"] == true && j["selected"] == 2; });
}

// Keys pressed and released, and characters typed, while the studio is busy
// with one frame (here: stopped while xdotool types) all arrive together;
// each key change is shown in a frame of its own with the characters it
// typed, so Tab opens the search, the name typed right after it fills it
// and Enter places the node; a quick Ctrl+Z undoes that.
TEST(StudioInteraction, KeysPressedDuringASlowFrameAreAllSeen) {
  const fs::path dir = fresh_dir("slow_keys");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "2"});
  json map = canvas_with_the_extrude_selected(studio);
  std::uint64_t rev = revision(map);
  studio.pause();
  xdo("key Tab type transf");
  xdo("key Return");
  studio.resume();
  map = studio.wait("the Transform placed and wired", [&](const json& j) { return revision(j) > rev && j["selected"] == 3 && j["links"].size() == 3; });
  rev = revision(map);
  studio.pause();
  xdo("key ctrl+z");
  studio.resume();
  map = studio.wait("the placing undone", [&](const json& j) { return revision(j) > rev && j["links"].size() == 2; });
  EXPECT_FALSE(map["node_positions"].contains("3"));
}

// Delete, then a click on another node, while the studio is stopped: both
// arrive in one frame, and the mouse and the keys wait in one queue, so they
// apply in the order they were made. The selected Extrude is deleted, then
// the Footprint clicked is selected and stays. (With a queue per device the
// press and Delete were shown in the same frame, where the canvas handles
// clicks first: the Footprint was selected, then deleted.)
TEST(StudioInteraction, AKeyThenAClickInOneFrameApplyInOrder) {
  const fs::path dir = fresh_dir("key_then_click");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "2"});
  json map = canvas_with_the_extrude_selected(studio);
  ASSERT_TRUE(map["node_positions"].contains("1"));
  const std::uint64_t rev = revision(map);
  const auto [fx, fy] = pin(map, 1, 0, true);
  studio.pause();
  xdo("key Delete");
  click({fx - 50, fy});  // on the Footprint's body, left of its output pin
  studio.resume();
  map = studio.wait("the Extrude deleted and the Footprint selected",
                    [&](const json& j) { return revision(j) > rev && j["selected"] == 1 && !j["node_positions"].contains("2"); });
  EXPECT_TRUE(map["node_positions"].contains("1"));
}

// Tab opens the node search over the canvas; typing filters it and Enter
// places the best match at the cursor, wired from the selected node. L lays
// the graph out again (one undo step).
TEST(StudioInteraction, TabSearchPlacesAWiredNodeAndLTidiesTheLayout) {
  const fs::path dir = fresh_dir("search");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "2"});
  json map = canvas_with_the_extrude_selected(studio);
  const auto canvas = map["canvas"];
  const int x = map["window"][0].get<int>() + static_cast<int>(canvas[0].get<double>() + canvas[2].get<double>() * 0.5);
  const int y = map["window"][1].get<int>() + static_cast<int>(canvas[1].get<double>() + canvas[3].get<double>() * 0.85);
  xdo("mousemove " + std::to_string(x) + " " + std::to_string(y) + " sleep 0.3");
  std::uint64_t rev = revision(map);
  press("Tab");
  type_into_focused_field(studio, "the node search", "transf");
  press("Return");
  map = studio.wait("the Transform placed and wired", [&](const json& j) { return revision(j) > rev && j["selected"] == 3 && j["links"].size() == 3; });
  const auto placed = map["node_positions"]["3"];
  rev = revision(map);
  press("l");
  map = studio.wait("the layout tidied", [&](const json& j) { return revision(j) > rev; });
  EXPECT_NE(map["node_positions"]["3"], placed);
  EXPECT_GE(map["canvas_min_text_px"].get<double>(), 10.0);
  save_and_quit(studio);

  const Graph g = load_pxg(recipe);
  ASSERT_TRUE(g.node(3));
  EXPECT_EQ(g.node(3)->type->name(), "Transform");
  EXPECT_EQ(g.source({3, 0}), (PortRef{2, 0}));
  // Laid out in layers: each node right of the one feeding it.
  EXPECT_LT(g.node(1)->editor.x, g.node(2)->editor.x);
  EXPECT_LT(g.node(2)->editor.x, g.node(3)->editor.x);
}

// Each node's outcome and time are written under its box: after an edit of
// the Extrude, the footprint above it is a cache hit and the Extrude computed
// again, on screen in their outcome's colour.
TEST(StudioInteraction, ShowsEachNodesOutcomeAndTimeUnderItsBox) {
  const fs::path dir = fresh_dir("timings");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "2"});
  const auto outcome = [](const json& j, const char* node) -> std::string {
    return j["node_timings"].contains(node) ? j["node_timings"][node]["outcome"].get<std::string>() : "";
  };
  json map = studio.wait("the house evaluated", [&](const json& j) {
    return j["settled"] && j["params"].contains("max_height") && outcome(j, "1") == "computed" && outcome(j, "2") == "computed";
  });
  EXPECT_GT(map["node_timings"]["1"]["ms"].get<double>(), 0.0);
  EXPECT_GT(map["node_timings"]["2"]["ms"].get<double>(), 0.0);
  // The computed green (90, 220, 110) of the label text; the cache-hit grey-blue (120, 140, 170).
  const auto green = [](double r, double g, double b) { return g > 140 && g > 1.5 * r && g > 1.4 * b; };
  const auto grey_blue = [](double r, double g, double b) { return b > 110 && b > r + 25 && b > g + 12; };
  // The map is written as the frame is built: the screen shows it a frame or two later.
  const auto label = [&](const Screen& s, const char* node, const std::function<bool(double, double, double)>& is) {
    return s.count(window_origin(map), map["node_timings"][node]["rect"], is);
  };
  const Screen before = screen_when([&](const Screen& s) { return label(s, "1", green) >= 10; });
  const long computed_first = label(before, "1", green), cached_first = label(before, "1", grey_blue);
  EXPECT_GE(computed_first, 10) << "the footprint's time on screen";
  EXPECT_EQ(cached_first, 0);

  const std::uint64_t rev = revision(map);
  type_into_slider(widget_centre(map, "max_height"), "6");
  map = studio.wait("the Extrude evaluated again", [&](const json& j) {
    return revision(j) > rev && j["settled"] && outcome(j, "1") == "cache hit" && outcome(j, "2") == "computed";
  });
  EXPECT_EQ(map["errors"], 0);
  EXPECT_EQ(map["node_timings"]["1"]["ms"].get<double>(), 0.0);  // a cache hit evaluates nothing
  const Screen after = screen_when([&](const Screen& s) { return label(s, "1", grey_blue) >= 10 && label(s, "2", green) >= 10; });
  const long cached = label(after, "1", grey_blue), computed = label(after, "2", green);
  EXPECT_GE(cached, 10) << "the footprint's 'cache hit' on screen";
  EXPECT_GE(computed, 10) << "the Extrude's time on screen";
}

// Files dragged onto the window: each feature of a GeoJSON is bound to the
// recipe's footprint input and its building shown where the feature stands; a
// recipe opens; anything else is explained.
TEST(StudioInteraction, DroppedGeoJsonBindsTheFootprintAndADroppedRecipeOpens) {
  const fs::path dir = fresh_dir("drop");
  const fs::path recipe = dir / "block.pxg";
  std::ofstream(recipe) << R"({
  "format": "procex-graph", "version": 2, "metadata": {"name": "block"},
  "inputs": [{"name": "footprint", "type": "footprint", "doc": ""}],
  "outputs": [{"name": "mesh", "type": "mesh", "doc": ""}],
  "nodes": [{"id": 1, "type": "Extrude", "version": 1, "params": {}}],
  "links": [{"from": "@footprint", "to": "1.footprint"}, {"from": "1.mesh", "to": "@mesh"}],
  "editor": {"nodes": {"1": {"x": 0, "y": 0}}}
})";
  // An L of six edges, where the stand-in plan is a rectangle of four.
  const fs::path footprints = dir / "plots.geojson";
  std::ofstream(footprints) << R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "id": "plot-7", "properties": {}, "geometry": {"type": "Polygon",
   "coordinates": [[[0, 0], [20, 0], [20, 8], [8, 8], [8, 16], [0, 16], [0, 0]]]}},
  {"type": "Feature", "id": "plot-8", "properties": {}, "geometry": {"type": "Polygon",
   "coordinates": [[[30, 0], [35, 0], [35, 5], [30, 5], [30, 0]]]}}]})";
  // Both buildings, each at its place: together they span 35 m by 16 m.
  const auto both_in_place = [](const json& j) {
    if (!j.contains("preview_bounds") || j["preview_features"] != 2) return false;
    const json& b = j["preview_bounds"];
    return std::abs(b[3].get<double>() - b[0].get<double>() - 35.0) < 1e-3 && std::abs(b[4].get<double>() - b[1].get<double>() - 16.0) < 1e-3;
  };
  const fs::path other = copy_test_recipe("house.pxg", dir);
  std::ofstream(dir / "notes.txt") << "not a recipe\n";
  Studio studio(recipe, dir);
  json map = studio.wait("the stand-in plan evaluated", [](const json& j) { return j["settled"] && j["preview_faces"] > 0; });
  const std::size_t rectangle = map["preview_faces"];
  EXPECT_EQ(map["preview_footprint"], "");

  drop_file(map, footprints);
  map = studio.wait("the dropped plans evaluated", [&](const json& j) {
    return j["settled"] && j["preview_footprint"] == footprints.string() + " (2 features)" && j["preview_faces"] > rectangle && both_in_place(j);
  });
  EXPECT_EQ(map["errors"], 0);
  EXPECT_FALSE(map["dirty"].get<bool>()) << "the preview's plan is not an edit of the recipe";

  // Any footprint file procex batch reads: the same plots as a Shapefile (GDAL's ogr2ogr).
  const fs::path shapefile = dir / "plots.shp";
  ASSERT_EQ(std::system(("ogr2ogr -a_srs EPSG:32632 " + shapefile.string() + " " + footprints.string()).c_str()), 0);
  drop_file(map, shapefile);
  map = studio.wait("the dropped Shapefile evaluated", [&](const json& j) {
    return j["settled"] && j["preview_footprint"] == shapefile.string() + " (2 features)" && both_in_place(j);
  });
  EXPECT_EQ(map["errors"], 0);

  drop_file(map, dir / "notes.txt");
  map = studio.wait("the refusal", [](const json& j) { return j["status"].get<std::string>().find("drop a recipe (.pxg)") != std::string::npos; });

  drop_file(map, other);
  map = studio.wait("the dropped recipe open", [&](const json& j) {
    return j["settled"] && j["status"] == "opened " + other.string() && j["node_positions"].contains("2");
  });
  EXPECT_EQ(map["errors"], 0);
  press("ctrl+q");
  EXPECT_EQ(studio.wait_exit(20s), 0);
}

// A footprint file dropped on a recipe that reads no party or street edges,
// then a recipe that does opened (the city's: party walls where terraced
// houses meet): its preview is the one the city shows when started on the
// file, the edges found again for the recipe now open.
TEST(StudioInteraction, ADroppedFootprintFilesEdgesAreFoundAgainForTheRecipeOpenedNext) {
  const fs::path dir = fresh_dir("relabel");
  const fs::path terrace = fs::path(PROCEX_SAMPLES) / "footprints" / "terrace.geojson";
  const fs::path city = fs::path(PROCEX_SAMPLES) / "city.pxg";
  const auto city_on_terrace = [&](const json& j) {
    return j["settled"] && j["status"] == "opened " + city.string() && j["preview_features"] == 3 && j["preview_faces"] > 0;
  };
  std::size_t started_on_file = 0;
  {
    Studio reference(city, dir, {"--autosave", "0", "--footprints", terrace.string()});
    const json map = reference.wait("the city on the terrace", [](const json& j) { return j["settled"] && j["preview_features"] == 3 && j["preview_faces"] > 0; }, 90s);
    EXPECT_EQ(map["errors"], 0);
    started_on_file = map["preview_faces"];
  }
  const fs::path house = copy_test_recipe("house.pxg", dir);
  Studio studio(house, dir);
  json map = studio.wait("the house evaluated", [](const json& j) { return j["settled"] && j["preview_faces"] > 0; });
  drop_file(map, terrace);
  map = studio.wait("the terrace under the house recipe", [](const json& j) { return j["settled"] && j["preview_features"] == 3; }, 60s);
  drop_file(map, city);
  map = studio.wait("the city opened on the terrace", city_on_terrace, 90s);
  EXPECT_EQ(map["errors"], 0);
  EXPECT_EQ(map["preview_faces"], started_on_file) << "the party and street edges the city reads, found for it";
  press("ctrl+q");
  EXPECT_EQ(studio.wait_exit(20s), 0);
}

}  // namespace
}  // namespace procex::studio

// The group library driven by real X input: with one of the city's building
// groups selected, Edit > Save group to library writes lib/building.pxg
// beside the recipe; the Evaluation panel's Library tab lists it, and its
// Place button adds an instance read from that file, which the saved recipe
// names, where it covers none of the city's nodes; opening that group to edit
// it inside the recipe is refused.
#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

#include "graph/pxg.h"
#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

TEST(StudioGroupLibrary, SavesAGroupAndPlacesItFromTheLibraryTab) {
  const fs::path dir = fresh_dir("group_library");
  const fs::path recipe = dir / "city.pxg";
  fs::copy_file(fs::path(PROCEX_SAMPLES) / "city.pxg", recipe);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "1"});
  json map = studio.wait("settled", [](const json& j) { return j["settled"].get<bool>() && j["selected"] == 1; });
  const std::size_t nodes_before = map["node_positions"].size();

  const auto saved = [](const json& j) { return j["status"].get<std::string>().find("saved group 'building' to ") != std::string::npos; };
  map = menu_item_and_wait(studio, map, "menu_edit", "menu_save_group", saved);
  ASSERT_TRUE(saved(map)) << map["status"];
  ASSERT_TRUE(fs::is_regular_file(dir / "lib" / "building.pxg"));
  EXPECT_NO_THROW(load_pxg(dir / "lib" / "building.pxg")) << "a recipe of its own";
  EXPECT_FALSE(map["dirty"].get<bool>()) << "the recipe itself is unchanged";

  // The Library tab, then Place.
  const auto listed = [](const json& j) { return j["buttons"].contains("library_place_building"); };
  click(button_centre(map, "tab_library"));
  map = studio.wait("the library listed", listed);
  map = click_and_wait(studio, map, [](const json& j) { return button_centre(j, "library_place_building"); }, "the group placed",
                    [&](const json& j) { return j["node_positions"].size() == nodes_before + 1; });
  EXPECT_NE(map["status"].get<std::string>().find("placed lib/building.pxg"), std::string::npos) << map["status"];
  const std::uint64_t placed = map["selected"].get<std::uint64_t>();
  // Placed at the canvas's centre, where the city's nodes are, it covers none of them.
  const json& rects = map["node_rects"];
  ASSERT_TRUE(rects.contains(std::to_string(placed))) << rects;
  const json& at = rects[std::to_string(placed)];
  for (const auto& [id, r] : rects.items()) {
    if (id == std::to_string(placed)) continue;
    const bool apart = at[0].get<float>() + at[2].get<float>() < r[0].get<float>() || r[0].get<float>() + r[2].get<float>() < at[0].get<float>() ||
                       at[1].get<float>() + at[3].get<float>() < r[1].get<float>() || r[1].get<float>() + r[3].get<float>() < at[1].get<float>();
    EXPECT_TRUE(apart) << "placed at " << at << " over node " << id << " at " << r;
  }
  // Its graph is the library file's, which other recipes may share: opening it here is refused, saying why.
  const auto refused = [](const json& j) { return j["status"].get<std::string>().find("is read from lib/building.pxg") != std::string::npos; };
  // A double-click on its body, beside its last input's name, meets only it.
  map = studio.wait("the placed group drawn", [&](const json& j) { return pins_shown(j, placed); });
  map = double_click_and_wait(studio, map, [&](const json& j) {
    int last = 0;
    for (const json& p : j["pins"])
      if (p["node"] == placed && !p["output"].get<bool>()) last = std::max(last, p["port"].get<int>());
    const auto [x, y] = pin(j, placed, last, false);
    return std::pair(x + 60, y);
  }, "the library group refused", refused);
  EXPECT_TRUE(refused(map)) << map["status"];
  EXPECT_TRUE(map["scope"].empty());
  save_and_quit(studio);

  const Graph g = load_pxg(recipe);
  ASSERT_TRUE(g.groups().count("building2"));
  EXPECT_EQ(g.groups().at("building2").file, "lib/building.pxg");
  EXPECT_EQ(g.nodes().size(), nodes_before + 1);
}

}  // namespace
}  // namespace procex::studio

// The panel layout driven by real X input: dragging the edge between the node
// canvas and the preview moves it, the split is kept in the user's config
// folder ($XDG_CONFIG_HOME/procex-studio/imgui.ini) for the next start, and
// View > Reset layout puts the panels back and rewrites the file. A file that
// is not the studio's leaves the default layout, and the status bar names it.
#include <fstream>
#include <iterator>
#include <string>

#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

double split_x(const json& map) { return map["layout"][0].get<double>(); }
double panel(const json& map, const std::string& name, int i) { return map["buttons"]["panel_" + name][i].get<double>(); }

json settled(Studio& studio) {
  return studio.wait("settled with the panels placed", [](const json& j) { return j["settled"].get<bool>() && j["buttons"].contains("panel_nodes"); });
}

// Drags the right edge of the node panel `dx` pixels.
json drag_split(Studio& studio, const json& map, int dx) {
  const double before = split_x(map);
  const auto [ox, oy] = window_origin(map);
  const int x = static_cast<int>(ox + panel(map, "nodes", 0) + panel(map, "nodes", 2)) - 2;
  const int y = static_cast<int>(oy + panel(map, "nodes", 1) + panel(map, "nodes", 3) / 2);
  drag({x, y}, {x + dx, y});
  return studio.wait("the split moved", [&](const json& j) { return split_x(j) > before + 0.02; });
}

TEST(StudioLayout, DraggedSplitIsKeptForTheNextStartAndReset) {
  const fs::path dir = fresh_dir("layout");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  const fs::path ini = dir / "config" / "procex-studio" / "imgui.ini";
  double default_width = 0, dragged_width = 0, dragged_split = 0;
  {
    Studio studio(recipe, dir);
    json map = settled(studio);
    EXPECT_NEAR(split_x(map), 0.5, 1e-9);
    default_width = panel(map, "nodes", 2);
    map = drag_split(studio, map, 150);
    // The preview gave the room the canvas took.
    map = studio.wait("the panels follow the split", [&](const json& j) {
      return panel(j, "nodes", 2) > default_width + 100 && panel(j, "preview", 0) > panel(map, "nodes", 0) + default_width + 100;
    });
    dragged_width = panel(map, "nodes", 2);
    dragged_split = split_x(map);
    EXPECT_NEAR(dragged_width, default_width + 150, 20);
    press("ctrl+q");
    ASSERT_EQ(studio.wait_exit(20s), 0);
  }
  const std::string saved = read_text(ini);
  EXPECT_NE(saved.find("[Procex][Layout]"), std::string::npos) << saved;
  EXPECT_NE(saved.find("SplitX=" + std::to_string(dragged_split).substr(0, 5)), std::string::npos) << saved;
  {
    Studio studio(recipe, dir);
    json map = settled(studio);
    EXPECT_NEAR(split_x(map), dragged_split, 1e-3);
    EXPECT_NEAR(panel(map, "nodes", 2), dragged_width, 1.5);
    // View > Reset layout.
    const auto is_default = [](const json& j) { return std::abs(split_x(j) - 0.5) < 1e-9; };
    map = menu_item_and_wait(studio, map, "menu_view", "menu_reset_layout", is_default);
    map = studio.wait("the panels back", [&](const json& j) { return std::abs(panel(j, "nodes", 2) - default_width) < 1.5; });
    EXPECT_NE(map["status"].get<std::string>().find("panel layout reset"), std::string::npos) << map["status"];
    EXPECT_NE(read_text(ini).find("SplitX=0.5000"), std::string::npos) << read_text(ini);
    press("ctrl+q");
    EXPECT_EQ(studio.wait_exit(20s), 0);
  }
}

TEST(StudioLayout, ASettingsFileThatIsNotTheStudiosLeavesTheDefault) {
  const fs::path dir = fresh_dir("layout_bad");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  const fs::path ini = dir / "config" / "procex-studio" / "imgui.ini";
  fs::create_directories(ini.parent_path());
  {
    // Out of range, not a number, unknown keys: each ignored or clamped.
    std::ofstream(ini) << "[Procex][Layout]\nSplitX=7\nSplitY=nan\nSplitZ=0.3\n[Window][Nodes]\nPos=-99999,99999\nSize=1e30,-5\n";
    Studio studio(recipe, dir);
    const json map = settled(studio);
    EXPECT_NEAR(split_x(map), 0.85, 1e-9);
    EXPECT_NEAR(map["layout"][1].get<double>(), 0.62, 1e-9);
    EXPECT_NEAR(panel(map, "nodes", 0), 0, 1e-9);
    press("ctrl+q");
    EXPECT_EQ(studio.wait_exit(20s), 0);
  }
  {
    // Larger than any file the studio writes: not read, and the status bar names the file.
    std::ofstream(ini) << "[Procex][Layout]\nSplitX=0.3\n" << std::string(100000, '#') << "\n";
    Studio studio(recipe, dir);
    const json map = settled(studio);
    EXPECT_NEAR(split_x(map), 0.5, 1e-9);
    EXPECT_NE(map["status"].get<std::string>().find(ini.string()), std::string::npos) << map["status"];
    press("ctrl+q");
    EXPECT_EQ(studio.wait_exit(20s), 0);
  }
}

}  // namespace
}  // namespace procex::studio

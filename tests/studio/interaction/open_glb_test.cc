// File > Open of a .glb driven by real X input: a file procex wrote shows in
// the preview in place of the recipe's (its placed windows on screen, in
// their tag's colour), View > Recipe preview brings the recipe's back, and a
// file the glb reader refuses changes nothing and is named in the status bar.
// The file read goes into File > Open recent, which opens it again; dropped
// on the window (a real XDND drag from another X client) it opens too.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

// Ctrl+O, the path typed into the prompt once it has the keyboard, Enter.
json open_path(Studio& studio, const fs::path& file, const std::function<bool(const json&)>& done) {
  press("ctrl+o");
  type_into_focused_field(studio, "the open prompt", file.string());
  press("Return");
  return studio.wait("the file opened", done);
}

// Pixels of the preview image in the window colour (cyan: blue and green well above red).
long window_pixels(const json& map) {
  const json& p = map["preview"];
  return capture_screen().count(window_origin(map), json::array({p[0], p[1], p[2], p[3]}), [](double r, double g, double b) {
    return b > 1.3 * r && g > 1.3 * r && b > 60;
  });
}

TEST(StudioOpenGlb, ShowsTheFileInThePreviewUntilAskedBack) {
  const fs::path dir = fresh_dir("open_glb");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  const fs::path windows = copy_test_recipe("windows.pxg", dir);
  fs::copy_file(fs::path(PROCEX_TEST_DATA) / "mesh_window_frame.obj", dir / "mesh_window_frame.obj");
  const fs::path glb = dir / "windows.glb";
  ASSERT_EQ(std::system((std::string(PROCEX_CLI_EXE) + " eval '" + windows.string() + "' -o '" + glb.string() + "' > /dev/null").c_str()), 0);
  {  // a .glb cut short: what the reader refuses
    std::ifstream in(glb, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir / "broken.glb", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  Studio studio(recipe, dir);
  json map = studio.wait("settled", [](const json& j) { return j["settled"].get<bool>() && j["preview_faces"].get<int>() > 0; });
  const long house_faces = map["preview_faces"].get<long>();
  EXPECT_EQ(map["preview_instances"], 0);
  EXPECT_EQ(window_pixels(map), 0) << "the house has no windows";

  map = open_path(studio, glb, [&](const json& j) { return j["viewing"] == glb.string(); });
  ASSERT_EQ(map["viewing"], glb.string());
  EXPECT_GT(map["preview_instances"].get<int>(), 0) << "the placed windows, instanced";
  EXPECT_NE(map["preview_faces"].get<long>(), house_faces);
  EXPECT_NE(map["status"].get<std::string>().find("viewing " + glb.string()), std::string::npos) << map["status"];
  map = studio.wait("the windows drawn", [](const json& j) { return window_pixels(j) > 200; }, 20s);

  // A file the reader refuses: the status names it, the preview keeps the viewed file.
  const fs::path broken = dir / "broken.glb";
  map = open_path(studio, broken, [&](const json& j) { return j["status"].get<std::string>().find(broken.string()) != std::string::npos; });
  EXPECT_NE(map["status"].get<std::string>().find(broken.string()), std::string::npos) << map["status"];
  EXPECT_EQ(map["viewing"], glb.string());

  // View > Recipe preview: the house again.
  const auto back = [&](const json& j) { return j["viewing"] == "" && j["preview_faces"].get<long>() == house_faces; };
  map = menu_item_and_wait(studio, map, "menu_view", "menu_recipe_preview", back);
  map = studio.wait("the windows gone", [](const json& j) { return window_pixels(j) == 0; }, 20s);
  EXPECT_FALSE(map["dirty"].get<bool>()) << "viewing a file does not change the recipe";

  // File > Open recent > the .glb (the newest entry; the refused file is not listed).
  const auto viewing = [&](const json& j) { return j["viewing"] == glb.string() && j["loading"] == ""; };
  click(button_centre(map, "menu_file"));
  const auto [x, y] = button_centre(studio.wait("the File menu", [](const json& j) { return j["buttons"].contains("menu_open_recent"); }), "menu_open_recent");
  xdo("mousemove " + std::to_string(x) + " " + std::to_string(y));  // hovered, the submenu opens
  click(button_centre(studio.wait("the recent files", [](const json& j) { return j["buttons"].contains("recent_1"); }), "recent_0"));
  map = studio.wait("the .glb opened again", viewing);
  ASSERT_TRUE(viewing(map)) << map["status"];
  EXPECT_NE(map["status"].get<std::string>().find("viewing " + glb.string()), std::string::npos) << map["status"];

  // Back to the recipe, then the .glb dropped on the window.
  map = menu_item_and_wait(studio, map, "menu_view", "menu_recipe_preview", back);
  ASSERT_TRUE(back(map));
  drop_file(map, glb);
  map = studio.wait("the dropped .glb viewed", viewing);
  EXPECT_GT(map["preview_instances"].get<int>(), 0);
  press("ctrl+q");
  EXPECT_EQ(studio.wait_exit(20s), 0);
}

}  // namespace
}  // namespace procex::studio

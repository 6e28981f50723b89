// The 3D preview, driven by real X input: its images are drawn on a thread of
// their own (ui/preview_renderer.h), so the window answers while one is drawn.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;

// The preview's plan extent along x (the mesh is Z up), 0 without bounds.
double extent_x(const json& map) {
  if (!map.contains("preview_bounds")) return 0;
  return map["preview_bounds"][3].get<double>() - map["preview_bounds"][0].get<double>();
}

// The preview's thread is held still (ptrace, that thread alone) from before an edit until after a
// click on the node canvas. The edit's evaluation reaches the window and its image is asked for but
// cannot be drawn; the click must still select a node, while the window shows the image from before
// the edit. Once the thread goes on, the edit's image is shown. The test checks the order of what
// the studio did, not how long it took. Drawn in the window's frame, as it was before it had a thread
// of its own, a new mesh's image was shown by the frame that received the mesh, so no map showed
// the edit's bounds beside the image from before it.
TEST(StudioPreview, TheCanvasAnswersWhileThePreviewIsBeingDrawn) {
  const fs::path dir = fresh_dir("preview_thread");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir, {"--autosave", "0", "--select", "1"});
  json map = studio.wait("the house drawn", [](const json& j) {
    return j["settled"] && j["params"].contains("width") && j["preview_images"].get<std::uint64_t>() > 0 && pins_shown(j, 2);
  });
  const std::uint64_t images = map["preview_images"].get<std::uint64_t>(), rev = revision(map);
  const double before = extent_x(map);

  HeldThread preview(studio.pid(), "procex-preview");
  ASSERT_TRUE(preview.held());
  type_into_slider(widget_centre(map, "width"), "20");
  map = studio.wait("the edit evaluated", [&](const json& j) { return revision(j) > rev && extent_x(j) > before + 1; });
  EXPECT_EQ(map["preview_images"].get<std::uint64_t>(), images) << "an image was shown while the preview's thread was held";
  EXPECT_FALSE(map["settled"].get<bool>()) << "settled before the edit's image was shown";

  // A click on the Extrude node's body, beside its input's name, selects it.
  const auto [x, y] = pin(map, 2, 0, false);
  click({x + 60, y});
  map = studio.wait("the Extrude node selected", [](const json& j) { return j["selected"] == 2; });
  EXPECT_EQ(map["preview_images"].get<std::uint64_t>(), images) << "an image was shown while the preview's thread was held";

  preview.release();
  map = studio.wait("the edit's image shown", [&](const json& j) { return j["settled"] && j["preview_images"].get<std::uint64_t>() > images; });
  EXPECT_GT(extent_x(map), before + 1);
  EXPECT_EQ(map["selected"], 2);
}

}  // namespace
}  // namespace procex::studio

// The .glb loader without a window: a file read on its thread comes back as
// a preview with the reader's progress seen on the way; a file the reader
// refuses comes back as its message; a newer load replaces an older one.
#include "app/studio/editor/glb_loader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "app/studio/editor/eval_worker.h"
#include "app/studio/editor/export_meshes.h"
#include "graph/pxg.h"
#include "tests/studio/studio_test_util.h"

namespace procex::studio {
namespace {

using namespace std::chrono_literals;

// Polls as the window does, once a frame, until the load is handed over.
GlbLoader::Loaded wait_for(GlbLoader& loader) {
  for (;;) {
    if (std::optional<GlbLoader::Loaded> done = loader.take()) return *done;
    std::this_thread::sleep_for(5ms);
  }
}

std::filesystem::path house_glb(const std::filesystem::path& dir) {
  EvalWorker worker;
  const Graph g = load_pxg(test::house_recipe());
  worker.submit(1, g);
  EXPECT_TRUE(worker.wait_idle(60s));
  EXPECT_TRUE(export_meshes(g, *worker.latest(), dir / "house.glb", {}));
  return dir / "house.glb";
}

TEST(GlbLoader, ReadsAFileOnItsThreadAndHandsItOverOnce) {
  const auto dir = test::temp_dir();
  const auto glb = house_glb(dir);
  GlbLoader loader;
  EXPECT_FALSE(loader.progress()) << "idle";
  loader.load(glb);
  const GlbLoader::Loaded done = wait_for(loader);
  EXPECT_EQ(done.file, glb);
  ASSERT_TRUE(done.mesh) << done.error;
  EXPECT_EQ(done.mesh->meshes, 1u);
  EXPECT_GT(done.mesh->faces, 0u);
  EXPECT_FALSE(loader.progress());
  EXPECT_FALSE(loader.take()) << "handed over once";
}

TEST(GlbLoader, ARefusedFileComesBackAsItsMessage) {
  const auto dir = test::temp_dir();
  std::ofstream(dir / "broken.glb") << "glTF but not really";
  GlbLoader loader;
  loader.load(dir / "broken.glb");
  const GlbLoader::Loaded done = wait_for(loader);
  EXPECT_FALSE(done.mesh);
  EXPECT_NE(done.error.find((dir / "broken.glb").string()), std::string::npos) << done.error;
  loader.load(dir / "missing.glb");
  EXPECT_NE(wait_for(loader).error.find("missing.glb"), std::string::npos);
}

TEST(GlbLoader, ANewerLoadReplacesAnOlderOne) {
  const auto dir = test::temp_dir();
  const auto glb = house_glb(dir);
  std::ofstream(dir / "broken.glb") << "not a glb";
  GlbLoader loader;
  loader.load(dir / "broken.glb");
  loader.load(glb);
  const GlbLoader::Loaded done = wait_for(loader);
  EXPECT_EQ(done.file, glb) << "only the newest load is handed over";
  EXPECT_TRUE(done.mesh);
}

}  // namespace
}  // namespace procex::studio

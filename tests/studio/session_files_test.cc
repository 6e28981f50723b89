// The studio's own files: recent recipes and autosaves for crash recovery.
#include "app/studio/editor/session_files.h"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "tests/studio/studio_test_util.h"

namespace procex::studio {
namespace {

namespace fs = std::filesystem;

TEST(RecentFiles, MostRecentFirstWithoutDuplicatesAndBounded) {
  const fs::path dir = test::temp_dir();
  {
    RecentFiles r(dir / "recent.txt", 3);
    for (const char* f : {"a.pxg", "b.pxg", "c.pxg", "a.pxg", "d.pxg"}) r.add(dir / f);
  }
  RecentFiles again(dir / "recent.txt", 3);  // read back from the file
  ASSERT_EQ(again.list().size(), 3u);
  EXPECT_EQ(again.list()[0].filename(), "d.pxg");
  EXPECT_EQ(again.list()[1].filename(), "a.pxg");
  EXPECT_EQ(again.list()[2].filename(), "c.pxg");
}

TEST(Autosave, OnePerRecipeAndRecoveredOnlyWhenNewerThanTheRecipe) {
  const fs::path dir = test::temp_dir();
  const fs::path home = dir / "home";
  const fs::path recipe = dir / "house.pxg";
  std::ofstream(recipe) << "{}";
  EXPECT_NE(autosave_path(home, recipe), autosave_path(home, dir / "other" / "house.pxg"));
  EXPECT_NE(autosave_path(home, recipe), autosave_path(home, {}));
  EXPECT_FALSE(find_recovery(home, recipe));
  // Autosaved after the recipe was last written: offered for recovery.
  fs::last_write_time(recipe, fs::file_time_type::clock::now() - std::chrono::minutes(5));
  write_autosave(home, recipe, "{\"edited\": true}");
  ASSERT_TRUE(find_recovery(home, recipe));
  EXPECT_EQ(test::read_text(*find_recovery(home, recipe)), "{\"edited\": true}");
  // The recipe saved after the autosave: nothing to recover.
  fs::last_write_time(recipe, fs::file_time_type::clock::now() + std::chrono::minutes(5));
  EXPECT_FALSE(find_recovery(home, recipe));
  remove_autosave(home, recipe);
  EXPECT_FALSE(fs::exists(autosave_path(home, recipe)));
  // The untitled recipe has its own autosave.
  write_autosave(home, {}, "{}");
  EXPECT_TRUE(find_recovery(home, {}));
}

}  // namespace
}  // namespace procex::studio

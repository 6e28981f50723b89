// confined_path: a file a recipe names stays inside the recipe's folder (or a
// folder the user allowed), however it is spelled: "..", absolute, symlinks.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/confined_path.h"
#include "base/confined_path_memo.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

class ConfinedPath : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    base_ = fs::weakly_canonical(dir_);
    recipe_ = base_ / "recipe";
    fs::create_directories(recipe_ / "lib");
    fs::create_directories(base_ / "elsewhere");
    std::ofstream(base_ / "secret.obj") << "v 0 0 0\n";
  }
  std::string refusal(const std::string& name, const std::vector<fs::path>& allowed = {}) {
    try {
      return "accepted as " + confined_path(recipe_, name, allowed).string();
    } catch (const IoError& e) {
      return e.what();
    }
  }
  fs::path base_, recipe_;
};

TEST_F(ConfinedPath, NamesInsideTheFolderResolve) {
  EXPECT_EQ(confined_path(recipe_, "lib/a.obj"), recipe_ / "lib" / "a.obj");
  EXPECT_EQ(confined_path(recipe_, "lib/../b.glb"), recipe_ / "b.glb");  // not yet written: fine
  EXPECT_EQ(confined_path(recipe_, (recipe_ / "out" / "c.glb").string()), recipe_ / "out" / "c.glb");
}

TEST_F(ConfinedPath, NamesOutsideAreRefusedHoweverSpelled) {
  for (const std::string& name : std::vector<std::string>{"../secret.obj", "lib/../../secret.obj", "/etc/passwd", (base_ / "secret.obj").string()}) {
    const std::string why = refusal(name);
    EXPECT_NE(why.find("lies outside the recipe's folder"), std::string::npos) << name << ": " << why;
    EXPECT_NE(why.find("--allow-path"), std::string::npos) << why;
  }
  fs::create_symlink(base_ / "secret.obj", recipe_ / "innocent.obj");
  fs::create_directory_symlink(base_ / "elsewhere", recipe_ / "out");
  EXPECT_NE(refusal("innocent.obj").find("outside"), std::string::npos) << refusal("innocent.obj");
  EXPECT_NE(refusal("out/model.glb").find("outside"), std::string::npos) << refusal("out/model.glb");
  EXPECT_NE(refusal("").find("no file name"), std::string::npos);
  // A folder named like the recipe's with more letters is not inside it.
  fs::create_directories(base_ / "recipe2");
  EXPECT_NE(refusal("../recipe2/x.obj").find("outside"), std::string::npos);
}

TEST_F(ConfinedPath, AllowedFoldersAreTrusted) {
  EXPECT_EQ(confined_path(recipe_, "../elsewhere/a.obj", std::vector<fs::path>{base_ / "elsewhere"}), base_ / "elsewhere" / "a.obj");
  EXPECT_NE(refusal("../secret.obj", {base_ / "elsewhere"}).find("outside"), std::string::npos);
}

// What a batch resolves its buildings' files with: confined_path's answers,
// kept; its refusals are not kept, so a name is refused however often it is
// asked for and accepted once its link is put right.
TEST_F(ConfinedPath, TheBatchesMemoGivesConfinedPathsAnswersAndKeepsNoRefusal) {
  ConfinedPathMemo memo;
  const std::vector<fs::path> allowed{base_ / "elsewhere"};
  for (int pass = 0; pass < 2; ++pass) {
    EXPECT_EQ(memo.resolve(recipe_, "lib/a.obj"), recipe_ / "lib" / "a.obj");
    EXPECT_EQ(memo.resolve(recipe_, "../elsewhere/a.obj", allowed), base_ / "elsewhere" / "a.obj");
    EXPECT_THROW(memo.resolve(recipe_, "../elsewhere/a.obj"), IoError) << "allowed by another call's folders";
    EXPECT_THROW(memo.resolve(recipe_, "../secret.obj"), IoError);
    EXPECT_THROW(memo.resolve(base_ / "elsewhere", "../recipe/lib/a.obj"), IoError) << "another root";
  }
  fs::create_symlink(base_ / "secret.obj", recipe_ / "innocent.obj");
  for (int pass = 0; pass < 2; ++pass) {
    try {
      memo.resolve(recipe_, "innocent.obj");
      ADD_FAILURE() << "a symlink out of the folder was followed";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("outside"), std::string::npos) << e.what();
    }
  }
  fs::remove(recipe_ / "innocent.obj");
  std::ofstream(recipe_ / "lib" / "b.obj") << "v 0 0 0\n";
  fs::create_symlink(recipe_ / "lib" / "b.obj", recipe_ / "innocent.obj");
  EXPECT_EQ(memo.resolve(recipe_, "innocent.obj"), recipe_ / "lib" / "b.obj");
}

}  // namespace
}  // namespace procex

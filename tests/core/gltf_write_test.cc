// write_glb's own JSON: names that need escaping come back unchanged, an
// empty scene is still a valid file, and data procex could not read back
// (or JSON cannot hold) is refused, naming the building, before anything is written.

#include <filesystem>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "base/read_file.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "tests/support/gltf_scripts.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

// One triangle tagged `tag`, for a building named `name`.
GltfMeshData triangle(const std::string& name, const std::string& tag, float x = 0) {
  GltfMeshData m;
  m.building = name;
  m.feature = 3;
  m.primitives.push_back({tag, {x, 0, 0, x + 1, 0, 0, x, 1, 0}, {0, 0, 1, 0, 0, 1, 0, 0, 1}, {0, 1, 2}, {}, {}});
  return m;
}

class GltfWrite : public test::ScratchDirTest {
 protected:
  void expect_refused(const GltfMeshData& mesh, const std::string& words) {
    const fs::path file = dir_ / "bad.glb";
    try {
      write_glb(file, {triangle("fine", "wall"), mesh});
      ADD_FAILURE() << "written: " << words;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(file));
  }
};

TEST_F(GltfWrite, NamesThatNeedEscapingRoundTrip) {
  const std::string name = "say \"hi\"\\ \n\t\x01 caf\xc3\xa9 \xe2\x86\x92";
  const fs::path file = dir_ / "names.glb";
  write_glb(file, {triangle(name, "tag \"q\""), triangle("b", "wall", 2)});
  const std::vector<GltfMeshData> back = read_glb(file);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].building, name);
  EXPECT_EQ(back[0].feature, 3);
  EXPECT_EQ(back[0].primitives.at(0).tag, "tag \"q\"");
  EXPECT_EQ(back[1].primitives.at(0).positions, triangle("b", "wall", 2).primitives[0].positions);
  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", file);
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
  EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
}

// A building on the plan's x axis stands at glTF z = -0 (z is minus north):
// written as 0, since reading "-0" back gives 0, and a merged file (written
// from what is read back) must have the bytes of one run.
TEST_F(GltfWrite, NegativeZeroIsWrittenAsZero) {
  GltfMeshData b = triangle("b", "wall");
  b.origin = {40, 0, -0.0};
  write_glb(dir_ / "first.glb", {b});
  const std::string first = read_file(dir_ / "first.glb", kMaxDataFileBytes);
  EXPECT_NE(first.find(R"("translation":[40,0,0])"), std::string::npos);
  write_glb(dir_ / "again.glb", read_glb(dir_ / "first.glb"));
  EXPECT_TRUE(read_file(dir_ / "again.glb", kMaxDataFileBytes) == first);
}

TEST_F(GltfWrite, EmptySceneIsAValidFile) {
  const fs::path file = dir_ / "empty.glb";
  GltfMeshData nothing;  // no triangles, no instances: not written
  nothing.building = "void";
  write_glb(file, {nothing});
  EXPECT_TRUE(read_glb(file).empty());
  EXPECT_EQ(fs::file_size(file) % 4, 0u);
  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", file);
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
}

TEST_F(GltfWrite, UnwritableMeshesAreRefused) {
  GltfMeshData m = triangle("short", "wall");
  m.primitives[0].normals.pop_back();
  expect_refused(m, "mesh 'short' has 8 normal and 9 position coordinates in primitive 'wall'");
  m = triangle("far", "wall");
  m.primitives[0].indices[2] = 3;
  expect_refused(m, "mesh 'far' has indices that are not triangles of its 3 vertices");
  m = triangle("nan", "wall");
  m.primitives[0].positions[4] = std::numeric_limits<float>::quiet_NaN();
  expect_refused(m, "mesh 'nan' has a vertex that is not finite");
  expect_refused(triangle("latin1", "caf\xe9"), "mesh 'latin1' has a tag that is not UTF-8");
}

}  // namespace
}  // namespace procex

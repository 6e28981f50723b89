// File > Export without a window: the shown meshes written by procex eval's
// writer, labelled with the dropped feature and the recipe's exposed values;
// what cannot be written says why and writes nothing.
#include "app/studio/editor/export_meshes.h"

#include <gtest/gtest.h>

#include "core/io/mesh_read.h"
#include "graph/pxg.h"
#include "tests/studio/studio_test_util.h"

namespace procex::studio {
namespace {

using namespace std::chrono_literals;

std::shared_ptr<const EvalSnapshot> evaluated(const Graph& g) {
  static EvalWorker worker;
  worker.submit(1, g);
  EXPECT_TRUE(worker.wait_idle(60s));
  return worker.latest();
}

TEST(ExportMeshes, WritesTheShownMeshLabelledWithTheFeature) {
  const auto dir = test::temp_dir();
  const Graph g = load_pxg(test::house_recipe());
  const auto shown = evaluated(g);
  ASSERT_TRUE(shown && shown->preview);
  GeoJsonFeature plot;
  plot.id = "plot-7";
  plot.properties["roof"] = "\"hip\"";
  const Result<std::size_t> obj = export_meshes(g, *shown, dir / "house.obj", {}, &plot);
  ASSERT_TRUE(obj) << obj.message();
  EXPECT_EQ(*obj, 1u);
  EXPECT_EQ(read_mesh_file(dir / "house.obj").n_faces(), shown->preview->faces);
  EXPECT_NE(test::read_text(dir / "house.obj").find("o plot-7"), std::string::npos) << "one object per building, named by its id";
  ASSERT_TRUE(export_meshes(g, *shown, dir / "house.glb", {}, &plot));
  EXPECT_NE(test::read_text(dir / "house.glb").find("\"roof\":\"hip\""), std::string::npos) << "the feature's properties in extras";
}

TEST(ExportMeshes, RefusalsSayWhyAndWriteNothing) {
  const auto dir = test::temp_dir();
  const Graph g = load_pxg(test::house_recipe());
  const auto shown = evaluated(g);
  ASSERT_TRUE(shown);
  const Result<std::size_t> unknown = export_meshes(g, *shown, dir / "house.stl", {}, nullptr);
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.message().find("unknown mesh format '.stl'"), std::string::npos) << unknown.message();
  ExportOptions geographic;
  geographic.crs = "EPSG:4326";
  const Result<std::size_t> gpkg = export_meshes(g, *shown, dir / "house.gpkg", geographic, nullptr);
  ASSERT_FALSE(gpkg);
  EXPECT_NE(gpkg.message().find("geographic"), std::string::npos) << gpkg.message();
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  const Result<std::size_t> nothing = export_meshes(g, EvalSnapshot{}, dir / "house.obj", {}, nullptr);
  ASSERT_FALSE(nothing);
  EXPECT_NE(nothing.message().find("nothing to export"), std::string::npos);
}

}  // namespace
}  // namespace procex::studio

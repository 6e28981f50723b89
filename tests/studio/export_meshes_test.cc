// File > Export without a window: the shown meshes written by procex eval's
// writer, labelled with the features of a footprint file given to the preview
// and the recipe's exposed values;
// what cannot be written says why and writes nothing.
#include "app/studio/editor/export_meshes.h"

#include <gtest/gtest.h>

#include "app/cli/feature_binding.h"
#include "core/io/footprint_read.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
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

TEST(ExportMeshes, WritesTheShownMesh) {
  const auto dir = test::temp_dir();
  const Graph g = load_pxg(test::house_recipe());
  const auto shown = evaluated(g);
  ASSERT_TRUE(shown && shown->preview);
  const Result<std::size_t> obj = export_meshes(g, *shown, dir / "house.obj", {});
  ASSERT_TRUE(obj) << obj.message();
  EXPECT_EQ(*obj, 1u);
  EXPECT_EQ(read_mesh_file(dir / "house.obj").n_faces(), shown->preview->faces);
}

// With a footprint file given to the preview: every feature's buildings,
// each labelled with its feature's id and properties, as procex batch writes them.
TEST(ExportMeshes, WritesEveryFeaturesBuildingsLabelledWithIt) {
  const auto dir = test::temp_dir();
  const std::filesystem::path samples = PROCEX_SAMPLES;
  const Graph city = load_pxg(samples / "city.pxg");
  GeoJsonCollection terrace = read_footprints(samples / "footprints" / "terrace.geojson");
  ASSERT_EQ(terrace.features.size(), 3u);  // and three streets
  add_edge_labels(city, terrace);
  EvalWorker worker;
  worker.submit(1, city, {}, preview_bindings(city, preview_footprint()), samples,
                std::make_shared<const std::vector<GeoJsonFeature>>(terrace.features));
  ASSERT_TRUE(worker.wait_idle(60s));
  const auto shown = worker.latest();
  ASSERT_TRUE(shown && shown->preview);
  ASSERT_EQ(shown->feature_meshes.size(), 3u);
  const Result<std::size_t> obj = export_meshes(city, *shown, dir / "terrace.obj", {});
  ASSERT_TRUE(obj) << obj.message();
  // The .mtl names the door's texture where it lies, in samples/meshes: read
  // back by our own trusted output, not confined to the export's folder.
  const auto as_written = [](const std::filesystem::path& name) { return name; };
  EXPECT_EQ(read_mesh_file(dir / "terrace.obj", nullptr, as_written).n_faces(), shown->preview->faces) << "every building";
  const std::string text = test::read_text(dir / "terrace.obj");
  for (const char* id : {"a", "b", "c"}) EXPECT_NE(text.find(std::string("\no ") + id), std::string::npos) << "an object named by feature " << id;
  ASSERT_TRUE(export_meshes(city, *shown, dir / "terrace.glb", {}));
  EXPECT_NE(test::read_text(dir / "terrace.glb").find("\"building\":\"house\""), std::string::npos) << "the features' properties in extras";
}

TEST(ExportMeshes, RefusalsSayWhyAndWriteNothing) {
  const auto dir = test::temp_dir();
  const Graph g = load_pxg(test::house_recipe());
  const auto shown = evaluated(g);
  ASSERT_TRUE(shown);
  const Result<std::size_t> unknown = export_meshes(g, *shown, dir / "house.stl", {});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.message().find("unknown mesh format '.stl'"), std::string::npos) << unknown.message();
  ExportOptions geographic;
  geographic.crs = "EPSG:4326";
  const Result<std::size_t> gpkg = export_meshes(g, *shown, dir / "house.gpkg", geographic);
  ASSERT_FALSE(gpkg);
  EXPECT_NE(gpkg.message().find("geographic"), std::string::npos) << gpkg.message();
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  const Result<std::size_t> nothing = export_meshes(g, EvalSnapshot{}, dir / "house.obj", {});
  ASSERT_FALSE(nothing);
  EXPECT_NE(nothing.message().find("nothing to export"), std::string::npos);
}

// Opening a .glb in the studio: the file procex wrote previews as the recipe
// did, face for face and tag for tag, in procex's frame, placed meshes instanced.
TEST(ExportMeshes, AWrittenGlbPreviewsAsTheRecipeDid) {
  const auto dir = test::temp_dir();
  for (const char* name : {"house.pxg", "windows.pxg"}) {
    SCOPED_TRACE(name);
    const std::filesystem::path recipe = std::filesystem::path(PROCEX_TEST_DATA) / name;
    const Graph g = load_pxg(recipe);
    EvalWorker worker;
    worker.submit(1, g, {}, {}, recipe.parent_path());
    ASSERT_TRUE(worker.wait_idle(60s));
    const auto shown = worker.latest();
    ASSERT_TRUE(shown && shown->preview && !shown->preview->empty());
    const std::filesystem::path glb = dir / (std::string(name) + ".glb");
    ASSERT_TRUE(export_meshes(g, *shown, glb, {}));
    const PreviewMesh& want = *shown->preview;
    if (std::string(name) == "windows.pxg") {
      EXPECT_GT(want.instances, 0u) << "the placed windows are instanced";
    }
    const PreviewMesh got = make_preview(read_glb_scene(glb));
    EXPECT_EQ(got.meshes, want.meshes);
    EXPECT_EQ(got.faces, want.faces);
    EXPECT_EQ(got.instances, want.instances);
    EXPECT_EQ(got.placed.size(), want.placed.size());
    EXPECT_EQ(got.vertex_count(), want.vertex_count());
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(got.min[k], want.min[k], 1e-4);
      EXPECT_NEAR(got.max[k], want.max[k], 1e-4);
    }
    ASSERT_EQ(got.tags.size(), want.tags.size());
    for (std::size_t i = 0; i < want.tags.size(); ++i) {
      EXPECT_EQ(got.tags[i].name, want.tags[i].name);
      EXPECT_EQ(got.tags[i].faces, want.tags[i].faces) << want.tags[i].name;
      EXPECT_NEAR(got.tags[i].area, want.tags[i].area, 1e-5 * want.tags[i].area) << want.tags[i].name;
    }
    // Outlines only: the triangulation's diagonals are not edges.
    EXPECT_EQ(got.edge_points.size() / 6, 2 * want.edge_points.size() / 6) << "each face draws its own outline, where the mesh shares an edge between two faces";
  }
}

}  // namespace
}  // namespace procex::studio

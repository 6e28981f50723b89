// Every node that names a file keeps to the recipe's folder (after symlinks),
// unless the user allowed another folder: a shared recipe cannot read
// ../secret.obj into its output, echo /etc/passwd in an error, or write a
// mesh over a file elsewhere.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::run_node;

class ConfinedFiles : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    base_ = fs::weakly_canonical(dir_);
    recipe_ = base_ / "recipe";
    fs::create_directories(recipe_);
    fs::copy_file(fs::path(PROCEX_TEST_DATA) / "mesh_window_frame.obj", base_ / "secret.obj");
    std::ofstream(base_ / "secret.geojson") << R"({"type": "FeatureCollection", "features": [{"type": "Feature",
      "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[9,0],[9,9],[0,9]]]}}]})";
  }

  // The node with its `file` parameter, evaluated as a recipe in recipe_.
  EvalResult evaluate(const std::string& type, const std::string& file, const std::vector<fs::path>& allowed = {}) {
    Graph g;
    const NodeId n = g.add_node(type).value();
    EXPECT_TRUE(g.set_param(n, "file", Value::make(file)));
    const ValueType& out = *g.node(n)->decl().outputs().at(0).type;
    EXPECT_TRUE(g.add_output({"out", &out, ""}));
    EXPECT_TRUE(g.connect(PortRef{n, 0}, PortRef{kGraphOutputs, 0}));
    if (type != "Footprint GeoJSON") {  // Export and Mesh Placement take a building
      const NodeId e = g.add_node("Extrude").value();
      const NodeId f = g.add_node("Footprint Polygon").value();
      EXPECT_TRUE(g.connect(PortRef{f, 0}, PortRef{e, 0}));
      EXPECT_TRUE(g.connect(PortRef{e, 0}, PortRef{n, 0}));
    }
    ResultCache cache(1 << 20);
    Evaluator ev(cache, "confined files test");
    EvalOptions options;
    options.folder = recipe_;
    options.allowed_folders = allowed;
    return ev.evaluate(g, {}, {}, options);
  }
  static std::string messages(const EvalResult& r) {
    std::string out;
    for (const Diagnostic& d : r.diagnostics) out += d.to_string() + "\n";
    return out;
  }
  void expect_refused(const std::string& type, const std::string& file) {
    const EvalResult r = evaluate(type, file);
    EXPECT_FALSE(r.ok()) << type << " " << file;
    EXPECT_NE(messages(r).find("lies outside the recipe's folder"), std::string::npos) << type << " " << file << ": " << messages(r);
  }
  fs::path base_, recipe_;
};

TEST_F(ConfinedFiles, FootprintGeoJsonReadsOnlyInside) {
  expect_refused("Footprint GeoJSON", "../secret.geojson");
  expect_refused("Footprint GeoJSON", "/etc/passwd");
  // GIS files GDAL reads (core/io/footprint_read.h) are confined the same way, /vsi paths included.
  expect_refused("Footprint GeoJSON", "../secret.gpkg");
  expect_refused("Footprint GeoJSON", "/vsicurl/https://example.com/buildings.shp");
  fs::create_symlink(base_ / "secret.geojson", recipe_ / "plan.geojson");
  expect_refused("Footprint GeoJSON", "plan.geojson");
  EXPECT_TRUE(evaluate("Footprint GeoJSON", "../secret.geojson", {base_}).ok());
}

TEST_F(ConfinedFiles, MeshPlacementReadsOnlyInside) {
  expect_refused("Mesh Placement", "../secret.obj");
  expect_refused("Mesh Placement", (base_ / "secret.obj").string());
  fs::create_directory_symlink(base_, recipe_ / "parts");
  expect_refused("Mesh Placement", "parts/secret.obj");
  fs::copy_file(base_ / "secret.obj", recipe_ / "window.obj");
  const EvalResult inside = evaluate("Mesh Placement", "window.obj");
  EXPECT_EQ(messages(inside).find("outside"), std::string::npos) << messages(inside);
}

TEST_F(ConfinedFiles, ExportWritesOnlyInside) {
  expect_refused("Export", "../escaped.glb");
  expect_refused("Export", (base_ / "escaped.glb").string());
  fs::create_directories(base_ / "elsewhere");
  fs::create_directory_symlink(base_ / "elsewhere", recipe_ / "out");
  expect_refused("Export", "out/model.glb");
  EXPECT_FALSE(fs::exists(base_ / "escaped.glb"));
  EXPECT_FALSE(fs::exists(base_ / "elsewhere" / "model.glb"));
  const EvalResult inside = evaluate("Export", "model.glb");
  ASSERT_TRUE(inside.ok()) << messages(inside);
  EXPECT_TRUE(fs::exists(recipe_ / "model.glb"));
  ASSERT_TRUE(evaluate("Export", "out/model.glb", {base_ / "elsewhere"}).ok());
  EXPECT_TRUE(fs::exists(base_ / "elsewhere" / "model.glb"));
}

TEST_F(ConfinedFiles, GroupFilesFollowTheSameRule) {
  fs::create_directories(base_ / "lib");
  std::ofstream(base_ / "lib" / "g.pxg") << R"({"format": "procex-graph", "version": 2})";
  fs::create_directory_symlink(base_ / "lib", recipe_ / "lib");
  std::ofstream(recipe_ / "r.pxg") << R"({"format": "procex-graph", "version": 2, "groups": [{"name": "g", "file": "lib/g.pxg"}]})";
  try {
    load_pxg(recipe_ / "r.pxg");
    FAIL() << "followed a symlink out of the recipe's folder";
  } catch (const PxgError& e) {
    EXPECT_NE(e.message().find("lies outside the recipe's folder"), std::string::npos) << e.what();
  }
  PxgOptions trusted;
  trusted.allowed_folders = {base_ / "lib"};
  EXPECT_NO_THROW(load_pxg(recipe_ / "r.pxg", trusted));
}

}  // namespace
}  // namespace procex

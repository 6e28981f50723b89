// File > Export driven by real X input, once per format procex eval writes,
// each file checked by what reads it: the Khronos glTF validator (.glb),
// procex's OBJ reader and OpenMesh's PLY reader, GDAL/OGR's Python bindings
// (.gpkg, tools/read_geopackage.py), cityjson-threejs-loader (CityJSON 2.0,
// tools/load_cityjson_three.mjs); and each byte for byte the file
// `procex eval` writes for the recipe, since both go through one writer.
// A CRS a GeoPackage cannot take is refused in the status bar, nothing written.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "core/io/mesh_read.h"
#include "tests/studio/interaction/studio_driver.h"

namespace procex::studio {
namespace {

using namespace driver;
using namespace std::chrono_literals;

const fs::path kTools = PROCEX_TOOLS;

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Exit code and output (stdout and stderr) of a shell command.
std::pair<int, std::string> run(const std::string& command) {
  std::pair<int, std::string> r{-1, ""};
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.second.append(buf, n);
  const int status = pclose(pipe);
  r.first = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// Waits for `name` on the map: listed once the popup holding it has placed itself.
json placed(Studio& studio, const std::string& name) {
  return studio.wait(name, [&](const json& j) { return j["buttons"].contains(name); });
}

// File > Export..., the format's button, the CRS for a GeoPackage, Export.
json export_as(Studio& studio, json map, const std::string& extension, const std::string& crs = "") {
  click(button_centre(map, "menu_file"));
  map = placed(studio, "menu_export");
  click(button_centre(map, "menu_export"));
  map = placed(studio, "export_format" + extension);
  const auto format_is = [&](const json& j) { return j.contains("prompt") && j["prompt"]["path"].get<std::string>().ends_with(extension); };
  click(button_centre(map, "export_format" + extension));
  map = studio.wait("the format " + extension, format_is);
  if (!crs.empty()) {
    map = placed(studio, "export_crs");
    click(button_centre(map, "export_crs"));
    type_into_focused_field(studio, "the CRS field", crs);
    map = studio.wait("the CRS", [&](const json& j) { return j.contains("prompt") && j["prompt"]["crs"] == crs; });
  }
  const std::string path = map["prompt"]["path"];
  // The dialog sizes itself to what the format shows: the button is where the newest frame put it.
  const auto closed = [](const json& j) { return !j.contains("prompt"); };
  click(button_centre(placed(studio, "prompt_ok"), "prompt_ok"));
  map = studio.wait("the dialog closed", closed);
  return studio.wait("the export of " + path, [&](const json& j) { return closed(j) && j["status"].get<std::string>().find(path) != std::string::npos; });
}

TEST(StudioExport, EveryFormatTheCliWritesReadsBackAndMatchesTheCliByteForByte) {
  ASSERT_EQ(run("node --version").first, 0) << "node (Node.js) is not installed: the glTF validator needs it (scripts/install-deps.sh)";
  ASSERT_TRUE(fs::exists(kTools / "node_modules" / "gltf-validator")) << "run scripts/install-deps.sh (or: cd tools && npm ci)";
  const fs::path dir = fresh_dir("export");
  const fs::path recipe = copy_test_recipe("house.pxg", dir);
  Studio studio(recipe, dir);
  json map = studio.wait("the house evaluated", [](const json& j) { return j["settled"] && j["preview_faces"] > 0; });
  const std::size_t faces = map["preview_faces"];
  const std::string crs = "EPSG:32632";

  // Longitude/latitude is no frame for metres: refused in the status bar, nothing written.
  map = export_as(studio, map, ".gpkg", "EPSG:4326");
  EXPECT_NE(map["status"].get<std::string>().find("geographic"), std::string::npos) << map["status"];
  EXPECT_FALSE(fs::exists(dir / "house.gpkg"));
  // The CRS field keeps what was typed (the refused EPSG:4326) for every
  // format that shows it: the .glb records its CRS too, so it is given again.
  const auto takes_crs = [](const std::string& extension) { return extension == ".glb" || extension == ".gpkg" || extension == ".json"; };
  const auto formats = {".glb", ".obj", ".ply", ".gpkg", ".json"};
  for (const char* extension : formats) {
    map = export_as(studio, map, extension, takes_crs(extension) ? crs : "");
    EXPECT_EQ(map["status"], "exported 1 mesh to " + (dir / "house").string() + extension);
  }
  press("ctrl+q");
  EXPECT_EQ(studio.wait_exit(20s), 0);

  // The same bytes as procex eval's.
  fs::create_directories(dir / "cli");
  for (const char* extension : formats) {
    SCOPED_TRACE(extension);
    const fs::path cli = dir / "cli" / (std::string("house") + extension);
    const auto [code, out] = run(std::string(PROCEX_CLI_EXE) + " eval " + recipe.string() + " -o " + cli.string() +
                                 (takes_crs(extension) ? " --crs " + crs : std::string()));
    ASSERT_EQ(code, 0) << out;
    EXPECT_TRUE(read_bytes(dir / (std::string("house") + extension)) == read_bytes(cli));
  }
  EXPECT_TRUE(read_bytes(dir / "house.mtl") == read_bytes(dir / "cli" / "house.mtl"));

  // What reads each format finds the building.
  const auto [glb_code, glb_report] = run("node " + (kTools / "validate_gltf.mjs").string() + " " + (dir / "house.glb").string());
  EXPECT_EQ(glb_code, 0) << glb_report;
  const json report = json::parse(glb_report, nullptr, false);
  ASSERT_FALSE(report.is_discarded()) << glb_report;
  EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_GT(report["info"]["totalTriangleCount"].get<int>(), 0);

  EXPECT_EQ(read_mesh_file(dir / "house.obj").n_faces(), faces);
  EXPECT_NE(read_bytes(dir / "house.obj").find("mtllib house.mtl"), std::string::npos);
  OpenMesh::PolyMesh_ArrayKernelT<> ply;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(ply, (dir / "house.ply").string()));
  EXPECT_EQ(ply.n_faces(), faces);

  const fs::path gis = dir / "gis.json";
  const auto [gis_code, gis_log] = run(std::string(PROCEX_PYTHON) + " " + (kTools / "read_geopackage.py").string() + " " +
                                       (dir / "house.gpkg").string() + " '" + crs + "' " + gis.string());
  ASSERT_EQ(gis_code, 0) << "GDAL's Python bindings (python3-gdal, scripts/install-deps.sh) failed:\n" << gis_log;
  const json layers = json::parse(read_bytes(gis))["layers"];
  EXPECT_EQ(layers["buildings"]["features"], 1);
  EXPECT_EQ(layers["surfaces"]["features"].get<std::size_t>(), faces);
  EXPECT_TRUE(layers["buildings"]["crs_same"]);

  const auto [city_code, city_out] = run("node " + (kTools / "load_cityjson_three.mjs").string() + " " + (dir / "house.json").string());
  ASSERT_EQ(city_code, 0) << city_out;
  const json city = json::parse(city_out, nullptr, false);
  ASSERT_FALSE(city.is_discarded()) << city_out;
  EXPECT_EQ(city["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/32632");
  ASSERT_EQ(city["objects"].size(), 1u);
  EXPECT_EQ(city["objects"].begin().value()["type"], "Building");
  EXPECT_GT(city["objects"].begin().value()["lods"]["2.2"]["triangles"].value("RoofSurface", 0), 0);
}

}  // namespace
}  // namespace procex::studio

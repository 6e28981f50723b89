// `procex batch -o city.gpkg` read back by GDAL/OGR's Python bindings
// (tools/read_geopackage.py, Debian's python3-gdal), as a GIS reads it: one
// feature per building named by its id, at the coordinates and heights the
// batch report gives, enclosing the report's volume, with the feature's
// properties as typed columns, its surfaces by tag, and the CRS it was
// given, which PROJ takes back to where the footprints are on the Earth.
// CRSs that cannot georeference metres are refused before any work.
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path& kRoot = test::kRepository;
const fs::path& kBlock = test::kSampleBlock;

class GisExport : public test::CommandTest {
 protected:
  int batch(const fs::path& footprints, const std::string& crs, const std::string& output = "city.gpkg",
            const std::string& target_crs = "") {
    BatchCommandOptions o;
    o.recipe = kRoot / "samples" / "city.pxg";
    o.footprints = footprints;
    o.output = dir_ / output;
    o.report = dir_ / "city.json";
    o.progress = false;
    o.export_options.crs = crs;
    o.target_crs = target_crs;
    return run_batch(o, out_, err_);
  }
  // What GDAL reads in `file`, the layers compared with `crs`.
  json read_back(const fs::path& file, const std::string& crs) {
    const fs::path result = dir_ / "read.json", log = dir_ / "read.log";
    const int status = std::system((std::string(PROCEX_PYTHON) + " " + (kRoot / "tools" / "read_geopackage.py").string() +
                                    " " + file.string() + " '" + crs + "' " + result.string() + " > " + log.string() +
                                    " 2>&1")
                                       .c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "GDAL's Python bindings (python3-gdal, scripts/install-deps.sh) failed:\n" << test::read_text(log);
    return json::parse(test::read_text(result));
  }
};


TEST_F(GisExport, EachBuildingIsAFeatureWhereTheReportPutsItInItsCrs) {
  const std::string crs = test::sample_block_crs();
  ASSERT_EQ(batch(kBlock, crs), 0) << err_.str();
  const json gis = read_back(dir_ / "city.gpkg", crs);
  const json report = json::parse(test::read_text(dir_ / "city.json"));
  const json block = json::parse(test::read_text(kBlock));

  ASSERT_EQ(gis["layers"]["buildings"]["features"], 18);
  EXPECT_EQ(gis["layers"]["buildings"]["geometry"], "3D Multi Polygon");
  EXPECT_EQ(gis["layers"]["surfaces"]["geometry"], "3D Polygon");
  for (const char* layer : {"buildings", "surfaces"}) EXPECT_TRUE(gis["layers"][layer]["crs_same"]) << layer;

  std::size_t faces = 0;
  for (const json& b : report["buildings"]) {
    const std::string id = b["id"];
    SCOPED_TRACE(id);
    ASSERT_TRUE(gis["buildings"].contains(id));
    const json& g = gis["buildings"][id];
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(g["min"][k].get<double>(), b["bounds"]["min"][k].get<double>(), 1e-9) << "axis " << k;
      EXPECT_NEAR(g["max"][k].get<double>(), b["bounds"]["max"][k].get<double>(), 1e-9) << "axis " << k;
    }
    const double volume = b["volume"];
    EXPECT_NEAR(g["volume"].get<double>(), volume, 1e-6 * volume);
    EXPECT_NEAR(g["attributes"]["procex_volume"]["value"].get<double>(), volume, 1e-6 * volume);
    EXPECT_NEAR(g["attributes"]["procex_height"]["value"].get<double>(),
                b["bounds"]["max"][2].get<double>() - b["bounds"]["min"][2].get<double>(), 1e-9);
    EXPECT_EQ(g["polygons"], b["faces"]);
    EXPECT_EQ(g["tags"], b["faces_per_tag"]);
    faces += b["faces"].get<std::size_t>();
    // The footprints lie around Monaco's cathedral: PROJ takes them back near their frame's
    // origin (within a kilometre; degrees taken as metres would be thousands of kilometres off).
    EXPECT_NEAR(g["lonlat"][0].get<double>(), 7.4251, 0.01);
    EXPECT_NEAR(g["lonlat"][1].get<double>(), 43.7371, 0.01);
  }
  EXPECT_EQ(gis["layers"]["surfaces"]["features"], faces);

  // The properties as typed columns, each building's values as its feature had them.
  for (const json& f : block["features"]) {
    const json& a = gis["buildings"][f["id"].get<std::string>()]["attributes"];
    EXPECT_EQ(a["area_m2"]["type"], "Real");
    EXPECT_DOUBLE_EQ(a["area_m2"]["value"].get<double>(), f["properties"]["area_m2"].get<double>());
    EXPECT_EQ(a["building"]["type"], "String");
    EXPECT_EQ(a["building"]["value"], f["properties"].value("building", json()));  // absent: an empty cell
    EXPECT_EQ(a["valid"]["type"], "Boolean");
    EXPECT_EQ(a["valid"]["value"].get<int>() != 0, f["properties"]["valid"].get<bool>());
  }
}

TEST_F(GisExport, TheFootprintsCrsMemberIsUsedWhenNoneIsGiven) {
  json block = json::parse(test::read_text(kBlock));
  block["crs"] = {{"type", "name"}, {"properties", {{"name", "urn:ogc:def:crs:EPSG::32632"}}}};
  const fs::path footprints = dir_ / "block_utm.geojson";
  std::ofstream(footprints) << block.dump();
  ASSERT_EQ(batch(footprints, ""), 0) << err_.str();
  const json gis = read_back(dir_ / "city.gpkg", "EPSG:32632");
  EXPECT_TRUE(gis["layers"]["buildings"]["crs_same"]);
  EXPECT_EQ(gis["layers"]["buildings"]["features"], 18);
}

TEST_F(GisExport, CrsThatCannotHoldMetresAreRefusedBeforeAnyWork) {
  // The footprints' CRS (--crs) and the one to build and write in (--target-crs).
  const std::map<std::pair<std::string, std::string>, std::string> refused = {
      {{"", ""}, "--crs"},
      {{"EPSG:4326", ""}, "geographic but its coordinates are not"},  // metres are no degrees
      {{test::sample_block_crs(), "EPSG:4326"}, "geographic"},
      {{test::sample_block_crs(), "EPSG:2263"}, "units of 0.3048"},  // New York Long Island, US feet
      {{"EPSG:999999", ""}, "PROJ does not know"},
  };
  for (const auto& [crs, why] : refused) {
    SCOPED_TRACE(crs.first + " -> " + crs.second);
    err_.str("");
    EXPECT_EQ(batch(kBlock, crs.first, "city.gpkg", crs.second), 2);
    EXPECT_NE(err_.str().find(why), std::string::npos) << err_.str();
    EXPECT_FALSE(fs::exists(dir_ / "city.gpkg"));
    EXPECT_FALSE(fs::exists(dir_ / "city.json"));
  }
}

TEST_F(GisExport, OneGeoPackagePerBuildingInAFolder) {
  BatchCommandOptions o;
  o.recipe = kRoot / "samples" / "city.pxg";
  o.footprints = kBlock;
  o.output = dir_ / "per_building/";
  o.format = "gpkg";
  o.progress = false;
  o.export_options.crs = test::sample_block_crs();
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "per_building")) {
    EXPECT_EQ(entry.path().extension(), ".gpkg");
    const json gis = read_back(entry.path(), o.export_options.crs);
    EXPECT_EQ(gis["layers"]["buildings"]["features"], 1);
    EXPECT_TRUE(gis["buildings"].contains(entry.path().stem().string()));
    ++files;
  }
  EXPECT_EQ(files, 18u);
}

TEST_F(GisExport, TheSameBuildingsWriteTheSameBytes) {
  const std::string crs = test::sample_block_crs();
  ASSERT_EQ(batch(kBlock, crs, "a.gpkg"), 0) << err_.str();
  ASSERT_EQ(batch(kBlock, crs, "b.gpkg"), 0) << err_.str();
  EXPECT_EQ(test::read_text(dir_ / "a.gpkg"), test::read_text(dir_ / "b.gpkg"));
}

}  // namespace
}  // namespace procex

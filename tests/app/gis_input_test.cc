// Footprints from GIS files (core/io/footprint_read.h), made here by GDAL's
// ogr2ogr (Debian gdal-bin) from the metric sample block taken back to
// longitude/latitude with the local frame its "projection" member states: the
// same footprints as RFC 7946 GeoJSON, a Shapefile, a GeoPackage and a
// FlatGeobuf make the same buildings, as big as the metric sample's, placed
// where they are on the Earth in the GeoPackage output's CRS. A lon/lat file
// that declares no CRS is refused rather than taken as metres; only the listed
// GDAL drivers open a file; OSM gives its buildings with their tags.
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "app/cli/merge_command.h"
#include "core/io/footprint_read.h"
#include "core/io/io_error.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path& kRoot = test::kRepository;
const fs::path& kBlock = test::kSampleBlock;

class GisInput : public test::CommandTest {
 protected:
  // Runs a shell command, failing the test with its output if it fails.
  void run(const std::string& command) {
    const fs::path log = dir_ / "command.log";
    const int status = std::system((command + " > " + log.string() + " 2>&1").c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command << "\n" << test::read_text(log);
  }
  // The sample block in longitude/latitude as `name` (its format by its extension).
  fs::path lon_lat(const std::string& name) {
    const fs::path geojson = dir_ / "block_lonlat.geojson";
    if (!fs::exists(geojson))  // RFC 7946: WGS84 longitude/latitude, no "crs" member
      run("ogr2ogr -f GeoJSON -lco RFC7946=YES -lco COORDINATE_PRECISION=12 -s_srs '" + test::sample_block_crs() +
          "' -t_srs EPSG:4326 " + geojson.string() + " " + kBlock.string());
    if (name == geojson.filename()) return geojson;
    run("ogr2ogr " + (dir_ / name).string() + " " + geojson.string());
    return dir_ / name;
  }
  int batch(const fs::path& footprints, const std::string& crs, const std::string& name, const std::string& target = "",
            const std::string& extension = ".gpkg", int shard = 0, int shards = 1) {
    BatchCommandOptions o;
    o.recipe = kRoot / "samples" / "city.pxg";
    o.footprints = footprints;
    o.output = dir_ / (name + extension);
    o.shard = shard, o.shards = shards;
    o.report = dir_ / (name + ".json");
    o.progress = false;
    o.export_options.crs = crs;
    o.target_crs = target;
    return run_batch(o, out_, err_);
  }
  json report(const std::string& name) { return json::parse(test::read_text(dir_ / (name + ".json"))); }
  // The batch's GeoPackage as GDAL's Python bindings read it (tools/read_geopackage.py).
  json read_back(const std::string& name, const std::string& crs) {
    const fs::path result = dir_ / (name + ".read.json");
    run(std::string(PROCEX_PYTHON) + " " + (kRoot / "tools" / "read_geopackage.py").string() + " " +
        (dir_ / (name + ".gpkg")).string() + " '" + crs + "' " + result.string());
    return json::parse(test::read_text(result));
  }
  // The batch's .glb georeference as GDAL's Python bindings read it (tools/read_glb_georeference.py).
  json read_glb_back(const std::string& name, const std::string& crs) {
    const fs::path result = dir_ / (name + ".glb.json");
    run(std::string(PROCEX_PYTHON) + " " + (kRoot / "tools" / "read_glb_georeference.py").string() + " " +
        (dir_ / (name + ".glb")).string() + " '" + crs + "' " + result.string());
    return json::parse(test::read_text(result));
  }
  static std::map<std::string, json> by_id(const json& report) {
    std::map<std::string, json> out;
    for (const json& b : report["buildings"]) out[b["id"]] = b;
    return out;
  }
};

TEST_F(GisInput, EveryFormatMakesTheMetricSamplesBuildings) {
  ASSERT_EQ(batch(kBlock, test::sample_block_crs(), "metric"), 0) << err_.str();
  const auto metric = by_id(report("metric"));
  ASSERT_EQ(metric.size(), 18u);
  std::map<std::string, std::map<std::string, json>> made;
  for (const std::string file : {"block_lonlat.geojson", "block.shp", "block.gpkg", "block.fgb"}) {
    SCOPED_TRACE(file);
    const fs::path input = lon_lat(file);
    // The GeoJSON is RFC 7946 (no "crs"): --crs says so; the others carry their CRS.
    ASSERT_EQ(batch(input, file == "block_lonlat.geojson" ? "EPSG:4326" : "", file), 0) << err_.str();
    made[file] = by_id(report(file));
    ASSERT_EQ(made[file].size(), metric.size());
    for (const auto& [id, b] : made[file]) {
      SCOPED_TRACE(id);
      ASSERT_TRUE(metric.count(id));
      const json& m = metric.at(id);
      ASSERT_EQ(b["status"], "ok") << b["reason"];
      const double volume = b["volume"], metric_volume = m["volume"];
      EXPECT_NEAR(volume, metric_volume, 1e-6 * metric_volume);
      EXPECT_NEAR(volume, made.begin()->second.at(id)["volume"].get<double>(), 1e-6 * volume);
      EXPECT_NEAR(b["bounds"]["max"][2].get<double>(), m["bounds"]["max"][2].get<double>(), 1e-3);  // height
      EXPECT_EQ(b["faces_per_tag"], m["faces_per_tag"]);
    }
  }
}

TEST_F(GisInput, LonLatIsBuiltInALocalFrameTheGeoPackageCarries) {
  ASSERT_EQ(batch(kBlock, test::sample_block_crs(), "metric"), 0) << err_.str();
  const json metric = read_back("metric", test::sample_block_crs());
  ASSERT_EQ(batch(lon_lat("block.gpkg"), "", "lonlat"), 0) << err_.str();
  const GeoJsonCollection read = read_footprints(lon_lat("block.gpkg"));
  EXPECT_NE(read.crs.find("procex local transverse Mercator"), std::string::npos) << read.crs;
  const json gis = read_back("lonlat", read.crs);
  for (const char* layer : {"buildings", "surfaces"}) EXPECT_TRUE(gis["layers"][layer]["crs_same"]) << layer;

  // The frame's origin is the data's centre (to 1e-6 degree, ~0.1 m)...
  double low[2] = {1e300, 1e300}, high[2] = {-1e300, -1e300};
  for (const auto& [id, b] : gis["buildings"].items())
    for (int k = 0; k < 2; ++k)
      low[k] = std::min(low[k], b["min"][k].get<double>()), high[k] = std::max(high[k], b["max"][k].get<double>());
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(low[k] + high[k], 0.0, 0.5) << "axis " << k;
  // ...and PROJ takes every building back to where the metric sample's is on the Earth (1e-8 degree: ~1 mm).
  ASSERT_EQ(gis["buildings"].size(), 18u);
  for (const auto& [id, b] : gis["buildings"].items()) {
    SCOPED_TRACE(id);
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(b["lonlat"][k].get<double>(), metric["buildings"][id]["lonlat"][k].get<double>(), 1e-8);
    EXPECT_NEAR(b["volume"].get<double>(), metric["buildings"][id]["volume"].get<double>(),
                1e-6 * b["volume"].get<double>());
  }
}

TEST_F(GisInput, TargetCrsBuildsInTheFrameAsked) {
  ASSERT_EQ(batch(kBlock, test::sample_block_crs(), "metric"), 0) << err_.str();
  const auto metric = by_id(report("metric"));
  ASSERT_EQ(batch(lon_lat("block.shp"), "", "shp", test::sample_block_crs()), 0) << err_.str();
  for (const auto& [id, b] : by_id(report("shp")))
    for (const char* end : {"min", "max"})
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(b["bounds"][end][k].get<double>(), metric.at(id)["bounds"][end][k].get<double>(), 1e-3) << id;
  EXPECT_TRUE(read_back("shp", test::sample_block_crs())["layers"]["buildings"]["crs_same"]);
}

// A GIS user puts the .glb's buildings back on the Earth from its scene's CRS
// and each node's origin alone: the lon/lat footprints' buildings (made in
// the local frame) land where the metric sample's (made in its own CRS) do.
TEST_F(GisInput, TheGlbCarriesItsCrsSoBuildingsGoBackWhereTheyWere) {
  ASSERT_EQ(batch(kBlock, test::sample_block_crs(), "metric", "", ".glb"), 0) << err_.str();
  const json metric = read_glb_back("metric", test::sample_block_crs());
  EXPECT_TRUE(metric["crs_same"]) << metric["crs"];
  const fs::path gpkg = lon_lat("block.gpkg");
  ASSERT_EQ(batch(gpkg, "", "lonlat", "", ".glb"), 0) << err_.str();
  const json lonlat = read_glb_back("lonlat", read_footprints(gpkg).crs);
  EXPECT_TRUE(lonlat["crs_same"]) << lonlat["crs"];
  EXPECT_TRUE(lonlat["projected_metres"]);
  EXPECT_NE(lonlat["crs"].get<std::string>().find("procex local transverse Mercator"), std::string::npos);
  ASSERT_EQ(lonlat["buildings"].size(), 18u);
  ASSERT_EQ(metric["buildings"].size(), 18u);
  for (const auto& [id, b] : lonlat["buildings"].items()) {
    SCOPED_TRACE(id);
    const json& m = metric["buildings"][id];
    EXPECT_TRUE(b["origin_is_translation"]);
    EXPECT_TRUE(m["origin_is_translation"]);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(b["lonlat"][k].get<double>(), m["lonlat"][k].get<double>(), 1e-8);
    for (const char* end : {"min", "max"}) EXPECT_NEAR(b[end][2].get<double>(), m[end][2].get<double>(), 1e-3);
  }
  // The CRS is in the scene's extras, which the Khronos validator accepts without a warning.
  run("node " + (kRoot / "tools" / "validate_gltf.mjs").string() + " " + (dir_ / "lonlat.glb").string() + " | tee " +
      (dir_ / "validated.json").string());
  const json report = json::parse(test::read_text(dir_ / "validated.json"));
  EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"]["messages"].dump(1);
  EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"]["messages"].dump(1);
}

TEST_F(GisInput, TheGlbCrsRefusesDegreesAndSurvivesMerge) {
  // A geographic CRS for metres is refused, naming it, before anything is made.
  EvalCommandOptions eval;
  eval.recipe = kRoot / "samples" / "house.pxg";
  eval.output = dir_ / "degrees.glb";
  eval.export_options.crs = "EPSG:4326";
  ASSERT_EQ(run_eval(eval, out_, err_), 2);
  EXPECT_NE(err_.str().find("'EPSG:4326' is geographic"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(eval.output));
  eval.export_options.crs = "EPSG:32632";  // a house with no footprints stands at the CRS's origin
  ASSERT_EQ(run_eval(eval, out_, err_), 0) << err_.str();
  EXPECT_TRUE(read_glb_back("degrees", "EPSG:32632")["crs_same"]);
  // Shards made in one CRS merge into the bytes a single run writes, CRS included.
  const fs::path gpkg = lon_lat("block.gpkg");
  ASSERT_EQ(batch(gpkg, "", "whole", "", ".glb"), 0) << err_.str();
  ASSERT_EQ(batch(gpkg, "", "part0", "", ".glb", 0, 2), 0) << err_.str();
  ASSERT_EQ(batch(gpkg, "", "part1", "", ".glb", 1, 2), 0) << err_.str();
  MergeCommandOptions merge;
  merge.parts = {dir_ / "part0.glb", dir_ / "part1.glb"};
  merge.output = dir_ / "merged.glb";
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  EXPECT_EQ(test::read_text(dir_ / "merged.glb"), test::read_text(dir_ / "whole.glb"));
  // Shards made in different CRSs are no one run.
  ASSERT_EQ(batch(gpkg, "", "utm1", test::sample_block_crs(), ".glb", 1, 2), 0) << err_.str();
  merge.parts = {dir_ / "part0.glb", dir_ / "utm1.glb"};
  merge.output = dir_ / "mixed.glb";
  EXPECT_EQ(run_merge(merge, out_, err_), 2);
  EXPECT_NE(err_.str().find("CRS"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "mixed.glb"));
}

// A Shapefile is several files: shards made while a sidecar changed (here
// its .cpg, the encoding its .dbf's text is read in) are no one run, though
// the .shp is the same.
TEST_F(GisInput, ShardsOfAShapefileWhoseSidecarChangedAreNoOneRun) {
  const fs::path shp = lon_lat("block.shp");
  ASSERT_EQ(batch(shp, "", "part0", "", ".glb", 0, 2), 0) << err_.str();
  ASSERT_EQ(batch(shp, "", "part1", "", ".glb", 1, 2), 0) << err_.str();
  MergeCommandOptions merge;
  merge.parts = {dir_ / "part0.glb", dir_ / "part1.glb"};
  merge.output = dir_ / "merged.glb";
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();  // one run: they merge
  std::ofstream(dir_ / "block.cpg") << "ISO-8859-1";
  ASSERT_EQ(batch(shp, "", "edited1", "", ".glb", 1, 2), 0) << err_.str();
  merge.parts = {dir_ / "part0.glb", dir_ / "edited1.glb"};
  merge.output = dir_ / "mixed.glb";
  EXPECT_EQ(run_merge(merge, out_, err_), 2);
  EXPECT_NE(err_.str().find("another recipe, footprint file or streets file"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(merge.output));
}

TEST_F(GisInput, LonLatThatDeclaresNoCrsIsRefusedNotTakenAsMetres) {
  const fs::path lonlat = lon_lat("block_lonlat.geojson");
  EXPECT_EQ(batch(lonlat, "", "refused"), 2);
  EXPECT_NE(err_.str().find(lonlat.string()), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("--crs EPSG:4326"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "refused.json"));
  // A metric file whose coordinates happen to lie in longitude/latitude range is read as metres.
  const fs::path small = dir_ / "small.geojson";
  std::ofstream(small) << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
      "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [12, 0], [12, 8], [0, 8], [0, 0]]]}}]})";
  const GeoJsonCollection read = read_footprints(small);
  ASSERT_EQ(read.features.size(), 1u);
  EXPECT_EQ(read.features[0].loops[0][2], glm::dvec2(12, 8));
  EXPECT_TRUE(read.crs.empty());
  // Coordinates that are no longitude/latitude under a geographic --crs are refused.
  EXPECT_EQ(batch(kBlock, "EPSG:4326", "wrong"), 2);
  EXPECT_NE(err_.str().find("geographic but its coordinates are not"), std::string::npos) << err_.str();
}

TEST_F(GisInput, OnlyTheListedDriversOpenAFile) {
  const fs::path shp = lon_lat("block.shp");
  const fs::path vrt = dir_ / "block.vrt";
  std::ofstream(vrt) << "<OGRVRTDataSource><OGRVRTLayer name=\"block\"><SrcDataSource>" << shp.string()
                     << "</SrcDataSource></OGRVRTLayer></OGRVRTDataSource>";
  for (const fs::path& refused : {vrt, fs::path("/vsicurl/https://example.com/block.shp"), fs::path("/vsizip/" + shp.string())}) {
    SCOPED_TRACE(refused);
    try {
      read_footprints(refused);
      ADD_FAILURE() << "read";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(refused.string()), std::string::npos) << e.what();
    }
  }
}

TEST_F(GisInput, ABadFeatureIsReportedAndSkipped) {
  const fs::path geojson = dir_ / "mixed.geojson", gpkg = dir_ / "mixed_in.gpkg";
  std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"id": "a"}, "geometry": {"type": "Polygon",
     "coordinates": [[[7.4251, 43.7371], [7.4253, 43.7371], [7.4253, 43.7372], [7.4251, 43.7372], [7.4251, 43.7371]]]}},
    {"type": "Feature", "properties": {"id": "tree"}, "geometry": {"type": "Point",
     "coordinates": [7.4252, 43.7371]}}]})";
  run("ogr2ogr -nlt GEOMETRY " + gpkg.string() + " " + geojson.string());
  EXPECT_EQ(batch(gpkg, "", "mixed"), 0) << err_.str();  // as for a GeoJSON feature: reported, the batch goes on
  const auto made = by_id(report("mixed"));
  EXPECT_EQ(made.at("a")["status"], "ok") << made.at("a")["reason"];
  EXPECT_EQ(made.at("tree")["status"], "refused");  // (a LineString would be a street: street_edges_batch_test)
  EXPECT_NE(made.at("tree")["reason"].get<std::string>().find("layer 'mixed' (FID 2)"), std::string::npos);
  EXPECT_NE(made.at("tree")["reason"].get<std::string>().find("'Point' is not a Polygon"), std::string::npos);
}

// GDAL cuts a Shapefile's field names to 10 characters: the OSM building keys
// come back under their own names, so they bind as from any other format.
TEST_F(GisInput, ShapefileCutFieldNamesGetTheirKeysBack) {
  const fs::path geojson = dir_ / "levels.geojson", shp = dir_ / "levels.shp";
  std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"id": "a",
      "building:levels": 3, "building:min_level": 1, "roof:height": 2.5, "roof:levels": 1, "roof:direction": 90,
      "roof:orientation": "across", "roof:shape": "gabled", "height": 9, "colour": "red"},
      "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [12, 0], [12, 8], [0, 8], [0, 0]]]}}]})";
  run("ogr2ogr " + shp.string() + " " + geojson.string());
  const std::string dbf = test::read_text(dir_ / "levels.dbf");
  EXPECT_NE(dbf.find("building_l"), std::string::npos);  // what GDAL wrote: the cut name
  const GeoJsonCollection read = read_footprints(shp);
  ASSERT_EQ(read.features.size(), 1u);
  const GeoJsonFeature& f = read.features[0];
  EXPECT_EQ(f.property_number("building:levels"), 3.0);
  EXPECT_EQ(f.property_number("building:min_level"), 1.0);
  EXPECT_EQ(f.property_number("roof:height"), 2.5);
  EXPECT_EQ(f.property_number("roof:levels"), 1.0);
  EXPECT_EQ(f.property_number("roof:direction"), 90.0);
  EXPECT_EQ(f.property_text("roof:orientation"), "across");
  EXPECT_EQ(f.property_text("roof_shape"), "gabled");  // 10 characters: only ':' laundered, which binding reads as '_'
  EXPECT_EQ(f.property_number("height"), 9.0);
  EXPECT_EQ(f.property_text("colour"), "red");
  EXPECT_FALSE(f.properties.count("building_l"));
  // A GeoPackage keeps long names: a field that is named building_l there stays so.
  const fs::path gpkg = dir_ / "cut.gpkg";
  run("ogr2ogr " + gpkg.string() + " " + shp.string());
  EXPECT_TRUE(read_footprints(gpkg).features.at(0).properties.count("building_l"));
}

TEST_F(GisInput, LayerChoosesAmongAGeoPackagesLayers) {
  const fs::path gpkg = dir_ / "two.gpkg";
  for (const char* name : {"roads", "houses"}) {
    const fs::path geojson = dir_ / (std::string(name) + ".geojson");
    std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"id": ")"
                           << name << R"("}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [12, 0], [12, 8], [0, 8], [0, 0]]]}}]})";
    run("ogr2ogr " + std::string(fs::exists(gpkg) ? "-update " : "") + "-a_srs EPSG:32632 -nln " + name + " " +
        gpkg.string() + " " + geojson.string());
  }
  EXPECT_EQ(read_footprints(gpkg).features.at(0).id, "roads");  // the first, as before
  FootprintReadOptions houses;
  houses.layer = "houses";
  EXPECT_EQ(read_footprints(gpkg, houses).features.at(0).id, "houses");
  FootprintReadOptions missing;
  missing.layer = "buildings";
  try {
    read_footprints(gpkg, missing);
    ADD_FAILURE() << "read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("has no layer 'buildings': its layers are 'roads', 'houses'"), std::string::npos)
        << e.what();
  }
  // Through the CLI: batch --layer.
  BatchCommandOptions o;
  o.recipe = kRoot / "samples" / "city.pxg";
  o.footprints = gpkg;
  o.output = dir_ / "houses.gpkg";
  o.report = dir_ / "houses.json";
  o.progress = false;
  o.layer = "houses";
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  EXPECT_TRUE(by_id(report("houses")).count("houses"));
  o.layer = "nothing";
  EXPECT_EQ(run_batch(o, out_, err_), 2);
  EXPECT_NE(err_.str().find("its layers are 'roads', 'houses'"), std::string::npos) << err_.str();
  // A GeoJSON file has one layer: a name for it is a mistake, said so.
  try {
    read_footprints(kBlock, houses);
    ADD_FAILURE() << "read";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("holds one layer"), std::string::npos) << e.what();
  }
}

TEST_F(GisInput, OsmBuildingsWithTheirTags) {
  const fs::path osm = dir_ / "block.osm";
  std::ofstream(osm) << R"(<?xml version="1.0" encoding="UTF-8"?>
<osm version="0.6" generator="gis_input_test">
  <node id="1" lat="43.7371" lon="7.4251" version="1"/><node id="2" lat="43.7371" lon="7.4253" version="1"/>
  <node id="3" lat="43.7372" lon="7.4253" version="1"/><node id="4" lat="43.7372" lon="7.4251" version="1"/>
  <node id="5" lat="43.7373" lon="7.4251" version="1"/><node id="6" lat="43.7374" lon="7.4252" version="1"/>
  <way id="10" version="1"><nd ref="1"/><nd ref="2"/><nd ref="3"/><nd ref="4"/><nd ref="1"/>
    <tag k="building" v="house"/><tag k="height" v="9 m"/><tag k="building:levels" v="3"/><tag k="roof:shape" v="gabled"/></way>
  <way id="11" version="1"><nd ref="4"/><nd ref="5"/><nd ref="6"/><nd ref="4"/><tag k="landuse" v="grass"/></way>
</osm>)";
  const GeoJsonCollection read = read_footprints(osm);
  ASSERT_EQ(read.features.size(), 1u);  // the grass is no building
  const GeoJsonFeature& f = read.features[0];
  EXPECT_EQ(f.id, "w10");
  EXPECT_EQ(f.property_number("height"), 9.0);
  EXPECT_EQ(f.property_number("building:levels"), 3.0);
  EXPECT_EQ(f.property_text("roof:shape"), "gabled");
  // On WGS84 at 43.737 N, 0.0002 degree of longitude is 16.112 m and 0.0001 degree of latitude 11.111 m.
  double low = 1e300, high = -1e300, south = 1e300, north = -1e300;
  for (const glm::dvec2& p : f.loops[0])
    low = std::min(low, p.x), high = std::max(high, p.x), south = std::min(south, p.y), north = std::max(north, p.y);
  EXPECT_NEAR(high - low, 16.112, 0.002);
  EXPECT_NEAR(north - south, 11.111, 0.002);
}

}  // namespace
}  // namespace procex

// `procex batch -o city.city.json` (CityJSON 2.0, core/io/cityjson_write.h)
// loaded by cityjson-threejs-loader (npm, under Node.js:
// tools/load_cityjson_three.mjs), as a CityJSON viewer loads it: every
// building a Building with LoD 1 and LoD 2 geometry, its LoD 2 faces as roof,
// wall and ground surfaces where the batch report puts the building, its
// LoD 1 block standing on the same ground to the same height; the CRS as
// metadata.referenceSystem; soffits as OuterCeilingSurface; a CRS with no
// EPSG code refused before any work.
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The bounds of a CityObject's geometry of that LoD in the file's own
// coordinates (its integer vertices scaled and translated, in double).
std::pair<std::array<double, 3>, std::array<double, 3>> file_bounds(const json& file, const std::string& id, const std::string& lod) {
  std::array<double, 3> low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
  const json& t = file["transform"];
  std::function<void(const json&)> visit = [&](const json& j) {
    if (j.is_number_integer()) {
      const json& v = file["vertices"][j.get<std::size_t>()];
      for (int k = 0; k < 3; ++k) {
        const double x = v[k].get<double>() * t["scale"][k].get<double>() + t["translate"][k].get<double>();
        low[k] = std::min(low[k], x), high[k] = std::max(high[k], x);
      }
    } else {
      for (const json& e : j) visit(e);
    }
  };
  for (const json& g : file["CityObjects"][id]["geometry"])
    if (g["lod"] == lod) visit(g["boundaries"]);
  return {low, high};
}

class CityJsonExport : public test::CommandTest {
 protected:
  int batch(const std::string& target_crs) {
    BatchCommandOptions o;
    o.recipe = test::kRepository / "samples" / "city.pxg";
    o.footprints = test::kSampleBlock;
    o.output = dir_ / "city.city.json";
    o.report = dir_ / "report.json";
    o.progress = false;
    o.export_options.crs = test::sample_block_crs();
    o.target_crs = target_crs;
    return run_batch(o, out_, err_);
  }
  // What cityjson-threejs-loader makes of the file.
  json load() {
    const fs::path result = dir_ / "loaded.json", log = dir_ / "loaded.log";
    const int status = std::system(("node " + (test::kRepository / "tools" / "load_cityjson_three.mjs").string() + " " +
                                    (dir_ / "city.city.json").string() + " > " + result.string() + " 2> " + log.string())
                                       .c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "cityjson-threejs-loader failed (node and tools/node_modules: scripts/install-deps.sh):\n"
        << test::read_text(log);
    return json::parse(test::read_text(result));
  }
};

TEST_F(CityJsonExport, EveryBuildingLoadsWithSemanticSurfacesWhereTheReportPutsIt) {
  ASSERT_EQ(batch("EPSG:32632"), 0) << err_.str();
  const json loaded = load();
  const json report = json::parse(test::read_text(dir_ / "report.json"));
  const json file = json::parse(test::read_text(dir_ / "city.city.json"));
  EXPECT_EQ(file["version"], "2.0");
  EXPECT_EQ(loaded["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/32632");
  ASSERT_EQ(loaded["objects"].size(), 18u);
  for (const json& b : report["buildings"]) {
    const std::string id = b["id"];
    SCOPED_TRACE(id);
    ASSERT_EQ(b["status"], "ok");
    ASSERT_TRUE(loaded["objects"].contains(id));
    const json& o = loaded["objects"][id];
    EXPECT_EQ(o["type"], "Building");
    ASSERT_TRUE(o["lods"].contains("1.2") && o["lods"].contains("2.2")) << o.dump();
    const json& lod2 = o["lods"]["2.2"];
    const json& lod1 = o["lods"]["1.2"];
    for (const char* type : {"RoofSurface", "WallSurface", "GroundSurface"})
      EXPECT_GT(lod2["triangles"].value(type, 0), 0) << type << ": " << lod2["triangles"].dump();
    EXPECT_FALSE(lod2["triangles"].contains("none"));
    // Where the report puts it: the loader holds the UTM coordinates in float32 (0.5 m steps
    // at 4.8e6 m north), the file itself (below) in millimetres.
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(lod2["min"][k].get<double>(), b["bounds"]["min"][k].get<double>(), 0.5) << "axis " << k;
      EXPECT_NEAR(lod2["max"][k].get<double>(), b["bounds"]["max"][k].get<double>(), 0.5) << "axis " << k;
    }
    const auto [low, high] = file_bounds(file, id, "2.2");
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(low[k], b["bounds"]["min"][k].get<double>(), 0.5e-3 + 1e-9) << "axis " << k;
      EXPECT_NEAR(high[k], b["bounds"]["max"][k].get<double>(), 0.5e-3 + 1e-9) << "axis " << k;
    }
    // The block stands on the building's ground to its top, on the same footprint.
    const auto [block_low, block_high] = file_bounds(file, id, "1.2");
    EXPECT_EQ(block_low[2], low[2]);
    EXPECT_EQ(block_high[2], high[2]);
    for (const char* type : {"RoofSurface", "WallSurface", "GroundSurface"})
      EXPECT_GT(lod1["area"].value(type, 0.0), 1.0) << type << ": " << lod1["area"].dump();
  }
  // The features' properties are the buildings' attributes, with the party
  // and street edges batch found for city.pxg's inputs of those names. Kept
  // in a name: a range-for over a member of a temporary read freed memory (ASan).
  const json block = json::parse(test::read_text(test::kSampleBlock));
  for (const json& f : block["features"]) {
    json attributes = file["CityObjects"][f["id"].get<std::string>()]["attributes"];
    for (const char* found : {"party_edges", "street_edges"}) {
      EXPECT_TRUE(attributes[found].is_array()) << f["id"] << " " << found;
      attributes.erase(found);
    }
    EXPECT_EQ(attributes, f["properties"]) << f["id"];
  }
}

// Soffits are the OuterCeilingSurface: samples/gallery_overhang.pxg's eaves
// reach 0.5 m past its 20 x 10 m walls, so under them lies the plan's ring
// between the roof's outline (its bounds) and the ground, 21 x 11 - 200 m².
TEST_F(CityJsonExport, SoffitsAreOuterCeilingSurfaces) {
  EvalCommandOptions o;
  o.recipe = test::kRepository / "samples" / "gallery_overhang.pxg";
  o.output = dir_ / "city.city.json";
  o.export_options.crs = "EPSG:32632";
  ASSERT_EQ(run_eval(o, out_, err_), 0) << err_.str();
  const json loaded = load();
  ASSERT_EQ(loaded["objects"].size(), 1u);
  const json& lod2 = loaded["objects"].begin().value()["lods"]["2.2"];
  const double ground = lod2["area"].value("GroundSurface", 0.0);
  EXPECT_NEAR(ground, 200.0, 1e-6);
  const double plan = (lod2["max"][0].get<double>() - lod2["min"][0].get<double>()) *
                      (lod2["max"][1].get<double>() - lod2["min"][1].get<double>());
  EXPECT_NEAR(plan, 21.0 * 11.0, 1e-6);
  EXPECT_NEAR(lod2["area"].value("OuterCeilingSurface", 0.0), plan - ground, 1e-6) << lod2.dump();
  for (const char* type : {"RoofSurface", "WallSurface"}) EXPECT_GT(lod2["triangles"].value(type, 0), 0) << type;
  EXPECT_FALSE(lod2["triangles"].contains("none"));
}

TEST_F(CityJsonExport, ACrsWithNoEpsgCodeIsRefusedNamingTargetCrs) {
  // The sample block's own frame is a PROJ string with no EPSG code.
  EXPECT_EQ(batch(""), 2);
  EXPECT_NE(err_.str().find("--target-crs"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "city.city.json"));
  EXPECT_FALSE(fs::exists(dir_ / "report.json"));
}

}  // namespace
}  // namespace procex

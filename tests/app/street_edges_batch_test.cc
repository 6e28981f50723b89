// procex batch binds street_edges from data: samples/footprints/terrace.geojson's
// street lines and those of --streets (core/geom/street_edges.h has the closed
// forms), beside party_edges, for samples/city.pxg, which reads both.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/feature_binding.h"
#include "app/cli/merge_command.h"
#include "app/cli/recipe_session.h"
#include "tests/app/command_test.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
const fs::path kSamples = PROCEX_SAMPLES;
const fs::path kTerrace = kSamples / "footprints" / "terrace.geojson";

class StreetEdgesBatch : public test::CommandTest {};

TEST_F(StreetEdgesBatch, EachHouseGetsTheEdgesFacingAStreetAndThoseItShares) {
  const std::optional<Graph> city = load_recipe(kSamples / "city.pxg", {}, err_);
  ASSERT_TRUE(city) << err_.str();
  FootprintReadOptions read;
  read.streets = kSamples / "footprints" / "terrace_east_street.geojson";
  const std::optional<GeoJsonCollection> c = open_footprints(*city, kSamples / "city.pxg", kTerrace, read, "batch", err_);
  ASSERT_TRUE(c) << err_.str();
  ASSERT_EQ(c->features.size(), 3u);
  const std::vector<std::pair<std::string, std::string>> want = {{"[0,2]", "[1]"}, {"[0]", "[1,3]"}, {"[0,1]", "[3]"}};
  for (std::size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(c->features[i].id);
    EXPECT_EQ(c->features[i].properties.at("street_edges"), want[i].first);
    EXPECT_EQ(c->features[i].properties.at("party_edges"), want[i].second);
  }
}

TEST_F(StreetEdgesBatch, TheStreetsAreNotBuildings) {
  BatchCommandOptions o;
  o.recipe = kSamples / "city.pxg";
  o.footprints = kTerrace;
  o.streets = kSamples / "footprints" / "terrace_east_street.geojson";
  o.output = dir_ / "terrace.glb";
  o.report = dir_ / "terrace.json";
  o.progress = false;
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str();
  const nlohmann::json report = nlohmann::json::parse(test::read_text(o.report));
  EXPECT_EQ(report["summary"]["ok"], 3) << report["summary"].dump();
  ASSERT_EQ(report["buildings"].size(), 3u);
  // A street file the batch cannot read stops it before any building.
  o.streets = dir_ / "no_such_streets.geojson";
  EXPECT_EQ(run_batch(o, out_, err_), kExitUnusableInput);
  EXPECT_NE(err_.str().find("no_such_streets.geojson"), std::string::npos) << err_.str();
}

// The streets decide the doors: shards made with other streets are no one run.
TEST_F(StreetEdgesBatch, ShardsMadeWithOtherStreetsAreNoOneRun) {
  const fs::path streets = dir_ / "streets.geojson";
  fs::copy_file(kSamples / "footprints" / "terrace_east_street.geojson", streets);
  const auto shard = [&](std::size_t i, const std::string& name) {
    BatchCommandOptions o;
    o.recipe = kSamples / "city.pxg";
    o.footprints = kTerrace;
    o.streets = streets;
    o.output = dir_ / (name + ".glb");
    o.progress = false;
    o.shard = i, o.shards = 2;
    return run_batch(o, out_, err_);
  };
  ASSERT_EQ(shard(0, "part0"), 0) << err_.str();
  ASSERT_EQ(shard(1, "part1"), 0) << err_.str();
  MergeCommandOptions merge;
  merge.parts = {dir_ / "part0.glb", dir_ / "part1.glb"};
  merge.output = dir_ / "merged.glb";
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  std::ofstream(streets, std::ios::app) << "\n";
  ASSERT_EQ(shard(1, "edited1"), 0) << err_.str();
  merge.parts = {dir_ / "part0.glb", dir_ / "edited1.glb"};
  merge.output = dir_ / "mixed.glb";
  EXPECT_EQ(run_merge(merge, out_, err_), 2);
  EXPECT_NE(err_.str().find("another recipe, footprint file or streets file"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(merge.output));
}

}  // namespace
}  // namespace procex

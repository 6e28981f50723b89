// FeatureSpool: footprints set aside on disk come back as they went in, by
// position, with the properties added since; a projection's pass drops and
// changes them in order; a repeated "features" member starts over.
#include "core/io/feature_spool.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/io_error.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const std::string kFootprints = std::string(PROCEX_DATA) + "/footprints/";

void expect_same(const GeoJsonFeature& got, const GeoJsonFeature& want) {
  EXPECT_EQ(got.index, want.index);
  EXPECT_EQ(got.id, want.id);
  EXPECT_EQ(got.loops, want.loops);
  EXPECT_EQ(got.polygon_of_loop, want.polygon_of_loop);
  EXPECT_EQ(got.properties, want.properties);
  EXPECT_EQ(got.edge_angles, want.edge_angles);
}

GeoJsonFeature odd_feature() {
  GeoJsonFeature f;
  f.index = 7;
  f.id = std::string("a \"quoted\"\0id", 13);  // any bytes, a NUL too
  f.loops = {{{0, 0}, {10, 0}, {10, 10}}, {}, {{1e300, -0.0}, {5e-324, 3}}};
  f.polygon_of_loop = {0, 0, 1};
  f.properties = {{"height", "12.5"}, {"name", "\"caf\\u00e9\""}, {"empty", ""}};
  f.edge_angles = {{30, 45, 60}, {}, {90, 0.1}};
  return f;
}

TEST(FeatureSpool, GivesBackEachFootprintAsItWent) {
  FeatureSpool spool(fs::temp_directory_path().string());
  const GeoJsonCollection c = read_geojson_file(kFootprints + "corpus_monaco.geojson");
  ASSERT_GT(c.features.size(), 500u);
  for (const GeoJsonFeature& f : c.features) spool.add(f);
  spool.add(odd_feature());
  ASSERT_EQ(spool.size(), c.features.size() + 1);
  for (std::size_t i = c.features.size(); i-- > 0;) {  // in any order
    SCOPED_TRACE(c.features[i].id);
    EXPECT_EQ(spool.index(i), c.features[i].index);
    expect_same(spool.at(i), c.features[i]);
  }
  expect_same(spool.at(c.features.size()), odd_feature());
}

TEST(FeatureSpool, AddedPropertiesNeverReplaceTheFootprintsOwn) {
  FeatureSpool spool(fs::temp_directory_path().string());
  spool.add(odd_feature());
  spool.add_properties(0, {{"party_edges", "[1,2]"}, {"height", "99"}});
  spool.add_properties(0, {{"street_edges", "[]"}, {"party_edges", "[5]"}});
  const GeoJsonFeature f = spool.at(0);
  EXPECT_EQ(f.properties.at("height"), "12.5");
  EXPECT_EQ(f.properties.at("party_edges"), "[1,2]");
  EXPECT_EQ(f.properties.at("street_edges"), "[]");
  EXPECT_EQ(f.properties.size(), 5u);
}

TEST(FeatureSpool, KeepIfChangesAndDropsInOrder) {
  FeatureSpool spool(fs::temp_directory_path().string());
  for (std::size_t i = 0; i < 5; ++i) {
    GeoJsonFeature f = odd_feature();
    f.index = i, f.id = "f" + std::to_string(i);
    spool.add(f);
    spool.add_properties(i, {{"party_edges", "[" + std::to_string(i) + "]"}});
  }
  spool.keep_if([](GeoJsonFeature& f) {
    f.loops[0][0].x += 1;
    return f.index % 2 == 0;
  });
  ASSERT_EQ(spool.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const GeoJsonFeature f = spool.at(i);
    EXPECT_EQ(f.index, 2 * i);
    EXPECT_EQ(spool.index(i), 2 * i);
    EXPECT_EQ(f.id, "f" + std::to_string(2 * i));
    EXPECT_EQ(f.loops[0][0].x, 1.0);
    EXPECT_EQ(f.properties.at("party_edges"), "[" + std::to_string(2 * i) + "]");
  }
  spool.clear();
  EXPECT_EQ(spool.size(), 0u);
  EXPECT_THROW(spool.at(0), std::out_of_range);
}

// A repeated "features" member: the last counts, in the spool as in memory.
TEST(FeatureSpool, ARepeatedFeaturesMemberStartsOver) {
  const fs::path file = fs::temp_directory_path() / ("procex_spool_repeat_" + std::to_string(::getpid()) + ".geojson");
  {
    std::ofstream(file) << R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "id": "gone", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1]]]}}],
      "features": [
      {"type": "Feature", "id": "kept", "properties": {"a": 1}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[2,0],[2,2]]]}}]})";
  }
  FeatureSpool spool(fs::temp_directory_path().string());
  const GeoJsonCollection c = read_geojson_file(file, {}, spool);
  fs::remove(file);
  EXPECT_TRUE(c.features.empty());
  ASSERT_EQ(spool.size(), 1u);
  EXPECT_EQ(spool.at(0).id, "kept");
  EXPECT_EQ(spool.at(0).index, 0u);
}

TEST(FeatureSpool, AFolderItCannotWriteInIsNamed) {
  try {
    FeatureSpool spool("/no/such/folder");
    FAIL() << "made a spool in a missing folder";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/folder"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace procex

#include "core/io/geojson.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/io/io_error.h"

namespace procex {
namespace {

const std::string kData = PROCEX_TEST_DATA;
const std::string kFootprints = std::string(PROCEX_DATA) + "/footprints/";

class GeoJsonCorpus : public ::testing::TestWithParam<const char*> {};

// Every feature of the real corpus reads, and the totals match the "stats"
// member that the converter wrote into each file.
TEST_P(GeoJsonCorpus, CountsMatchTheFilesStats) {
  const GeoJsonCollection c = read_geojson_file(kFootprints + GetParam());
  ASSERT_TRUE(c.members.count("stats"));
  const nlohmann::json stats = nlohmann::json::parse(c.members.at("stats"));
  EXPECT_TRUE(c.errors.empty()) << c.errors.front().message;
  EXPECT_EQ(c.features.size(), stats["features"].get<std::size_t>());
  std::size_t polygons = 0, rings = 0, vertices = 0;
  for (const GeoJsonFeature& f : c.features) {
    polygons += f.polygon_of_loop.empty() ? 0 : f.polygon_of_loop.back() + 1;
    rings += f.loops.size();
    for (const auto& loop : f.loops) vertices += loop.size();
    // The per-feature statistics count vertices without the closing repeat, as we do.
    std::size_t mine = 0;
    for (const auto& loop : f.loops) mine += loop.size();
    ASSERT_EQ(f.property_number("n_vertices"), static_cast<double>(mine)) << f.id;
  }
  EXPECT_EQ(polygons, stats["polygons"].get<std::size_t>());
  EXPECT_EQ(rings, stats["rings"].get<std::size_t>());
  EXPECT_EQ(rings - polygons, stats["holes"].get<std::size_t>());
  EXPECT_EQ(vertices, stats["vertices"].get<std::size_t>());
}

INSTANTIATE_TEST_SUITE_P(Files, GeoJsonCorpus,
                         ::testing::Values("corpus_monaco.geojson", "corpus_manhattan_2015.geojson",
                                           "corpus_baltimore_2015.geojson"));

TEST(GeoJson, ReadsIdsPropertiesAndDropsTheClosingVertex) {
  const GeoJsonCollection c = read_geojson_file(kFootprints + "corpus_baltimore_2015.geojson");
  const GeoJsonFeature& f = c.features.front();
  EXPECT_EQ(f.index, 0u);
  EXPECT_EQ(f.id, "w49666537");
  EXPECT_EQ(f.property_text("building"), "yes");
  EXPECT_EQ(f.property_text("valid"), "true");
  EXPECT_EQ(f.properties.at("region"), "\"baltimore_2015\"");
  ASSERT_EQ(f.loops.size(), 1u);
  EXPECT_EQ(f.loops[0].size(), 7u);
  EXPECT_NE(f.loops[0].front(), f.loops[0].back());
  EXPECT_FALSE(f.property_text("no such property"));
}

TEST(GeoJson, BadFeaturesAreReportedAndTheOthersRead) {
  const GeoJsonCollection c = read_geojson_file(kData + "/geojson_bad_features.geojson");
  ASSERT_EQ(c.features.size(), 2u);
  EXPECT_EQ(c.features[0].id, "good_square");
  EXPECT_EQ(c.features[0].property_number("height"), 12.0);
  EXPECT_EQ(c.features[0].property_text("name"), "Sq/uare");
  // The MultiPolygon: its id is its index, its loops in ring order.
  const GeoJsonFeature& multi = c.features[1];
  EXPECT_EQ(multi.id, "6");
  ASSERT_EQ(multi.loops.size(), 3u);
  EXPECT_EQ(multi.polygon_of_loop, (std::vector<std::size_t>{0, 0, 1}));
  EXPECT_EQ(multi.loops[2].size(), 3u);
  EXPECT_EQ(c.members.at("name"), "\"one good feature among bad ones\"");

  ASSERT_EQ(c.errors.size(), 5u);
  EXPECT_EQ(c.errors[0].id, "string_coordinate");
  EXPECT_EQ(c.errors[0].pointer, "/features/1/geometry/coordinates/0/2/1");
  EXPECT_EQ(c.errors[1].pointer, "/features/2/geometry/type");
  EXPECT_NE(c.errors[1].message.find("Point"), std::string::npos);
  EXPECT_EQ(c.errors[2].id, "null_geometry");
  EXPECT_EQ(c.errors[2].pointer, "/features/3/geometry");
  EXPECT_EQ(c.errors[3].id, "42");
  EXPECT_EQ(c.errors[3].pointer, "/features/4/geometry/coordinates/0/2");
  EXPECT_EQ(c.errors[4].index, 5u);
  EXPECT_EQ(c.errors[4].pointer, "/features/5");
  for (const auto& e : c.errors) EXPECT_NE(e.message.find(e.pointer), std::string::npos) << e.message;
}

TEST(GeoJson, ReadsPerEdgeAnglesInRingOrder) {
  GeoJsonReadOptions options;
  options.angles_property = "angles";
  const GeoJsonCollection c = read_geojson_file(kData + "/geojson_edge_angles.geojson", options);
  ASSERT_EQ(c.features.size(), 1u);
  const GeoJsonFeature& f = c.features[0];
  ASSERT_EQ(f.edge_angles.size(), 2u);
  EXPECT_EQ(f.edge_angles[1], (std::vector<double>{0, 10, 20, 90}));
  const Footprint fp = to_footprint(f, 45.0);
  EXPECT_EQ(fp.loops[1].edges[3].angle_deg, 90.0);
  EXPECT_EQ(fp.loops[1].edges[3].id, 7);

  ASSERT_EQ(c.errors.size(), 3u);
  EXPECT_EQ(c.errors[0].pointer, "/features/1/properties/angles/0");
  EXPECT_EQ(c.errors[1].pointer, "/features/2/properties/angles/0/2");
  EXPECT_EQ(c.errors[2].pointer, "/features/3/properties/angles");

  // Optional angles: the feature without them reads, at the default angle.
  options.require_angles = false;
  const GeoJsonCollection lenient = read_geojson_file(kData + "/geojson_edge_angles.geojson", options);
  ASSERT_EQ(lenient.features.size(), 2u);
  EXPECT_TRUE(lenient.features[1].edge_angles.empty());
  EXPECT_EQ(to_footprint(lenient.features[1], 30.0).loops[0].edges[2].angle_deg, 30.0);
}

TEST(GeoJson, SyntaxErrorNamesFileLineAndColumn) {
  try {
    read_geojson_file(kData + "/geojson_syntax_error.geojson");
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("geojson_syntax_error.geojson:3:"), std::string::npos) << e.what();
  }
}

// Features are read as the parser finishes each (and dropped from the
// document): members before and after them are kept whole, arrays among them
// (a bbox) too, and a repeated "features" member counts once, the last, as a
// parsed document would have it.
TEST(GeoJson, FeaturesReadOneAtATimeAmongOtherMembers) {
  const GeoJsonCollection c = parse_geojson(R"({"bbox": [0, 0, 9, 9], "features": [
      {"type": "Feature", "id": "first", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1]]]}}],
    "type": "FeatureCollection", "features": [7,
      {"type": "Feature", "properties": {"features": [1]}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[2,0],[2,2],[0,0]]]}}],
    "name": {"features": [[1, 2]]}})");
  ASSERT_EQ(c.features.size(), 1u);
  EXPECT_EQ(c.features[0].index, 1u);
  EXPECT_EQ(c.features[0].id, "1");
  EXPECT_EQ(c.features[0].loops, (std::vector<std::vector<glm::dvec2>>{{{0, 0}, {2, 0}, {2, 2}}}));
  EXPECT_EQ(c.features[0].properties.at("features"), "[1]");
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].pointer, "/features/0");
  EXPECT_EQ(c.members.at("bbox"), "[0,0,9,9]");
  EXPECT_EQ(c.members.at("name"), R"({"features":[[1,2]]})");
  EXPECT_EQ(c.members.size(), 2u);
}

// A file of several megabytes (read a chunk at a time) reads as its text does.
TEST(GeoJson, AFileReadsAsItsText) {
  std::string text = R"({"type": "FeatureCollection", "name": "grid", "features": [)";
  for (int i = 0; i < 20000; ++i) {
    const std::string x = std::to_string(i * 10) + ".125", x1 = std::to_string(i * 10 + 8) + ".5";
    text += (i ? ",\n" : "") + std::string(R"({"type": "Feature", "id": "f)") + std::to_string(i) +
            R"(", "properties": {"height": )" + std::to_string(i % 40) + R"(}, "geometry": {"type": "Polygon", "coordinates": [[[)" +
            x + ",0],[" + x1 + ",0],[" + x1 + ",7.25],[" + x + ",7.25]]]}}";
  }
  text += "]}";
  ASSERT_GT(text.size(), 3u << 20);
  const auto file = std::filesystem::temp_directory_path() / ("procex_geojson_file_" + std::to_string(::getpid()) + ".geojson");
  std::ofstream(file, std::ios::binary) << text;
  const GeoJsonCollection from_file = read_geojson_file(file), from_text = parse_geojson(text, {}, file.string());
  std::filesystem::remove(file);
  ASSERT_EQ(from_file.features.size(), 20000u);
  EXPECT_EQ(from_file.members, from_text.members);
  for (std::size_t i = 0; i < from_file.features.size(); ++i) {
    ASSERT_EQ(from_file.features[i].id, from_text.features[i].id);
    ASSERT_EQ(from_file.features[i].loops, from_text.features[i].loops) << i;
    ASSERT_EQ(from_file.features[i].properties, from_text.features[i].properties) << i;
  }
  EXPECT_EQ(from_file.features.back().loops[0][2], glm::dvec2(199998.5, 7.25));
}

TEST(GeoJson, RefusesWhatIsNotAFeatureCollection) {
  EXPECT_THROW(parse_geojson(R"({"type": "Feature"})"), IoError);
  EXPECT_THROW(parse_geojson(R"({"type": "FeatureCollection", "features": 3})"), IoError);
  EXPECT_THROW(parse_geojson("[1, 2]"), IoError);
  EXPECT_THROW(read_geojson_file(kData + "/no_such_file.geojson"), IoError);
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

// Property values are numbers only when the whole value is one, with at
// most a unit of length: never the front of a longer string.
TEST(GeoJson, PropertyNumbersAreStrict) {
  const GeoJsonCollection c = parse_geojson(R"({"type": "FeatureCollection", "features": [{"type": "Feature",
      "properties": {"a": 12.5, "b": "12", "c": "12 m", "d": "40 ft", "e": "40'", "f": "3,5", "g": "0x3",
                     "h": "3 storeys", "i": "", "j": "1e999", "k": " 7 m", "l": true},
      "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,1]]]}}]})");
  const GeoJsonFeature& f = c.features.at(0);
  EXPECT_EQ(f.property_number("a"), 12.5);
  EXPECT_EQ(f.property_number("b"), 12.0);
  EXPECT_EQ(f.property_number("c"), 12.0);
  EXPECT_NEAR(*f.property_number("d"), 12.192, 1e-12);
  EXPECT_NEAR(*f.property_number("e"), 12.192, 1e-12);
  EXPECT_EQ(f.property_number("k"), 7.0);
  for (const char* bad : {"f", "g", "h", "i", "j", "l", "missing"}) EXPECT_EQ(f.property_number(bad), std::nullopt) << bad;
}

}  // namespace
}  // namespace procex

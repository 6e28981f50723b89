// The JSON readers of core/io (GeoJSON footprints, .json shapes, reports) on
// files made to break them: numbers beyond double range, nesting deep enough
// to overflow a stack, a folder where a file should be. Each is an IoError
// naming the file, never an uncaught exception or a crash.

#include <filesystem>
#include <fstream>
#include <utility>
#include <string>

#include <gtest/gtest.h>

#include "core/io/geojson.h"
#include "core/io/io_error.h"
#include "core/io/json_read.h"
#include "core/io/polyjson.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

const std::string kSquare = R"("geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,1]]]})";

template <class Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const IoError& e) {
    return e.what();
  }
  return "no IoError";
}

// The message points at the number: line and column of its first character.
TEST(HostileJson, NumbersBeyondDoubleRangeAreRefused) {
  const std::string in_property = R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties":
  {"height": 1e400}, )" + kSquare + "}]}";
  const std::string why = error_of([&] { parse_geojson(in_property, {}, "big.geojson"); });
  EXPECT_NE(why.find("big.geojson:2:14: a number beyond double range"), std::string::npos) << why;
  EXPECT_NE(why.find("'1e400'"), std::string::npos) << why;
  const std::string in_string = R"({"1e400": "1e400", "loops": [[[0,0],[-1e999,0],[1,1]]]})";
  EXPECT_NE(error_of([&] { parse_polyjson(in_string, "big.json"); }).find("big.json:1:38: a number beyond double range"),
            std::string::npos)
      << error_of([&] { parse_polyjson(in_string, "big.json"); });
}

TEST(HostileJson, DeepNestingIsRefusedBeforeParsing) {
  const std::string deep = std::string(80000, '[') + std::string(80000, ']');
  const std::string in_property =
      R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"x": )" + deep + "}, " + kSquare + "}]}";
  const std::string why = error_of([&] { parse_geojson(in_property, {}, "deep.geojson"); });
  EXPECT_NE(why.find("deep.geojson:1:"), std::string::npos) << why;
  EXPECT_NE(why.find("nesting deeper than 64 levels"), std::string::npos) << why;
  const std::string member = R"({"type": "FeatureCollection", "name": )" + deep + R"(, "features": []})";
  EXPECT_NE(error_of([&] { parse_geojson(member, {}, "deep.geojson"); }).find("nesting deeper"), std::string::npos);
  EXPECT_NE(error_of([&] { parse_polyjson(deep, "deep.json"); }).find("nesting deeper"), std::string::npos);
  // A real MultiPolygon with holes is far from the limit.
  const std::string multi = R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"a": {"b": [1]}},
      "geometry": {"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[1,1],[0,1]]]]}}]})";
  EXPECT_EQ(parse_geojson(multi).features.size(), 1u);
}

// A footprint file is read a chunk at a time (read_geojson_file): the same
// refusals, naming the file, line and column, as for its text.
TEST(HostileJson, FilesReadAsTheyGoAreRefusedAlike) {
  const test::ScratchDir dir("hostile_stream");
  const std::string deep = std::string(80000, '[') + std::string(80000, ']');
  const std::string head = R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties":
  )";
  const std::pair<std::string, std::string> cases[] = {
      {head + R"({"height": 1e400}, )" + kSquare + "}]}", ":2:14: a number beyond double range"},
      {head + R"({"x": )" + deep + "}, " + kSquare + "}]}", ":2:69: nesting deeper than 64 levels"},
      {head + R"({}, )" + kSquare + "}]} x", ": not valid JSON"},  // more after the end
      {head + R"({}, )" + kSquare, ": not valid JSON"},            // cut short
  };
  for (const auto& [text, why] : cases) {
    const auto file = dir / "hostile.geojson";
    std::ofstream(file, std::ios::binary) << text;
    const std::string got = error_of([&] { read_geojson_file(file); });
    EXPECT_EQ(got, error_of([&] { parse_geojson(text, {}, file.string()); }));
    EXPECT_NE(got.find(why), std::string::npos) << got;
  }
}

TEST(HostileJson, AFolderIsNotAFile) {
  const test::ScratchDir dir("hostile_json");
  std::filesystem::create_directories(dir / "dir.geojson");
  EXPECT_NE(error_of([&] { read_geojson_file(dir / "dir.geojson"); }).find("it is a folder, not a file"), std::string::npos);
  EXPECT_NE(error_of([&] { read_polyjson_file(dir / "dir.geojson"); }).find("it is a folder"), std::string::npos);
  EXPECT_NE(error_of([&] { read_json_file(dir / "dir.geojson"); }).find("it is a folder"), std::string::npos);
}

}  // namespace
}  // namespace procex

#include "core/io/polyjson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "core/geom/error.h"
#include "core/io/io_error.h"

namespace procex {
namespace {

const std::string kData = PROCEX_TEST_DATA;
const std::string kSynthetic = std::string(PROCEX_DATA) + "/synthetic/";

// Every synthetic case reads, with the shape, loop and vertex counts of the manifest.
TEST(PolyJson, ReadsEverySyntheticCase) {
  std::ifstream in(kSynthetic + "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  ASSERT_GE(manifest.size(), 30u);
  for (const auto& entry : manifest) {
    const std::string file = entry["file"].get<std::string>();
    const std::vector<PolyShape> shapes = read_polyjson_file(kSynthetic + file);
    std::size_t loops = 0, vertices = 0;
    for (const PolyShape& s : shapes) {
      loops += s.loops.size();
      for (const auto& loop : s.loops) vertices += loop.size();
      EXPECT_TRUE(s.weights.empty()) << file;
    }
    EXPECT_EQ(shapes.size(), entry["shapes"].get<std::size_t>()) << file;
    EXPECT_EQ(loops, entry["loops"].get<std::size_t>()) << file;
    EXPECT_EQ(vertices, entry["vertices"].get<std::size_t>()) << file;
  }
}

TEST(PolyJson, WeightsBecomeAnglesFromTheVertical) {
  EXPECT_DOUBLE_EQ(weight_to_angle_deg(1.0), 45.0);
  EXPECT_NEAR(weight_to_angle_deg(2.0), 90.0 - std::atan(2.0) * 180.0 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(weight_to_angle_deg(0.5), 63.43494882292201, 1e-12);
  EXPECT_THROW(weight_to_angle_deg(0.0), InputError);
  EXPECT_THROW(weight_to_angle_deg(-1.0), InputError);
  EXPECT_THROW(weight_to_angle_deg(NAN), InputError);

  const std::vector<PolyShape> shapes = read_polyjson_file(kData + "/polyjson_weighted_rectangle.json");
  ASSERT_EQ(shapes.size(), 1u);
  const Footprint fp = to_footprint(shapes[0]);
  ASSERT_EQ(fp.loops.size(), 1u);
  EXPECT_NEAR(fp.loops[0].edges[0].angle_deg, 26.56505117707799, 1e-12);
  EXPECT_DOUBLE_EQ(fp.loops[0].edges[1].angle_deg, 45.0);
  EXPECT_EQ(fp.loops[0].edges[3].id, 3);
}

TEST(PolyJson, ReferenceCycleWeights) {
  const std::vector<PolyShape> shapes = read_polyjson_file(kSynthetic + "c_courtyard_0008.json");
  const auto w = reference_cycle_weights(shapes[0]);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], (std::vector<double>{1.0, 0.5, 2.0, 1.0}));
  EXPECT_EQ(w[1], (std::vector<double>{1.0, 0.5, 2.0, 1.0}));
  const Footprint fp = to_footprint(shapes[0], w);
  EXPECT_DOUBLE_EQ(fp.loops[1].edges[0].angle_deg, 45.0);
  EXPECT_EQ(fp.loops[1].edges[0].id, 4);
  // Without weights: one angle everywhere.
  EXPECT_DOUBLE_EQ(to_footprint(shapes[0], 30.0).loops[1].edges[2].angle_deg, 30.0);
}

TEST(PolyJson, ErrorsNameTheJsonPointer) {
  try {
    read_polyjson_file(kData + "/polyjson_weights_count_mismatch.json");
    FAIL();
  } catch (const IoError& e) {
    EXPECT_EQ(e.pointer(), "/weights/0");
  }
  try {
    read_polyjson_file(kData + "/polyjson_bad_coordinate.json");
    FAIL();
  } catch (const IoError& e) {
    EXPECT_EQ(e.pointer(), "/polygons/1/loops/0/2/1");
    EXPECT_NE(std::string(e.what()).find("polyjson_bad_coordinate.json"), std::string::npos);
  }
  EXPECT_THROW(parse_polyjson(R"({"loops": [[[0, 0], [1, 0], [1, 1]]], "weights": [[1, -2, 1]]})"), IoError);
  EXPECT_THROW(parse_polyjson(R"({"polygons": {}})"), IoError);
  EXPECT_THROW(parse_polyjson("{\"loops\": "), IoError);
}

}  // namespace
}  // namespace procex

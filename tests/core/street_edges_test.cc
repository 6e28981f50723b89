// Street edges from data (core/geom/street_edges.h), read as the batch reads
// them: samples/footprints/terrace.geojson holds three 10 x 12 m terraced houses
// a, b, c in a row (edges 0 south, 1 east, 2 north, 3 west) and street lines;
// terrace_east_street.geojson is a second file of streets.
//
//                 lane (y = 15, x -2..12): 3 m behind a's north edge
//   +------+------+------+
//   |  a   |  b   |  c   |     east street (x = 42): 12 m from c's east edge,
//   |      | ---- |      |     22 m from b's (across c)
//   +------+------+------+     passage (y = 3) inside b: behind its edges
//   south street (y = -8 .. -8.5): 8 m in front of every south edge
//   far street (x = -25): 25 m from a's west edge, beyond 20 m
#include <gtest/gtest.h>

#include "core/geom/street_edges.h"
#include "core/io/footprint_read.h"
#include "core/io/io_error.h"

namespace procex {
namespace {

const std::filesystem::path kFootprints = std::filesystem::path(PROCEX_SAMPLES) / "footprints";
using Ids = std::vector<std::vector<std::int32_t>>;

Ids streets_of(const GeoJsonCollection& c, double distance = 20.0) {
  std::vector<PlanLoops> plans;
  for (const GeoJsonFeature& f : c.features) plans.push_back(f.loops);
  return street_edges(plans, c.lines, distance);
}

TEST(StreetEdges, LineStringsInTheFootprintFileAreStreets) {
  const GeoJsonCollection c = read_footprints(kFootprints / "terrace.geojson");
  ASSERT_EQ(c.features.size(), 3u);  // the lines are not footprints
  EXPECT_TRUE(c.errors.empty());
  ASSERT_EQ(c.lines.size(), 3u);
  EXPECT_EQ(c.lines[0].size(), 3u);  // the south street bends
  EXPECT_EQ(streets_of(c), (Ids{{0, 2}, {0}, {0}}));
  // Within 3 m only the lane counts; within 8 m not the south street, 8 to 8.29 m off along a.
  EXPECT_EQ(streets_of(c, 3.0), (Ids{{2}, {}, {}}));
  EXPECT_EQ(streets_of(c, 8.0), (Ids{{2}, {}, {}}));
}

TEST(StreetEdges, ASecondFileAddsItsStreets) {
  FootprintReadOptions read;
  read.streets = kFootprints / "terrace_east_street.geojson";
  const GeoJsonCollection c = read_footprints(kFootprints / "terrace.geojson", read);
  ASSERT_EQ(c.features.size(), 3u);
  ASSERT_EQ(c.lines.size(), 5u);
  EXPECT_EQ(streets_of(c), (Ids{{0, 2}, {0}, {0, 1}}));
  // The far street 25 m off a, the east street 22 m off b (a street edge
  // says how near a street is, not what stands between).
  EXPECT_EQ(streets_of(c, 25.5), (Ids{{0, 2, 3}, {0, 1}, {0, 1}}));
}

TEST(StreetEdges, AStreetTooShortOrMissingIsSaidSo) {
  const GeoJsonCollection c = parse_geojson(
      R"({"type": "FeatureCollection", "features": [
           {"type": "Feature", "id": "stub", "geometry": {"type": "LineString", "coordinates": [[0, 0]]}}]})",
      {}, "stub.geojson");
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].message,
            "stub.geojson: feature stub at /features/0/geometry/coordinates: a LineString needs at least two positions");
  FootprintReadOptions read;
  read.streets = kFootprints / "missing.geojson";
  EXPECT_THROW(read_footprints(kFootprints / "terrace.geojson", read), IoError);
}

}  // namespace
}  // namespace procex

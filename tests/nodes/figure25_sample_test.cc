// samples/footprints/figure25.geojson was written once from
// tests/support/figure25.h: it must stay the same 24 loops (each ring from the
// same first vertex, in the same direction, to the micrometre), so that
// samples/gallery_figure25.pxg shows the footprint the gallery test and the
// profile benchmark sweep.
#include <cmath>
#include <cstddef>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/io/geojson.h"
#include "tests/support/figure25.h"

namespace procex {
namespace {

const std::filesystem::path kSamples = PROCEX_SAMPLES;

bool same_ring(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i].x - b[i].x) > 1e-6 || std::abs(a[i].y - b[i].y) > 1e-6) return false;
  return true;
}

TEST(Figure25Sample, FootprintFileHoldsTheGalleryTestsLoops) {
  const GeoJsonCollection c = read_geojson_file(kSamples / "footprints" / "figure25.geojson");
  ASSERT_TRUE(c.errors.empty());
  ASSERT_EQ(c.features.size(), 1u);
  EXPECT_EQ(c.features[0].id, "figure25");
  const auto& loops = c.features[0].loops;
  const Footprint want = testing::figure25_analogue();
  ASSERT_EQ(loops.size(), want.loops.size());
  std::size_t vertices = 0;
  for (const Loop& w : want.loops) {
    vertices += w.points.size();
    std::size_t matches = 0;
    for (const auto& got : loops) matches += same_ring(got, w.points) ? 1 : 0;
    EXPECT_EQ(matches, 1u) << "a loop starting at " << w.points[0].x << ", " << w.points[0].y;
  }
  EXPECT_EQ(vertices, 552u);
}

}  // namespace
}  // namespace procex

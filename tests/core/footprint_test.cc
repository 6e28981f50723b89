#include "core/geom/footprint.h"

#include <gtest/gtest.h>

namespace procex {
namespace {

TEST(Footprint, MakeFootprintNumbersEdgesAcrossLoops) {
  const Footprint fp = make_footprint({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 2}, {2, 2}}}, 30.0);
  ASSERT_EQ(fp.loops.size(), 2u);
  EXPECT_EQ(fp.loops[1].edges.size(), 3u);
  EXPECT_EQ(fp.loops[1].edges[2].id, 6);
  EXPECT_DOUBLE_EQ(fp.loops[0].edges[0].angle_deg, 30.0);
}

}  // namespace
}  // namespace procex

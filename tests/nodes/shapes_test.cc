#include "nodes/support/shapes.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geom/nesting.h"
#include "core/geom/prepare.h"

namespace procex {
namespace {

double area(const std::vector<std::vector<glm::dvec2>>& loops) {
  double a = 0;
  for (const auto& l : loops) a += 0.5 * twice_signed_area(l);
  return a;
}

TEST(Shapes, AreasAndOrientation) {
  const ShapeSize s{12, 10, 4, 8};
  EXPECT_DOUBLE_EQ(area(make_shape("rectangle", s)), 120);
  EXPECT_DOUBLE_EQ(area(make_shape("l", s)), 12 * 4 + 4 * 6);
  EXPECT_DOUBLE_EQ(area(make_shape("t", s)), 12 * 4 + 4 * 6);
  EXPECT_DOUBLE_EQ(area(make_shape("u", s)), 12 * 4 + 2 * 4 * 6);
  EXPECT_DOUBLE_EQ(area(make_shape("courtyard", s)), 120 - 4 * 2);
  EXPECT_NEAR(area(make_shape("ngon", s)), 0.5 * 8 * 36 * std::sin(2 * M_PI / 8), 1e-9);
  for (const char* shape : {"rectangle", "l", "t", "u", "courtyard", "ngon"}) {
    SCOPED_TRACE(shape);
    // Already oriented and clean: prepare has nothing to repair.
    EXPECT_EQ(prepare_footprint(make_footprint(make_shape(shape, s), 45)).notes, std::vector<std::string>{});
  }
}

TEST(Shapes, ImpossibleSizesNameTheParameter) {
  try {
    make_shape("u", {10, 10, 5, 3});
    FAIL() << "a U with arms half as wide as the plan has no gap";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("arm"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make_shape("ngon", {10, 10, 1, 2}), std::invalid_argument);
  EXPECT_THROW(make_shape("star", {}), std::invalid_argument);
}

}  // namespace
}  // namespace procex

// Splitting affine maps into glTF-legal nodes: outer is T * R * S, inner a
// rotation, and together they give back the map.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "core/placement/trs_split.h"

namespace procex {
namespace {

double max_difference(const glm::dmat4& a, const glm::dmat4& b) {
  double d = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
  return d;
}

glm::dmat4 affine(const glm::dvec3& x, const glm::dvec3& y, const glm::dvec3& z, const glm::dvec3& t) {
  return glm::dmat4(glm::dvec4(x, 0), glm::dvec4(y, 0), glm::dvec4(z, 0), glm::dvec4(t, 1));
}

TEST(TrsSplit, RotationScaleAndMirrorNeedNoSplit) {
  EXPECT_TRUE(is_trs(glm::dmat4(1.0)));
  EXPECT_TRUE(is_trs(affine({0, 2, 0}, {-3, 0, 0}, {0, 0, -1}, {4, 5, 6})));
  EXPECT_FALSE(is_trs(affine({1, 0, 0}, {0.2, 1, 0}, {0, 0, 1}, {0, 0, 0})));
}

// A .glb holds matrices in float32 (core/io/gltf_write.cc): a rotation and
// scale rounded so still needs no split, though its columns are no longer
// orthogonal to double precision.
TEST(TrsSplit, RotationsRoundedToFloatNeedNoSplit) {
  for (int k = 1; k <= 50; ++k) {
    const glm::dmat4 m = glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(40.0 * k, -3.0, 7.5)), 0.37 * k,
                                                glm::dvec3(1.0, 2.0 * k, -3.0)),
                                    glm::dvec3(1.5 * k, -0.7, 2.0 + k));
    EXPECT_TRUE(is_trs(glm::dmat4(glm::mat4(m)))) << k;
  }
}

TEST(TrsSplit, ShearsSplitIntoTwoLegalNodes) {
  const glm::dmat4 cases[] = {
      affine({1, 0, 0}, {0.2, 1.6667, 0}, {0, 0, 1}, {2, 0, 0}),            // a leaning stretched pillar
      affine({1, 0.5, 0}, {0, 1, 4}, {-0.5, 0.3, 0.1}, {1, 2, 3}),          // a general map
      affine({-1, 0.5, 0}, {0, 1, 4}, {-0.5, 0.3, 0.1}, {0, 0, 0}),         // with a mirror
      affine({1e3, 0, 0}, {1, 1e-2, 0}, {0, 0, 1}, {1e5, -1e5, 7}),         // very uneven scales
  };
  for (const glm::dmat4& m : cases) {
    const TrsSplit s = split_trs(m);
    EXPECT_TRUE(is_trs(s.outer));
    EXPECT_TRUE(is_trs(s.inner));
    EXPECT_NEAR(glm::determinant(glm::dmat3(s.inner)), 1.0, 1e-12);
    EXPECT_EQ(glm::dvec3(s.inner[3]), glm::dvec3(0.0));
    EXPECT_LT(max_difference(s.outer * s.inner, m), 1e-9 * std::max(1.0, std::abs(m[3][0]) + std::abs(m[0][0])))
        << "determinant " << glm::determinant(glm::dmat3(m));
    EXPECT_GT(glm::determinant(glm::dmat3(s.outer)) * glm::determinant(glm::dmat3(m)), 0.0);
  }
}

}  // namespace
}  // namespace procex

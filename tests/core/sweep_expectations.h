// Expectations shared by the sweep tests that build meshes: a surface is
// closed, oriented and planar by the engine's own terms and a valid 2-manifold
// by the full validator; faces counted per tag.
#pragma once

#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "core/mesh/surface.h"
#include "core/mesh/validate.h"
#include "tests/core/surface_checks.h"

namespace procex::testing {

inline std::map<std::string, int> faces_per_tag(const Surface& s) {
  std::map<std::string, int> n;
  for (const SurfaceFace& f : s.faces)
    if (f.kind == FaceKind::Side) ++n[f.tag];
  return n;
}

// Closed, oriented and planar by the engine's own terms, then as an OpenMesh
// mesh by the full validator (manifold, no self-intersections).
inline SurfaceCheck expect_valid(const Surface& s) {
  const SurfaceCheck c = check_surface(s, 1e-6);
  EXPECT_TRUE(c.closed) << c.problem;
  EXPECT_TRUE(c.planar) << c.problem;
  const ValidationReport v = validate(build_mesh(s), {});
  EXPECT_TRUE(v.ok()) << (v.problems.empty() ? std::string() : v.problems.front());
  return c;
}

}  // namespace procex::testing

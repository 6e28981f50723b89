// Hand-made closed surfaces and plans for the mesh tests: vertical prisms over planar
// footprints (loops at even nesting depth CCW, odd depth CW), so every
// expected property (closed, oriented, volume) is known in closed form.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/geom/nesting.h"
#include "core/mesh/surface.h"

namespace procex::test {

// A prism from z0 to z1. Each material loop with the holes directly inside
// it becomes one base face (facing down) and one cap face (facing up), with
// holes; every edge becomes a wall with source edge = its running number.
inline Surface extrude(const std::vector<std::vector<glm::dvec2>>& loops, double z0, double z1) {
  Surface s;
  std::vector<std::uint32_t> first;
  for (const auto& loop : loops) {
    first.push_back(static_cast<std::uint32_t>(s.vertices.size()));
    for (const auto& p : loop) s.vertices.push_back({p.x, p.y, z0});
  }
  const auto top = static_cast<std::uint32_t>(s.vertices.size());
  for (std::uint32_t i = 0; i < top; ++i) s.vertices.push_back({s.vertices[i].x, s.vertices[i].y, z1});

  auto ring = [&](std::size_t li, bool reversed, std::uint32_t offset) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t k = 0; k < loops[li].size(); ++k) out.push_back(offset + first[li] + k);
    if (reversed) std::reverse(out.begin(), out.end());
    return out;
  };
  const LoopNesting nesting = loop_nesting(loops);
  for (std::size_t li = 0; li < loops.size(); ++li) {
    if (nesting.depth[li] % 2) continue;
    SurfaceFace base{FaceKind::Base, -1, {ring(li, true, 0)}, {}};
    SurfaceFace cap{FaceKind::Cap, -1, {ring(li, false, top)}, {}};
    for (std::size_t h = 0; h < loops.size(); ++h) {
      if (nesting.parent[h] != static_cast<int>(li)) continue;
      base.loops.push_back(ring(h, true, 0));
      cap.loops.push_back(ring(h, false, top));
    }
    s.faces.push_back(base);
    s.faces.push_back(cap);
  }
  std::int32_t edge = 0;
  for (std::size_t li = 0; li < loops.size(); ++li) {
    const auto n = static_cast<std::uint32_t>(loops[li].size());
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t a = first[li] + k, b = first[li] + (k + 1) % n;
      s.faces.push_back({FaceKind::Side, edge++, {{a, b, top + b, top + a}}, {}});
    }
  }
  return s;
}

inline std::vector<glm::dvec2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline Surface box(const glm::dvec3& lo, const glm::dvec3& hi) {
  return extrude({rectangle(lo.x, lo.y, hi.x, hi.y)}, lo.z, hi.z);
}

// A 10 x 10 x 2 block around a 4 x 4 courtyard: base and cap have a hole.
inline Surface square_ring() {
  std::vector<glm::dvec2> hole = rectangle(3, 3, 7, 7);
  std::reverse(hole.begin(), hole.end());
  return extrude({rectangle(0, 0, 10, 10), hole}, 0.0, 2.0);
}

// n corners at sorted random angles and radii from 50 to 100 m
// (bench/scale_inputs.py's random family): its roof at 45 degrees is n long
// thin triangles side by side, running every way.
inline std::vector<glm::dvec2> spiky_plan(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi), radius(50.0, 100.0);
  std::vector<double> angles(static_cast<std::size_t>(n));
  for (double& a : angles) a = turn(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<glm::dvec2> ring;
  for (const double a : angles) {
    const double r = radius(rng);
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

// Both surfaces in one, the second's vertex ids shifted.
inline Surface combine(Surface a, const Surface& b) {
  const auto shift = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (SurfaceFace f : b.faces) {
    for (auto& loop : f.loops)
      for (auto& v : loop) v += shift;
    a.faces.push_back(f);
  }
  return a;
}

}  // namespace procex::test

// Sweep states made straight from a plan's points, the plans the engine's
// tests share, and a comparison of two sweeps' output to the bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/driver.h"
#include "core/sweep/sweep_state.h"

namespace procex::engine {

// The clustering scale sweep() tries first.
constexpr Tolerances kStarTolerances{200.0, Tolerances::retry_relative[0]};

inline State loaded(const std::vector<glm::dvec2>& points, const Tolerances& tol, const SweepOptions& options = {},
             std::vector<double> slopes = {}, Budget* budget = nullptr) {
  if (slopes.empty()) slopes.assign(points.size(), 1.0);
  State st(tol, options, budget);
  FaceGroup base;
  base.kind = FaceKind::Base;
  st.base_face = 0;
  st.faces.push_back(base);
  for (std::size_t j = 0; j < points.size(); ++j) st.sources.push_back(Source{static_cast<std::int32_t>(j)});
  load_loop(st, points, std::move(slopes), std::vector<std::string>(points.size()), 0, 0);
  return st;
}

// Loops as load_loop takes them (the first material, counter-clockwise; holes
// clockwise), every edge of slope 1, each edge its own source.
inline State loaded_loops(const std::vector<std::vector<glm::dvec2>>& loops, const Tolerances& tol) {
  State st(tol, {});
  FaceGroup base;
  base.kind = FaceKind::Base;
  base.outward = {0.0, 0.0, -1.0};  // as sweep() loads it, so that build_surface() makes a solid
  st.base_face = 0;
  st.faces.push_back(base);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const int first = static_cast<int>(st.sources.size());
    for (std::size_t j = 0; j < loops[l].size(); ++j)
      st.sources.push_back(Source{static_cast<std::int32_t>(st.sources.size())});
    load_loop(st, loops[l], std::vector<double>(loops[l].size(), 1.0), std::vector<std::string>(loops[l].size()),
              first, static_cast<int>(l));
  }
  return st;
}

// A star of n corners with radii 100 and 90 m alternating, jittered by up to
// a millimetre so that its events do not all fall at one height: every
// second corner is reflex and can run into almost every edge.
inline std::vector<glm::dvec2> star(int n) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < n; ++i) {
    const double r = (i % 2 == 0 ? 100.0 : 90.0) + 1e-3 * std::sin(12.9898 * i);
    const double a = 2.0 * M_PI * i / n;
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return points;
}

// A random star-shaped polygon as bench/scale_inputs.py makes them (sorted
// random angles, radii 50-100 m): about half its corners reflex, their lines
// running every way.
inline std::vector<glm::dvec2> random_star_shaped(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), radius(50.0, 100.0);
  std::vector<double> angles(static_cast<std::size_t>(n));
  for (double& a : angles) a = angle(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<glm::dvec2> points;
  for (double a : angles) {
    const double r = radius(rng);
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return points;
}

// A comb of 1 m teeth on a 1 m bar (bench/scale_inputs.py's), counter-clockwise:
// every reflex corner runs along the line of all the edges between the teeth.
inline std::vector<glm::dvec2> comb(int teeth) {
  std::vector<glm::dvec2> points = {{0, 0}, {2.0 * teeth + 1, 0}, {2.0 * teeth + 1, 1}};
  for (int t = teeth - 1; t >= 0; --t) {
    const double x = 2.0 * t + 1;
    points.insert(points.end(), {{x + 1, 1}, {x + 1, 5}, {x, 5}, {x, 1}});
  }
  points.push_back({0, 1});
  return points;
}

// A square with k x k square holes, clockwise (bench/scale_inputs.py's
// "holes": 2 m holes 1 m apart): the walls along one line of holes are
// collinear.
inline std::vector<std::vector<glm::dvec2>> holes_plan(int k) {
  const double side = 3.0 * k + 1.0;
  std::vector<std::vector<glm::dvec2>> loops{{{0, 0}, {side, 0}, {side, side}, {0, side}}};
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double x = 1.0 + 3.0 * i, y = 1.0 + 3.0 * j;
      loops.push_back({{x, y}, {x, y + 2}, {x + 2, y + 2}, {x + 2, y}});
    }
  return loops;
}

// Slopes from vertical walls to planes leaning out, in a fixed mix: corners
// that do not move, corners faster than the planes, and every corner able to
// split (meeting planes from outside).
inline std::vector<double> mixed_slopes(std::size_t n) {
  const double kinds[] = {1.0, 0.0, 2.5, -0.4, 0.7};
  std::vector<double> slopes;
  for (std::size_t j = 0; j < n; ++j) slopes.push_back(kinds[(j * 7) % 5]);
  return slopes;
}

// Two sweeps' output, to the bit: the same vertices and the same faces.
inline void expect_same_roof(const State& got, const State& expected) {
  EXPECT_EQ(got.vertices.size(), expected.vertices.size());
  EXPECT_EQ(got.faces.size(), expected.faces.size());
  if (got.vertices.size() != expected.vertices.size() || got.faces.size() != expected.faces.size()) return;
  EXPECT_EQ(std::memcmp(got.vertices.data(), expected.vertices.data(), expected.vertices.size() * sizeof expected.vertices[0]), 0);
  for (std::size_t f = 0; f < expected.faces.size(); ++f) {
    const std::vector<HalfEdge>& a = got.faces[f].half_edges;
    const std::vector<HalfEdge>& b = expected.faces[f].half_edges;
    EXPECT_EQ(a.size(), b.size()) << "face " << f;
    for (std::size_t h = 0; h < std::min(a.size(), b.size()); ++h)
      EXPECT_TRUE(a[h].from == b[h].from && a[h].to == b[h].to) << "face " << f << ", half-edge " << h;
  }
}

}  // namespace procex::engine

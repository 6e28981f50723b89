// Points of the plane looked up by distance: a hash grid whose cells are as
// wide as the distance, so a lookup visits the 3 x 3 cells around a point
// whatever the number of points.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace procex {

class PointGrid {
 public:
  explicit PointGrid(double radius) : radius_(radius) {}

  void add(glm::dvec2 p, std::uint32_t id) { cells_[key(cell(p.x), cell(p.y))].push_back({p, id}); }

  // Calls f(id, position) for every point added within the radius of p.
  template <class F>
  void for_each_near(glm::dvec2 p, F&& f) const {
    const long long gx = cell(p.x), gy = cell(p.y);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = cells_.find(key(gx + dx, gy + dy));
        if (it == cells_.end()) continue;
        for (const auto& [q, id] : it->second)
          if (glm::length(q - p) <= radius_) f(id, q);
      }
  }

  // The first point added within the radius of p, if any.
  std::optional<std::uint32_t> first_near(glm::dvec2 p) const {
    std::optional<std::uint32_t> found;
    for_each_near(p, [&](std::uint32_t id, glm::dvec2) {
      if (!found || id < *found) found = id;
    });
    return found;
  }

 private:
  long long cell(double v) const { return static_cast<long long>(std::floor(v / radius_)); }
  // Unsigned arithmetic: cells far from the origin wrap instead of overflowing.
  static std::uint64_t key(long long x, long long y) {
    return static_cast<std::uint64_t>(x) * 73856093ULL ^ static_cast<std::uint64_t>(y) * 19349663ULL;
  }

  double radius_;
  std::unordered_map<std::uint64_t, std::vector<std::pair<glm::dvec2, std::uint32_t>>> cells_;
};

}  // namespace procex

// Points of the plane looked up by distance: a hash grid whose cells are as
// wide as the distance, so a lookup visits the 3 x 3 cells around a point
// whatever the number of points. The cells live in one open-addressed table
// and the points in one array, each cell chaining its points in the order
// they came: no allocation per point or per cell.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace procex {

class PointGrid {
 public:
  explicit PointGrid(double radius) : radius_(radius) {}

  // Room for about n points (each in a cell of its own) without rehashing.
  void reserve(std::size_t n) {
    points_.reserve(n);
    std::size_t size = 16;
    while (size < 2 * n) size *= 2;
    if (size > cells_.size()) rehash(size);
  }

  void add(glm::dvec2 p, std::uint32_t id) {
    if (2 * (used_ + 1) > cells_.size()) grow();
    Cell& c = find_or_add(cell(p.x), cell(p.y));
    const auto i = static_cast<std::uint32_t>(points_.size());
    points_.push_back({p, id, kEnd});
    if (c.head == kEnd) {
      c.head = i;
    } else {
      points_[c.tail].next = i;
    }
    c.tail = i;
  }

  // Calls f(id, position) for every point added within the radius of p.
  template <class F>
  void for_each_near(glm::dvec2 p, F&& f) const {
    if (cells_.empty()) return;
    const long long gx = cell(p.x), gy = cell(p.y);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const Cell* c = find(gx + dx, gy + dy);
        if (!c) continue;
        for (std::uint32_t i = c->head; i != kEnd; i = points_[i].next)
          if (glm::length(points_[i].p - p) <= radius_) f(points_[i].id, points_[i].p);
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
  static constexpr std::uint32_t kEnd = UINT32_MAX;
  struct Point {
    glm::dvec2 p;
    std::uint32_t id, next;
  };
  struct Cell {
    long long x = 0, y = 0;
    std::uint32_t head = kEnd, tail = kEnd;  // head == kEnd: an empty slot
  };

  long long cell(double v) const { return static_cast<long long>(std::floor(v / radius_)); }
  // Unsigned arithmetic: cells far from the origin wrap instead of overflowing.
  static std::uint64_t hash(long long x, long long y) {
    const std::uint64_t h =
        static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4FULL;
    return h ^ (h >> 32);
  }
  const Cell* find(long long x, long long y) const {
    const std::size_t mask = cells_.size() - 1;
    for (std::size_t s = hash(x, y) & mask;; s = (s + 1) & mask) {
      const Cell& c = cells_[s];
      if (c.head == kEnd) return nullptr;
      if (c.x == x && c.y == y) return &c;
    }
  }
  Cell& find_or_add(long long x, long long y) {
    const std::size_t mask = cells_.size() - 1;
    for (std::size_t s = hash(x, y) & mask;; s = (s + 1) & mask) {
      Cell& c = cells_[s];
      if (c.head == kEnd) {
        ++used_;
        c.x = x;
        c.y = y;
        return c;
      }
      if (c.x == x && c.y == y) return c;
    }
  }
  void grow() { rehash(cells_.empty() ? 16 : 2 * cells_.size()); }
  void rehash(std::size_t size) {
    std::vector<Cell> old = std::move(cells_);
    cells_.assign(size, Cell{});
    used_ = 0;
    for (const Cell& c : old)
      if (c.head != kEnd) {
        Cell& to = find_or_add(c.x, c.y);
        to.head = c.head;
        to.tail = c.tail;
      }
  }

  double radius_;
  std::vector<Cell> cells_;  // a power of two in size, at most half used
  std::size_t used_ = 0;
  std::vector<Point> points_;
};

}  // namespace procex

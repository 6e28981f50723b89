// Points of the plane in a k-d tree whose nodes keep their bounding boxes, so
// that a search can skip every part of the plane its caller rules out by box
// (convex_partition: the parts wholly outside an ear). A grid or a box search
// visits every point under a query's bounding box; for a long thin triangle
// (the fan of ears across a comb's bar) that is most of the points, every time.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

namespace procex {

class PointTree {
 public:
  PointTree() = default;
  explicit PointTree(std::vector<std::pair<glm::dvec2, std::uint32_t>> points) : points_(std::move(points)) {
    if (points_.empty()) return;
    std::vector<std::pair<glm::dvec2, std::uint32_t>> scratch;
    build(0, points_.size(), bounds(points_.begin(), points_.end()), scratch);
  }

  // Calls f(id, position) for the points in every part of the tree that
  // skip(lo, hi) does not rule out (it may rule out a box only if no point
  // f is to see can lie in it), until f returns false; whether none did.
  template <class Skip, class F>
  bool search(Skip&& skip, F&& f) const {
    return nodes_.empty() || visit(0, skip, f);
  }

 private:
  static constexpr std::size_t kLeafSize = 8;
  // A split leaves much less when its boxes' area is under this share of the
  // other way's; kLongest bounds how elongated a box is let grow otherwise
  // (measured on the 262,144-corner square with holes: 8 visits 58 % more
  // nodes than boxes let grow without bound, 16 19 %; the random plan's ears
  // look at 49M and 60M points against 1.09 billion).
  static constexpr double kMuchLess = 0.5;
  static constexpr double kLongest = 16.0;
  struct Node {
    glm::dvec2 lo, hi;
    std::uint32_t first, count;  // the node's points in points_
    std::uint32_t right = 0;     // an inner node's second child (its first follows it)
  };

  using Iterator = std::vector<std::pair<glm::dvec2, std::uint32_t>>::iterator;
  using Box = std::pair<glm::dvec2, glm::dvec2>;

  // box: the node's points' bounds; scratch: room for its points.
  void build(std::size_t first, std::size_t count, const Box& box,
             std::vector<std::pair<glm::dvec2, std::uint32_t>>& scratch) {
    const std::size_t id = nodes_.size();
    nodes_.push_back({box.first, box.second, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count)});
    if (count <= kLeafSize) return;
    const auto begin = points_.begin() + static_cast<std::ptrdiff_t>(first);
    const auto end = begin + static_cast<std::ptrdiff_t>(count);
    // Split across x or y, whichever leaves the smaller boxes. Points on a
    // line across the split stay on one side, so rows of points (the
    // corners of a grid of holes) end in boxes of their own that a thin
    // triangle between two rows passes by: a split through a row would leave
    // boxes reaching over the gap between it and the next. The points as
    // split across x wait in scratch while y is tried.
    //
    // Where neither way leaves much less (points spread evenly: both save
    // about one spacing's worth), a box more than kLongest times as long as
    // it is wide is split across its length. Left to the areas' noise, the
    // splits of a random star-shaped plan's corners kept running one way,
    // into strips 100 m long and a few cm wide, and every thin ear running
    // across them (its spikes point every way) met O(n) of them.
    std::size_t mid[2];
    Box halves[2][2];
    double area[2];
    for (int axis = 0; axis < 2; ++axis) {
      if (axis == 1) scratch.assign(begin, end);
      mid[axis] = split(begin, end, axis);
      halves[axis][0] = bounds(begin, begin + static_cast<std::ptrdiff_t>(mid[axis]));
      halves[axis][1] = bounds(begin + static_cast<std::ptrdiff_t>(mid[axis]), end);
      area[axis] = 0.0;
      for (const auto& [lo, hi] : halves[axis]) area[axis] += (hi.x - lo.x) * (hi.y - lo.y);
    }
    int axis = area[0] < area[1] ? 0 : 1;
    if (area[axis] >= kMuchLess * area[1 - axis]) {
      const glm::dvec2 extent = box.second - box.first;
      if (extent.x > kLongest * extent.y) axis = 0;
      if (extent.y > kLongest * extent.x) axis = 1;
    }
    if (axis == 0) std::copy(scratch.begin(), scratch.end(), begin);
    build(first, mid[axis], halves[axis][0], scratch);
    nodes_[id].right = static_cast<std::uint32_t>(nodes_.size());
    build(first + mid[axis], count - mid[axis], halves[axis][1], scratch);
  }

  static Box bounds(Iterator begin, Iterator end) {
    glm::dvec2 lo = begin->first, hi = lo;
    for (auto it = begin; it != end; ++it) lo = glm::min(lo, it->first), hi = glm::max(hi, it->first);
    return {lo, hi};
  }

  // Orders [begin, end) about the median along axis and returns how many
  // lie before the split: the median's value goes wholly to the side that
  // leaves the halves nearer even, unless every point has it.
  static std::size_t split(Iterator begin, Iterator end, int axis) {
    const auto count = end - begin, half = count / 2;
    std::nth_element(begin, begin + half, end,
                     [axis](const auto& a, const auto& b) { return a.first[axis] < b.first[axis]; });
    const double median = begin[half].first[axis];
    const auto below = std::partition(begin, begin + half, [&](const auto& p) { return p.first[axis] < median; });
    const auto above = std::partition(begin + half, end, [&](const auto& p) { return p.first[axis] == median; });
    const auto at_below = below - begin, at_above = above - begin;
    if (at_below == 0 && at_above == count) return static_cast<std::size_t>(half);
    if (at_below == 0) return static_cast<std::size_t>(at_above);
    if (at_above == count) return static_cast<std::size_t>(at_below);
    return static_cast<std::size_t>(half - at_below <= at_above - half ? at_below : at_above);
  }

  template <class Skip, class F>
  bool visit(std::size_t id, Skip& skip, F& f) const {
    const Node& n = nodes_[id];
    if (skip(n.lo, n.hi)) return true;
    if (n.right == 0) {
      for (std::size_t k = n.first; k < n.first + n.count; ++k)
        if (!f(points_[k].second, points_[k].first)) return false;
      return true;
    }
    return visit(id + 1, skip, f) && visit(n.right, skip, f);
  }

  std::vector<std::pair<glm::dvec2, std::uint32_t>> points_;
  std::vector<Node> nodes_;
};

}  // namespace procex

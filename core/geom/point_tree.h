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
    if (!points_.empty()) build(0, points_.size());
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
  struct Node {
    glm::dvec2 lo, hi;
    std::uint32_t first, count;  // the node's points in points_
    std::uint32_t right = 0;     // an inner node's second child (its first follows it)
  };

  void build(std::size_t first, std::size_t count) {
    const std::size_t id = nodes_.size();
    glm::dvec2 lo = points_[first].first, hi = lo;
    for (std::size_t k = first; k < first + count; ++k) lo = glm::min(lo, points_[k].first), hi = glm::max(hi, points_[k].first);
    nodes_.push_back({lo, hi, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count)});
    if (count <= kLeafSize) return;
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    const auto begin = points_.begin() + static_cast<std::ptrdiff_t>(first);
    std::nth_element(begin, begin + static_cast<std::ptrdiff_t>(count / 2), begin + static_cast<std::ptrdiff_t>(count),
                     [axis](const auto& a, const auto& b) { return a.first[axis] < b.first[axis]; });
    build(first, count / 2);
    nodes_[id].right = static_cast<std::uint32_t>(nodes_.size());
    build(first + count / 2, count - count / 2);
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

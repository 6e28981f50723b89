#include "core/geom/nesting.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/common.hpp>

#include "core/geom/predicates.h"

namespace procex {

double twice_signed_area(const std::vector<glm::dvec2>& loop) {
  double a = 0.0;
  const std::size_t n = loop.size();
  if (n == 0) return a;
  // Relative to the first point, which keeps the sum accurate far from the origin.
  const glm::dvec2 o = loop[0];
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const glm::dvec2 p = loop[k] - o, q = loop[k + 1] - o;
    a += p.x * q.y - p.y * q.x;
  }
  return a;
}

bool point_in_loop(const glm::dvec2& p, const std::vector<glm::dvec2>& loop) {
  bool inside = false;
  const std::size_t n = loop.size();
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2& a = loop[k];
    const glm::dvec2& b = loop[(k + 1) % n];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    // The edge crosses the horizontal line through p; is the crossing right of p?
    const int o = orient2d(a, b, p);
    if (b.y > a.y ? o > 0 : o < 0) inside = !inside;
  }
  return inside;
}

namespace {

struct Box {
  glm::dvec2 lo, hi;
  bool contains(const Box& o) const { return lo.x <= o.lo.x && lo.y <= o.lo.y && o.hi.x <= hi.x && o.hi.y <= hi.y; }
};

// The loops' boxes in a hierarchy (split at the median of their centres
// along the longer side), so that the boxes holding a loop's box are found
// below the nodes whose boxes hold it: comparing every pair of boxes, a
// square with 65,536 square holes took 6 s.
class BoxTree {
 public:
  explicit BoxTree(const std::vector<Box>& boxes) : boxes_(boxes), order_(boxes.size()) {
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    if (!boxes.empty()) build(0, static_cast<std::uint32_t>(boxes.size()));
  }

  // Calls f(j) for every box j that holds b.
  template <class F>
  void holding(const Box& b, F&& f) const {
    if (nodes_.empty()) return;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!node.box.contains(b)) continue;
      if (node.left == kLeaf) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
          if (boxes_[order_[k]].contains(b)) f(order_[k]);
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
  }

 private:
  static constexpr std::uint32_t kLeaf = std::numeric_limits<std::uint32_t>::max(), kLeafMost = 4;
  struct Node {
    Box box;
    std::uint32_t first, count, left = kLeaf, right = kLeaf;
  };

  std::uint32_t build(std::uint32_t first, std::uint32_t count) {
    Box box = boxes_[order_[first]];
    for (std::uint32_t k = first + 1; k < first + count; ++k) {
      box.lo = glm::min(box.lo, boxes_[order_[k]].lo);
      box.hi = glm::max(box.hi, boxes_[order_[k]].hi);
    }
    const auto at = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({box, first, count});
    if (count <= kLeafMost) return at;
    const int axis = box.hi.x - box.lo.x >= box.hi.y - box.lo.y ? 0 : 1;
    // An empty loop's box (infinite ends) sorts last: the order stays strict.
    const auto key = [&](std::uint32_t i) {
      const double centre = boxes_[i].lo[axis] + boxes_[i].hi[axis];
      return std::isnan(centre) ? HUGE_VAL : centre;
    };
    std::nth_element(order_.begin() + first, order_.begin() + first + count / 2, order_.begin() + first + count,
                     [&](std::uint32_t i, std::uint32_t j) { return key(i) < key(j); });
    const std::uint32_t left = build(first, count / 2);
    const std::uint32_t right = build(first + count / 2, count - count / 2);
    nodes_[at].left = left;
    nodes_[at].right = right;
    return at;
  }

  const std::vector<Box>& boxes_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace

LoopNesting loop_nesting(const std::vector<std::vector<glm::dvec2>>& loops) {
  const std::size_t n = loops.size();
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    Box b{glm::dvec2(std::numeric_limits<double>::infinity()), glm::dvec2(-std::numeric_limits<double>::infinity())};
    for (const auto& p : loops[i]) {
      b.lo = glm::min(b.lo, p);
      b.hi = glm::max(b.hi, p);
    }
    boxes[i] = b;
  }
  const BoxTree tree(boxes);
  LoopNesting out{std::vector<int>(n, 0), std::vector<int>(n, -1)};
  std::vector<std::vector<int>> containers(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (loops[i].empty()) continue;
    tree.holding(boxes[i], [&](std::uint32_t j) {
      if (j != i && loops[j].size() >= 3 && point_in_loop(loops[i][0], loops[j]))
        containers[i].push_back(static_cast<int>(j));
    });
    out.depth[i] = static_cast<int>(containers[i].size());
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int j : containers[i])
      if (out.depth[j] == out.depth[i] - 1) out.parent[i] = j;
  return out;
}

}  // namespace procex

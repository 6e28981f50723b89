// Segments, added over time, looked up by rays to +x: convex_partition joins
// each hole to the ring by the first ring edge a ray from the hole meets, and
// the ring grows with every hole joined. Walking the whole ring for every hole
// made a square with 65,536 holes take a minute (O(holes x vertices)).
//
// The segments sit in trees of boxes (split at medians), each tree about
// twice the size of the next as segments are added, so that a segment is
// rebuilt into O(log n) trees and a ray starts from O(log n) roots; the
// latest few are looked at one by one until they are worth a tree.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

class HorizontalRays {
 public:
  void add(glm::dvec2 a, glm::dvec2 b, std::uint32_t id);

  // Calls f(id) for every segment whose box the ray from p to +x passes at
  // or left of `limit`, nearest boxes first; `limit` is read again as the
  // search goes, so f may lower it to the nearest hit found. Not const: the
  // search keeps its stack here.
  template <class F>
  void along(glm::dvec2 p, const double& limit, F&& f) {
    for (const Tree& t : trees_) {
      if (t.nodes.empty()) continue;
      stack_.assign(1, 0u);
      while (!stack_.empty()) {
        const Node& n = t.nodes[stack_.back()];
        stack_.pop_back();
        if (n.hi.x < p.x || n.lo.x > limit || p.y < n.lo.y || p.y > n.hi.y) continue;
        if (n.left == kLeaf) {
          for (std::uint32_t k = n.first; k < n.first + n.count; ++k) f(t.id[k]);
          continue;
        }
        // The nearer child last, so that it is searched first.
        const bool left_first = t.nodes[n.left].lo.x <= t.nodes[n.left + 1].lo.x;
        stack_.push_back(left_first ? n.left + 1 : n.left);
        stack_.push_back(left_first ? n.left : n.left + 1);
      }
    }
    for (std::size_t k = indexed_; k < boxes_.size(); ++k) {
      const Box& b = boxes_[k];
      if (!(b.hi.x < p.x || b.lo.x > limit || p.y < b.lo.y || p.y > b.hi.y)) f(b.id);
    }
  }

 private:
  static constexpr std::uint32_t kLeaf = 0xffffffffu;
  struct Node {
    glm::dvec2 lo, hi;
    std::uint32_t first, count, left = kLeaf;  // children left and left + 1
  };
  struct Tree {
    std::size_t from = 0, to = 0;  // the segments it holds, by the order added
    std::vector<Node> nodes;
    std::vector<std::uint32_t> id;  // its segments' ids, leaf by leaf
  };
  Tree build(std::size_t from, std::size_t to) const;

  struct Box {
    glm::dvec2 lo, hi;
    std::uint32_t id;
  };
  std::vector<Box> boxes_;  // every segment's, in the order added
  std::vector<Tree> trees_;
  std::size_t indexed_ = 0;
  std::vector<std::uint32_t> stack_;  // along's
};

}  // namespace procex

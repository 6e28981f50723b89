#include "core/geom/horizontal_rays.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace procex {
namespace {

constexpr std::uint32_t kLeafMost = 8;
// Segments looked at one by one before they make a tree of their own.
constexpr std::size_t kTreeLeast = 64;

}  // namespace

void HorizontalRays::add(glm::dvec2 a, glm::dvec2 b, std::uint32_t id) {
  boxes_.push_back({glm::min(a, b), glm::max(a, b), id});
  if (boxes_.size() < indexed_ + kTreeLeast) return;
  trees_.push_back(build(indexed_, boxes_.size()));
  indexed_ = boxes_.size();
  while (trees_.size() >= 2) {
    const Tree& last = trees_.back();
    const Tree& before = trees_[trees_.size() - 2];
    if (before.to - before.from >= 2 * (last.to - last.from)) break;
    Tree merged = build(before.from, last.to);
    trees_.pop_back();
    trees_.back() = std::move(merged);
  }
}

HorizontalRays::Tree HorizontalRays::build(std::size_t from, std::size_t to) const {
  Tree t;
  t.from = from;
  t.to = to;
  std::vector<std::uint32_t> order(to - from);
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(from + k);
  // Not a number sorts last: the order stays strict (nth_element needs it).
  const auto centre = [&](std::uint32_t k, int axis) {
    const double c = boxes_[k].lo[axis] + boxes_[k].hi[axis];
    return std::isnan(c) ? HUGE_VAL : c;
  };
  t.nodes.push_back({{}, {}, 0, static_cast<std::uint32_t>(order.size())});
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const std::uint32_t first = t.nodes[i].first, count = t.nodes[i].count;
    glm::dvec2 lo = boxes_[order[first]].lo, hi = boxes_[order[first]].hi;
    for (std::uint32_t k = first + 1; k < first + count; ++k) {
      lo = glm::min(lo, boxes_[order[k]].lo);
      hi = glm::max(hi, boxes_[order[k]].hi);
    }
    t.nodes[i].lo = lo;
    t.nodes[i].hi = hi;
    if (count <= kLeafMost) continue;
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    const auto begin = order.begin() + first;
    std::nth_element(begin, begin + count / 2, begin + count,
                     [&](std::uint32_t a, std::uint32_t b) { return centre(a, axis) < centre(b, axis); });
    t.nodes[i].left = static_cast<std::uint32_t>(t.nodes.size());
    t.nodes.push_back({{}, {}, first, count / 2});
    t.nodes.push_back({{}, {}, first + count / 2, count - count / 2});
  }
  t.id.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) t.id[k] = boxes_[order[k]].id;
  return t;
}

}  // namespace procex

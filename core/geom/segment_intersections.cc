#include "core/geom/segment_intersections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/predicates.h"
#include "core/geom/segment_distance.h"

namespace procex {

namespace {

// Consecutive segments i -> j share i.b == j.a; they overlap beyond it only
// if j turns straight back along i.
bool consecutive_overlap(const Segment2& i, const Segment2& j) {
  // The cheap test first: most turns do not reverse.
  return glm::dot(i.b - i.a, j.b - j.a) < 0.0 && orient2d(i.a, i.b, j.b) == 0;
}

// Closest approach of two segments that do not cross: at an endpoint of one.
double segment_gap(const Segment2& i, const Segment2& j) {
  return std::min({distance_to_segment(i.a, j.a, j.b), distance_to_segment(i.b, j.a, j.b),
                   distance_to_segment(j.a, i.a, i.b), distance_to_segment(j.b, i.a, i.b)});
}

// Consecutive segments i -> j fold back within `within` when j's far end lies
// that near i, or i's start that near j.
bool consecutive_fold(const Segment2& i, const Segment2& j, double within) {
  return consecutive_overlap(i, j) ||
         (within > 0.0 && (distance_to_segment(j.b, i.a, i.b) <= within || distance_to_segment(i.a, j.a, j.b) <= within));
}

}  // namespace

bool segments_meet(const Segment2& i, const Segment2& j, double within) {
  return segments_intersect(i.a, i.b, j.a, j.b) || (within > 0.0 && segment_gap(i, j) <= within);
}

namespace {

// Whether segments i and j of chains meet: where one follows the other (as
// `next` links them), only by folding back onto it.
bool chained_pair_meets(const Segment2& si, const Segment2& sj, bool i_then_j, bool j_then_i, double within) {
  // A two-edge loop.
  if (i_then_j && j_then_i) return consecutive_fold(si, sj, within) || consecutive_fold(sj, si, within);
  if (i_then_j) return consecutive_fold(si, sj, within);
  if (j_then_i) return consecutive_fold(sj, si, within);
  return segments_meet(si, sj, within);
}

struct Box2 {
  glm::dvec2 lo, hi;
};

bool boxes_overlap(const Box2& a, const Box2& b) {
  return !(a.hi.x < b.lo.x || b.hi.x < a.lo.x || a.hi.y < b.lo.y || b.hi.y < a.lo.y);
}

glm::dvec2 perp(glm::dvec2 v) { return {-v.y, v.x}; }

// A box turned along a direction. The long thin spikes of a plan side by side
// fit in thin strips, while their boxes along the axes, or the cells of a
// grid they pass, hold each spike's neighbours for most of its length: the
// edges of a random star-shaped plan of 262,144 corners, 17 m long and 2 mm
// apart, shared a grid's cells in 7.8e8 pairs.
struct Strip {
  glm::dvec2 centre{0.0}, axis{1.0, 0.0};  // axis of unit length
  double along = 0.0, across = 0.0;        // half the extent along axis and across it
};

// False only where an axis parts the strips (the separating axis test over
// their four axes).
bool strips_overlap(const Strip& a, const Strip& b) {
  const glm::dvec2 d = b.centre - a.centre;
  const auto parts = [&](glm::dvec2 w) {
    const double ra = a.along * std::abs(glm::dot(a.axis, w)) + a.across * std::abs(glm::dot(perp(a.axis), w));
    const double rb = b.along * std::abs(glm::dot(b.axis, w)) + b.across * std::abs(glm::dot(perp(b.axis), w));
    return std::abs(glm::dot(d, w)) > ra + rb;
  };
  return !(parts(a.axis) || parts(perp(a.axis)) || parts(b.axis) || parts(perp(b.axis)));
}

// A hierarchy of strips over the segments, each node turned along the main
// direction of its segments and split across it or along it, whichever
// leaves the smaller strips; pairs are visited where two leaves' strips
// overlap. Spikes side by side fall into strips of their neighbours, so a
// plan's segments come in a few pairs each (about 4 for a random star-shaped
// plan's edges), after an O(n log n) build.
class SegmentTree {
 public:
  // At most this many segments are compared pair by pair, in order, without a tree.
  static constexpr std::uint32_t kFlatMost = 32;

  SegmentTree(const std::vector<Segment2>& segments, double within) : segments_(segments), boxes_(segments.size()) {
    double reach = 0.0;
    glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Segment2& s = segments[i];
      boxes_[i] = {glm::min(s.a, s.b) - within, glm::max(s.a, s.b) + within};
      lo = glm::min(lo, boxes_[i].lo);
      hi = glm::max(hi, boxes_[i].hi);
      reach = std::max({reach, std::abs(s.a.x), std::abs(s.a.y), std::abs(s.b.x), std::abs(s.b.y)});
    }
    // Rounding in turning the points into a strip's frame and back, and in
    // the overlap test; the coordinates' own last places count when they lie
    // far from the origin.
    const double span = std::max({hi.x - lo.x, hi.y - lo.y, std::numeric_limits<double>::min()});
    margin_ = within + 1e-9 * span + 16.0 * std::numeric_limits<double>::epsilon() * reach;
    order_.resize(segments.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<std::uint32_t>(i);
    nodes_.reserve(2 * segments.size() / kLeafMost + 1);
    build(0, static_cast<std::uint32_t>(segments.size()));
  }

  void visit_pairs(const std::function<bool(std::size_t, std::size_t)>& visit) {
    visit_ = &visit;
    self_pairs(0);
  }

 private:
  static constexpr std::uint32_t kLeaf = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::uint32_t kLeafMost = 4;

  struct Node {
    Strip strip;
    std::uint32_t first = 0, count = 0;  // its segments in order_
    std::uint32_t left = kLeaf, right = kLeaf;
  };

  // The main direction of the segments order_[first, first + count): the
  // principal axis of their directions, a segment's weighing as its length
  // squared.
  glm::dvec2 direction(std::uint32_t first, std::uint32_t count) const {
    double xx = 0.0, xy = 0.0, yy = 0.0;
    for (std::uint32_t k = first; k < first + count; ++k) {
      const glm::dvec2 d = segments_[order_[k]].b - segments_[order_[k]].a;
      xx += d.x * d.x;
      xy += d.x * d.y;
      yy += d.y * d.y;
    }
    // The larger eigenvalue's eigenvector of [[xx, xy], [xy, yy]].
    const double half_gap = 0.5 * (xx - yy), root = std::hypot(half_gap, xy);
    const glm::dvec2 v = half_gap >= 0.0 ? glm::dvec2(half_gap + root, xy) : glm::dvec2(xy, root - half_gap);
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? v / length : glm::dvec2(1.0, 0.0);
  }

  // The extent of the segments' ends along `axis` and across it, from `origin`.
  struct Extent {
    double s_lo = std::numeric_limits<double>::infinity(), s_hi = -s_lo, t_lo = s_lo, t_hi = -s_lo;
    double area() const { return (s_hi - s_lo) * (t_hi - t_lo); }
  };
  Extent extent(std::uint32_t first, std::uint32_t count, glm::dvec2 origin, glm::dvec2 axis) const {
    Extent e;
    for (std::uint32_t k = first; k < first + count; ++k)
      for (const glm::dvec2 p : {segments_[order_[k]].a, segments_[order_[k]].b}) {
        const double s = glm::dot(p - origin, axis), t = glm::dot(p - origin, perp(axis));
        e.s_lo = std::min(e.s_lo, s);
        e.s_hi = std::max(e.s_hi, s);
        e.t_lo = std::min(e.t_lo, t);
        e.t_hi = std::max(e.t_hi, t);
      }
    return e;
  }

  // Orders order_[first, first + count) about its median by the segments'
  // midpoints along w.
  void split_at_median(std::uint32_t first, std::uint32_t count, glm::dvec2 w) {
    keyed_.clear();
    for (std::uint32_t k = first; k < first + count; ++k) {
      const double key = glm::dot(segments_[order_[k]].a + segments_[order_[k]].b, w);
      // Not a number sorts last: the order stays strict (nth_element needs it).
      keyed_.push_back({std::isnan(key) ? HUGE_VAL : key, order_[k]});
    }
    std::nth_element(keyed_.begin(), keyed_.begin() + count / 2, keyed_.end());
    for (std::uint32_t k = 0; k < count; ++k) order_[first + k] = keyed_[k].second;
  }

  std::uint32_t build(std::uint32_t first, std::uint32_t count) {
    const auto at = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_[at].first = first;
    nodes_[at].count = count;
    // The root's strip is never compared with another, and a few segments'
    // pairs of boxes cost less to compare than strips to build (a building's
    // plan, checked once for every footprint of a batch).
    const bool root = at == 0;
    if (root && count <= kFlatMost) return at;
    const glm::dvec2 axis = direction(first, count), origin = segments_[order_[first]].a;
    if (!root) {
      const Extent e = extent(first, count, origin, axis);
      Strip& strip = nodes_[at].strip;
      strip.axis = axis;
      strip.centre = origin + axis * (0.5 * (e.s_lo + e.s_hi)) + perp(axis) * (0.5 * (e.t_lo + e.t_hi));
      strip.along = 0.5 * (e.s_hi - e.s_lo) + margin_;
      strip.across = 0.5 * (e.t_hi - e.t_lo) + margin_;
    }
    if (count <= kLeafMost) return at;
    // Across the main direction parts spikes side by side; along it, a row
    // of short segments.
    const std::uint32_t half = count / 2;
    const auto halves_area = [&](glm::dvec2 w) {
      split_at_median(first, count, w);
      return extent(first, half, origin, axis).area() + extent(first + half, count - half, origin, axis).area();
    };
    const double along_area = halves_area(axis);
    if (halves_area(perp(axis)) > along_area) split_at_median(first, count, axis);
    const std::uint32_t left = build(first, half);
    const std::uint32_t right = build(first + half, count - half);
    nodes_[at].left = left;
    nodes_[at].right = right;
    return at;
  }

  bool emit(std::uint32_t i, std::uint32_t j) const {
    if (!boxes_overlap(boxes_[i], boxes_[j])) return true;
    return (*visit_)(std::min(i, j), std::max(i, j));
  }

  bool self_pairs(std::uint32_t n) {
    const Node& node = nodes_[n];
    if (node.left == kLeaf) {
      for (std::uint32_t p = node.first; p < node.first + node.count; ++p)
        for (std::uint32_t q = p + 1; q < node.first + node.count; ++q)
          if (!emit(order_[p], order_[q])) return false;
      return true;
    }
    return self_pairs(node.left) && self_pairs(node.right) && cross_pairs(node.left, node.right);
  }

  bool cross_pairs(std::uint32_t a, std::uint32_t b) {
    const Node &na = nodes_[a], &nb = nodes_[b];
    if (!strips_overlap(na.strip, nb.strip)) return true;
    if (na.left == kLeaf && nb.left == kLeaf) {
      for (std::uint32_t p = na.first; p < na.first + na.count; ++p)
        for (std::uint32_t q = nb.first; q < nb.first + nb.count; ++q)
          if (!emit(order_[p], order_[q])) return false;
      return true;
    }
    if (nb.left == kLeaf || (na.left != kLeaf && na.count >= nb.count))
      return cross_pairs(na.left, b) && cross_pairs(na.right, b);
    return cross_pairs(a, nb.left) && cross_pairs(a, nb.right);
  }

  const std::vector<Segment2>& segments_;
  std::vector<Box2> boxes_;  // each segment's, grown by within
  double margin_ = 0.0;
  std::vector<std::uint32_t> order_;
  std::vector<std::pair<double, std::uint32_t>> keyed_;  // split_at_median's
  std::vector<Node> nodes_;
  const std::function<bool(std::size_t, std::size_t)>* visit_ = nullptr;
};

}  // namespace

void for_each_near_segment_pair(const std::vector<Segment2>& segments, double within,
                                const std::function<bool(std::size_t, std::size_t)>& visit) {
  if (segments.size() < 2) return;
  SegmentTree(segments, within).visit_pairs(visit);
}

std::vector<std::pair<std::size_t, std::size_t>> intersecting_segment_pairs(const std::vector<Segment2>& segments,
                                                                            const std::vector<std::size_t>& next,
                                                                            std::size_t max_pairs, double within) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for_each_near_segment_pair(segments, within, [&](std::size_t i, std::size_t j) {
    const bool i_then_j = !next.empty() && next[i] == j;
    const bool j_then_i = !next.empty() && next[j] == i;
    if (chained_pair_meets(segments[i], segments[j], i_then_j, j_then_i, within)) out.push_back({i, j});
    return out.size() < max_pairs;
  });
  std::sort(out.begin(), out.end());
  return out;
}

LoopSegments loop_segments(const std::vector<std::vector<glm::dvec2>>& loops) {
  LoopSegments out;
  for (const auto& loop : loops) {
    const std::size_t first = out.segments.size(), n = loop.size();
    out.first.push_back(first);
    for (std::size_t k = 0; k < n; ++k) {
      out.segments.push_back({loop[k], loop[(k + 1) % n]});
      out.next.push_back(first + (k + 1) % n);
    }
  }
  return out;
}

std::optional<std::pair<std::size_t, std::size_t>> loop_crossing(const std::vector<glm::dvec2>& loop) {
  // A short loop's pairs in the order the tree's flat root visits them,
  // without building it: the sweep asks this of most faces it makes.
  const std::size_t n = loop.size();
  if (n <= SegmentTree::kFlatMost) {
    std::array<Segment2, SegmentTree::kFlatMost> segs;
    std::array<Box2, SegmentTree::kFlatMost> boxes;
    for (std::size_t k = 0; k < n; ++k) {
      segs[k] = {loop[k], loop[k + 1 == n ? 0 : k + 1]};
      boxes[k] = {glm::min(segs[k].a, segs[k].b), glm::max(segs[k].a, segs[k].b)};
    }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (boxes_overlap(boxes[i], boxes[j]) &&
            chained_pair_meets(segs[i], segs[j], j == i + 1, i == 0 && j == n - 1, 0.0))
          return std::pair{i, j};
    return std::nullopt;
  }
  const LoopSegments segs = loop_segments({loop});
  const auto crossings = intersecting_segment_pairs(segs.segments, segs.next, 1);
  if (crossings.empty()) return std::nullopt;
  return crossings[0];
}

}  // namespace procex

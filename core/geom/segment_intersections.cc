#include "core/geom/segment_intersections.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/predicates.h"

namespace procex {

namespace {

// Consecutive segments i -> j share i.b == j.a; they overlap beyond it only
// if j turns straight back along i.
bool consecutive_overlap(const Segment2& i, const Segment2& j) {
  return orient2d(i.a, i.b, j.b) == 0 && glm::dot(i.b - i.a, j.b - j.a) < 0.0;
}

double distance_to_segment(const glm::dvec2& p, const Segment2& s) {
  const glm::dvec2 d = s.b - s.a;
  const double len2 = glm::dot(d, d);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s.a, d) / len2, 0.0, 1.0) : 0.0;
  return glm::distance(p, s.a + t * d);
}

// Closest approach of two segments that do not cross: at an endpoint of one.
double segment_gap(const Segment2& i, const Segment2& j) {
  return std::min({distance_to_segment(i.a, j), distance_to_segment(i.b, j), distance_to_segment(j.a, i),
                   distance_to_segment(j.b, i)});
}

// Consecutive segments i -> j fold back within `within` when j's far end lies
// that near i, or i's start that near j.
bool consecutive_fold(const Segment2& i, const Segment2& j, double within) {
  return consecutive_overlap(i, j) ||
         (within > 0.0 && (distance_to_segment(j.b, i) <= within || distance_to_segment(i.a, j) <= within));
}

}  // namespace

bool segments_meet(const Segment2& i, const Segment2& j, double within) {
  return segments_intersect(i.a, i.b, j.a, j.b) || (within > 0.0 && segment_gap(i, j) <= within);
}

void for_each_box_pair(const std::vector<Box2>& boxes, const std::function<bool(std::size_t, std::size_t)>& visit) {
  const std::size_t n = boxes.size();
  if (n < 2) return;
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
  for (const Box2& b : boxes) {
    lo_x = std::min(lo_x, b.lo.x);
    lo_y = std::min(lo_y, b.lo.y);
    hi_x = std::max(hi_x, b.hi.x);
    hi_y = std::max(hi_y, b.hi.y);
  }
  // About one box per cell on a square-ish grid.
  const double span = std::max({hi_x - lo_x, hi_y - lo_y, std::numeric_limits<double>::min()});
  const std::int64_t cells = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::sqrt(static_cast<double>(n))));
  const double cell = span / static_cast<double>(cells) * (1.0 + 1e-9);
  auto cell_of = [&](double v, double lo) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((v - lo) / cell), 0, cells - 1);
  };
  struct Range {
    std::int32_t x0, x1, y0, y1;
  };
  std::vector<Range> ranges(n);
  // Each box listed in every cell it covers, cell by cell, in box order (a
  // counting sort: two passes over the boxes). Cell k = x * cells + y holds
  // the boxes at [start[k], start[k + 1]) of `in`.
  const auto cell_count = static_cast<std::size_t>(cells * cells);
  std::vector<std::size_t> start(cell_count + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Box2& b = boxes[i];
    const Range r{static_cast<std::int32_t>(cell_of(b.lo.x, lo_x)), static_cast<std::int32_t>(cell_of(b.hi.x, lo_x)),
                  static_cast<std::int32_t>(cell_of(b.lo.y, lo_y)), static_cast<std::int32_t>(cell_of(b.hi.y, lo_y))};
    ranges[i] = r;
    for (std::int64_t x = r.x0; x <= r.x1; ++x)
      for (std::int64_t y = r.y0; y <= r.y1; ++y) ++start[static_cast<std::size_t>(x * cells + y) + 1];
  }
  for (std::size_t k = 0; k < cell_count; ++k) start[k + 1] += start[k];
  std::vector<std::uint32_t> in(start[cell_count]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      const Range& r = ranges[i];
      for (std::int64_t x = r.x0; x <= r.x1; ++x)
        for (std::int64_t y = r.y0; y <= r.y1; ++y)
          in[fill[static_cast<std::size_t>(x * cells + y)]++] = static_cast<std::uint32_t>(i);
    }
  }
  for (std::size_t k = 0; k < cell_count; ++k) {
    const auto cx = static_cast<std::int32_t>(static_cast<std::int64_t>(k) / cells);
    const auto cy = static_cast<std::int32_t>(static_cast<std::int64_t>(k) % cells);
    for (std::size_t p = start[k]; p < start[k + 1]; ++p) {
      for (std::size_t q = p + 1; q < start[k + 1]; ++q) {
        std::size_t i = in[p], j = in[q];
        if (i > j) std::swap(i, j);
        const Range &ri = ranges[i], &rj = ranges[j];
        // Visit each pair once: in the lowest cell both boxes cover.
        if (std::max(ri.x0, rj.x0) != cx || std::max(ri.y0, rj.y0) != cy) continue;
        const Box2 &bi = boxes[i], &bj = boxes[j];
        if (bi.hi.x < bj.lo.x || bj.hi.x < bi.lo.x || bi.hi.y < bj.lo.y || bj.hi.y < bi.lo.y) continue;
        if (!visit(i, j)) return;
      }
    }
  }
}

std::vector<std::pair<std::size_t, std::size_t>> intersecting_segment_pairs(const std::vector<Segment2>& segments,
                                                                            const std::vector<std::size_t>& next,
                                                                            std::size_t max_pairs, double within) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::vector<Box2> boxes;
  boxes.reserve(segments.size());
  const glm::dvec2 margin(within, within);
  for (const Segment2& s : segments) boxes.push_back({glm::min(s.a, s.b) - margin, glm::max(s.a, s.b) + margin});
  for_each_box_pair(boxes, [&](std::size_t i, std::size_t j) {
    const Segment2 &si = segments[i], &sj = segments[j];
    const bool i_then_j = !next.empty() && next[i] == j;
    const bool j_then_i = !next.empty() && next[j] == i;
    bool hit;
    if (i_then_j && j_then_i) {
      hit = consecutive_fold(si, sj, within) || consecutive_fold(sj, si, within);  // a two-edge loop
    } else if (i_then_j) {
      hit = consecutive_fold(si, sj, within);
    } else if (j_then_i) {
      hit = consecutive_fold(sj, si, within);
    } else {
      hit = segments_meet(si, sj, within);
    }
    if (hit) out.push_back({i, j});
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

}  // namespace procex

#include "core/geom/segment_intersections.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
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
  return orient2d(i.a, i.b, j.b) == 0 && glm::dot(i.b - i.a, j.b - j.a) < 0.0;
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

struct Box2 {
  glm::dvec2 lo, hi;
};

// A uniform grid of about one segment per cell, each segment listed in the
// cells its neighbourhood (within `within`) passes through, column by column:
// a long diagonal segment crosses a row of cells, where its box would cover a
// square of them, and the long thin spikes of a plan side by side would all
// share each other's cells.
class SegmentGrid {
 public:
  struct Rows {
    std::int64_t lo, hi;
  };

  SegmentGrid(const std::vector<Segment2>& segments, double within) : segments_(segments), within_(within) {
    double reach = 0.0;
    for (const Segment2& s : segments) {
      lo_ = glm::min(lo_, glm::min(s.a, s.b));
      hi_ = glm::max(hi_, glm::max(s.a, s.b));
      reach = std::max({reach, std::abs(s.a.x), std::abs(s.a.y), std::abs(s.b.x), std::abs(s.b.y)});
    }
    lo_ -= within;
    hi_ += within;
    const double span = std::max({hi_.x - lo_.x, hi_.y - lo_.y, std::numeric_limits<double>::min()});
    cells_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::sqrt(static_cast<double>(segments.size()))));
    cell_ = span / static_cast<double>(cells_) * (1.0 + 1e-9);
    // Rounding in clipping a segment to a column, far inside a cell; the
    // coordinates' own last places count when they lie far from the origin.
    slack_ = 1e-9 * span + 16.0 * std::numeric_limits<double>::epsilon() * reach;
    // Each segment's rows, column by column, worked out once: listing it and
    // telling whether a pair meets first in a cell both read them.
    first_column_.resize(segments.size());
    offset_.resize(segments.size() + 1, 0);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Rows columns = clipped_columns(i);
      first_column_[i] = columns.lo;
      for (std::int64_t x = columns.lo; x <= columns.hi; ++x) rows_.push_back(clipped_rows(i, x));
      offset_[i + 1] = rows_.size();
    }
  }

  std::int64_t cells() const { return cells_; }

  // The first and last column segment i's neighbourhood reaches.
  Rows columns(std::size_t i) const {
    return {first_column_[i], first_column_[i] + static_cast<std::int64_t>(offset_[i + 1] - offset_[i]) - 1};
  }

  // The rows segment i's neighbourhood passes through in column x, one of
  // its columns.
  Rows rows(std::size_t i, std::int64_t x) const {
    return rows_[offset_[i] + static_cast<std::size_t>(x - first_column_[i])];
  }

  // The lowest cell (x, y) both segments' lists hold, x-major, if any.
  std::optional<std::pair<std::int64_t, std::int64_t>> first_shared_cell(std::size_t i, std::size_t j) const {
    const Rows ci = columns(i), cj = columns(j);
    for (std::int64_t x = std::max(ci.lo, cj.lo); x <= std::min(ci.hi, cj.hi); ++x) {
      const Rows ri = rows(i, x), rj = rows(j, x);
      if (std::max(ri.lo, rj.lo) <= std::min(ri.hi, rj.hi)) return std::pair{x, std::max(ri.lo, rj.lo)};
    }
    return std::nullopt;
  }

 private:
  Rows clipped_columns(std::size_t i) const {
    const Segment2& s = segments_[i];
    return {cell_of(std::min(s.a.x, s.b.x) - within_ - slack_, lo_.x),
            cell_of(std::max(s.a.x, s.b.x) + within_ + slack_, lo_.x)};
  }

  // Segment i clipped to column x, widened by within and the slack.
  Rows clipped_rows(std::size_t i, std::int64_t x) const {
    const Segment2& s = segments_[i];
    const glm::dvec2 d = s.b - s.a;
    double t0 = 0.0, t1 = 1.0;
    if (d.x != 0.0) {
      const double left = lo_.x + static_cast<double>(x) * cell_ - within_ - slack_;
      const double right = lo_.x + static_cast<double>(x + 1) * cell_ + within_ + slack_;
      t0 = (left - s.a.x) / d.x;
      t1 = (right - s.a.x) / d.x;
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::clamp(t0, 0.0, 1.0);
      t1 = std::clamp(t1, 0.0, 1.0);
    }
    const double y0 = s.a.y + t0 * d.y, y1 = s.a.y + t1 * d.y;
    // The clipped ends are rounded: a further slack in y of the clipping's
    // error in t times the segment's rise.
    const double pad = within_ + slack_ + 1e-9 * std::abs(d.y);
    return {cell_of(std::min(y0, y1) - pad, lo_.y), cell_of(std::max(y0, y1) + pad, lo_.y)};
  }

  std::int64_t cell_of(double v, double lo) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((v - lo) / cell_)), 0, cells_ - 1);
  }

  const std::vector<Segment2>& segments_;
  double within_;
  glm::dvec2 lo_{std::numeric_limits<double>::infinity()}, hi_{-std::numeric_limits<double>::infinity()};
  std::int64_t cells_ = 1;
  double cell_ = 1.0, slack_ = 0.0;
  std::vector<std::int64_t> first_column_;
  std::vector<std::size_t> offset_;  // segment i's rows are rows_[offset_[i], offset_[i + 1])
  std::vector<Rows> rows_;
};

}  // namespace

void for_each_near_segment_pair(const std::vector<Segment2>& segments, double within,
                                const std::function<bool(std::size_t, std::size_t)>& visit) {
  const std::size_t n = segments.size();
  if (n < 2) return;
  const SegmentGrid grid(segments, within);
  const std::int64_t cells = grid.cells();
  // Each segment listed in every cell it passes, cell by cell, in segment
  // order (a counting sort: two passes over the segments). Cell k = x * cells
  // + y holds the segments at [start[k], start[k + 1]) of `in`.
  const auto cell_count = static_cast<std::size_t>(cells * cells);
  std::vector<std::size_t> start(cell_count + 1, 0);
  auto each_cell = [&](std::size_t i, auto&& f) {
    const SegmentGrid::Rows columns = grid.columns(i);
    for (std::int64_t x = columns.lo; x <= columns.hi; ++x) {
      const SegmentGrid::Rows rows = grid.rows(i, x);
      for (std::int64_t y = rows.lo; y <= rows.hi; ++y) f(static_cast<std::size_t>(x * cells + y));
    }
  };
  for (std::size_t i = 0; i < n; ++i) each_cell(i, [&](std::size_t k) { ++start[k + 1]; });
  for (std::size_t k = 0; k < cell_count; ++k) start[k + 1] += start[k];
  std::vector<std::uint32_t> in(start[cell_count]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) each_cell(i, [&](std::size_t k) { in[fill[k]++] = static_cast<std::uint32_t>(i); });
  }
  std::vector<Box2> boxes(n);
  for (std::size_t i = 0; i < n; ++i)
    boxes[i] = {glm::min(segments[i].a, segments[i].b) - within, glm::max(segments[i].a, segments[i].b) + within};
  for (std::size_t k = 0; k < cell_count; ++k) {
    const std::pair<std::int64_t, std::int64_t> here{static_cast<std::int64_t>(k) / cells, static_cast<std::int64_t>(k) % cells};
    for (std::size_t p = start[k]; p < start[k + 1]; ++p) {
      for (std::size_t q = p + 1; q < start[k + 1]; ++q) {
        std::size_t i = in[p], j = in[q];
        if (i > j) std::swap(i, j);
        const Box2 &bi = boxes[i], &bj = boxes[j];
        if (bi.hi.x < bj.lo.x || bj.hi.x < bi.lo.x || bi.hi.y < bj.lo.y || bj.hi.y < bi.lo.y) continue;
        // Visit each pair once: in the first cell both pass.
        if (grid.first_shared_cell(i, j) != here) continue;
        if (!visit(i, j)) return;
      }
    }
  }
}

std::vector<std::pair<std::size_t, std::size_t>> intersecting_segment_pairs(const std::vector<Segment2>& segments,
                                                                            const std::vector<std::size_t>& next,
                                                                            std::size_t max_pairs, double within) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for_each_near_segment_pair(segments, within, [&](std::size_t i, std::size_t j) {
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

#include "core/placement/repeat.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "core/placement/placement_error.h"
#include "core/geom/tolerances.h"

namespace procex {
namespace {

// Rule 3's rounding of q = usable / spacing to a count.
double rounded_count(double q, Repeat::Rounding rounding) {
  const double nearest = std::round(q);
  if (std::abs(q - nearest) <= kRepeatCountRelative * std::max(1.0, q)) return nearest;
  switch (rounding) {
    case Repeat::Rounding::Down:
      return std::floor(q);
    case Repeat::Rounding::Nearest:
      return std::floor(q + 0.5);
    case Repeat::Rounding::Up:
      return std::ceil(q);
  }
  return std::floor(q);
}

void check_size(double items) {
  // (Not as an integer: a tiny spacing gives more items than any integer holds.)
  if (!(items <= static_cast<double>(kMaxRepeatItems)))
    throw PlacementError("the repetition would place more than " + std::to_string(kMaxRepeatItems) +
                         " items: use a larger spacing or fewer items");
}

}  // namespace

std::vector<Slot> repeat_line(double length, const Repeat& r) {
  if (!std::isfinite(length) || !std::isfinite(r.margin_start) || !std::isfinite(r.margin_end))
    throw PlacementError("a repetition needs a finite length and margins");
  if (r.count < 0) throw PlacementError("a repetition count must not be negative, not " + std::to_string(r.count));
  if (r.count == 0 && !(r.spacing > 0.0 && std::isfinite(r.spacing)))
    throw PlacementError("a repetition needs a count > 0 or a finite spacing > 0 (spacing " + std::to_string(r.spacing) + ")");
  const double usable = length - r.margin_start - r.margin_end;
  std::vector<Slot> out;
  if (usable < 0.0) return out;
  const bool cells = r.layout == Repeat::Layout::Cells;
  if (usable == 0.0) {
    if (!cells) out.push_back({r.margin_start, 0.0});
    return out;
  }
  // The number of intervals (Cells: cells; Ends: gaps between items), the
  // pitch, and where the first item sits.
  double intervals = 0.0, pitch = 0.0, start = r.margin_start;
  if (r.count > 0) {
    check_size(r.count);
    intervals = cells ? r.count : r.count - 1;
    pitch = intervals > 0 ? usable / intervals : usable;
  } else {
    intervals = rounded_count(usable / r.spacing, r.rounding);
    check_size(intervals + 1);
    pitch = r.fill && intervals > 0 ? usable / intervals : r.spacing;
    if (!r.fill) start += (usable - intervals * pitch) / 2;  // the group centred
  }
  const auto n = static_cast<std::size_t>(intervals);
  if (cells) {
    for (std::size_t i = 0; i < n; ++i) out.push_back({start + (static_cast<double>(i) + 0.5) * pitch, pitch});
  } else if (n == 0) {
    out.push_back({r.margin_start + usable / 2, usable});
  } else {
    for (std::size_t i = 0; i <= n; ++i) out.push_back({start + static_cast<double>(i) * pitch, pitch});
  }
  return out;
}

namespace {

// Items along the line from a to b (a point per slot), with the axes of `axes`.
std::vector<Cell> row_on_line(const glm::dvec3& a, const glm::dvec3& b, const Frame& axes, const Repeat& columns) {
  const double length = glm::length(b - a);
  const glm::dvec3 dir = length > 0.0 ? (b - a) / length : axes.along;
  std::vector<Cell> out;
  int column = 0;
  for (const Slot& s : repeat_line(length, columns)) {
    Cell& c = out.emplace_back();
    c.frame = axes;
    c.frame.origin = a + s.position * dir;
    c.width = s.pitch;
    c.column = column++;
  }
  return out;
}

}  // namespace

std::vector<Cell> repeat_between(const Frame& first, const Frame& last, const Repeat& columns) {
  return row_on_line(first.origin, last.origin, first, columns);
}

std::vector<Cell> repeat_on_span(const ResolvedAnchor& anchor, const Repeat& columns) {
  if (!anchor.present) return {};
  const Frame& f = anchor.frame;
  const bool forward = glm::dot(anchor.span_to - anchor.span_from, f.along) >= 0.0;
  return row_on_line(forward ? anchor.span_from : anchor.span_to, forward ? anchor.span_to : anchor.span_from, f,
                     columns);
}

std::vector<Cell> repeat_grid(const ResolvedAnchor& anchor, double z_from, double z_to, const Repeat& columns,
                              const Repeat& rows) {
  const std::string name = "anchor '" + anchor.name + "' (edge " + std::to_string(anchor.edge_id) + ")";
  if (!std::isfinite(z_from) || !std::isfinite(z_to) || z_to < z_from)
    throw PlacementError("a grid on " + name + " needs finite heights with z_from <= z_to, not " +
                         std::to_string(z_from) + " and " + std::to_string(z_to));
  if (!anchor.present) return {};
  const Frame& f = anchor.frame;
  // Rows are laid out along `up`; heights become distances up the face.
  if (!(f.up.z > kFrameOrthonormality))
    throw PlacementError("a grid on " + name + " needs a face that rises (its frame's up " + vector_text(f.up) +
                         " is horizontal): rows between heights have no place on it");
  const double s_from = (z_from - f.origin.z) / f.up.z, s_to = (z_to - f.origin.z) / f.up.z;
  const std::vector<Slot> row_slots = repeat_line(s_to - s_from, rows);
  const std::vector<Cell> row = repeat_on_span(anchor, columns);
  if (row.size() * row_slots.size() > kMaxRepeatItems)
    throw PlacementError("a grid on " + name + " would place " + std::to_string(row.size() * row_slots.size()) +
                         " items, more than " + std::to_string(kMaxRepeatItems));
  std::vector<Cell> out;
  out.reserve(row.size() * row_slots.size());
  for (std::size_t r = 0; r < row_slots.size(); ++r) {
    for (const Cell& c : row) {
      Cell& g = out.emplace_back(c);
      g.frame.origin += (s_from + row_slots[r].position) * f.up;
      g.height = row_slots[r].pitch;
      g.row = static_cast<int>(r);
    }
  }
  return out;
}

}  // namespace procex

// Repetition (paper 3.6): N items, or one every d metres with the count
// following the facade's length, in a row along an edge, in a column up a
// face, or in a grid of both. Pure functions: they return where items go,
// and placing a mesh there is frame_transform.h's or stretch.h's job.
//
// Rules, in order:
// 1. The usable length is the line's length minus margin_start and
//    margin_end. A negative usable length places nothing (a facade too short
//    for its margins gets no windows; not an error).
// 2. Count mode (count > 0), Cells layout: the usable length is cut into
//    `count` equal cells, one item at each cell's centre. Ends layout: the
//    first item at the start, the last at the end, the rest evenly between
//    (one item: the middle).
// 3. Spacing mode (count == 0, spacing d > 0): q = usable / d, rounded to an
//    integer k by `rounding` (Down: floor, Nearest: halves round up, Up:
//    ceil), q within kRepeatCountRelative of an integer counting as that
//    integer. Cells: k cells; Ends: k intervals, so k + 1 items (k == 0: one
//    item in the middle). With `fill` the pitch becomes usable / k so the
//    items span the usable length (Down: pitch >= d, never closer than asked;
//    Up: pitch <= d); without it the pitch is exactly d and the group is
//    centred (with Up or Nearest it may then reach into the margins).
// 4. A usable length of exactly zero gives no Cells and one Ends item.
// Items are ordered from the line's start; the same input gives the same
// output, bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geom/anchor.h"

namespace procex {

// More items than this in one repetition is refused (a spacing of a
// millimetre on a long facade is a mistake, not a request).
inline constexpr std::size_t kMaxRepeatItems = 100000;

struct Repeat {
  enum class Layout : std::uint8_t { Cells, Ends };
  enum class Rounding : std::uint8_t { Down, Nearest, Up };
  int count = 0;          // > 0: exactly this many items
  double spacing = 0.0;   // when count == 0: the target pitch, metres
  Rounding rounding = Rounding::Down;
  bool fill = true;
  Layout layout = Layout::Cells;
  double margin_start = 0.0, margin_end = 0.0;  // metres kept free at each end
};

// One item on a line: its distance from the line's start and its pitch (the
// cell's width for Cells, the distance between neighbours for Ends; the
// usable length for a lone Ends item).
struct Slot {
  double position = 0.0;
  double pitch = 0.0;
};

// Throws PlacementError for a non-finite length or margin, a negative count,
// neither a count nor a positive spacing, or more than kMaxRepeatItems items.
std::vector<Slot> repeat_line(double length, const Repeat& repeat);

// An item on a face. The frame's origin is the item's position (for a grid,
// the centre of its cell), its axes the face's (anchor.h's Frame).
struct Cell {
  Frame frame;
  double width = 0.0;   // the column pitch
  double height = 0.0;  // the row pitch; 0 for a single row
  int column = 0, row = 0;
};

// A row between two frames on one edge: items on the line from first.origin
// to last.origin, all with first's axes.
std::vector<Cell> repeat_between(const Frame& first, const Frame& last, const Repeat& columns);

// A row across the anchor's span (the part of its edge's face at the
// anchor's height, ResolvedAnchor::span_from/span_to), ordered along the
// frame's `along`, with the anchor's axes. An absent anchor gives no items.
std::vector<Cell> repeat_on_span(const ResolvedAnchor& anchor, const Repeat& columns);

// A grid: the columns of repeat_on_span times rows up the face between the
// world heights z_from and z_to (measured along the frame's `up`, so on a
// sloping face the rows follow the slope). The columns do not narrow with
// height: on a sloping face, give each row its own anchor instead. Throws
// PlacementError if z_to < z_from or the face is horizontal.
std::vector<Cell> repeat_grid(const ResolvedAnchor& anchor, double z_from, double z_to, const Repeat& columns,
                              const Repeat& rows);

}  // namespace procex

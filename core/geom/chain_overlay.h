// The overlay of closed chains on a plane. A chain is a set of directed
// segments whose ends balance at every point (the boundary of a polygon with
// holes, counter-clockwise around what it covers). Chains come in groups;
// cut against each other at every crossing and every point lying on another
// segment, they divide the plane into cells, and every cell has a winding
// number per group and in total. Where chains fold over each other (a
// flattened soffit over a flattened ledge) their windings cancel, and the
// cells of non-zero winding are what is left: simple, meeting vertex to
// vertex, each given to one group that covers it.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

struct OverlaySegment {
  std::uint32_t from, to;  // indices into the points
  int group;               // the chain it belongs to; negative: it cuts and is cut, but covers nothing
};

struct OverlayCell {
  std::vector<std::uint32_t> loop;  // one boundary cycle, the cell on its left
  int winding = 0;                  // the cell's total winding number
  int owner = -1;                   // the lowest group whose own winding there is `winding`'s sign
};

struct ChainOverlay {
  std::vector<glm::dvec2> points;  // the input points, then the crossings found
  // Per input segment, the points along it in order, from its `from` to its `to`.
  std::vector<std::vector<std::uint32_t>> pieces;
  // Every boundary cycle of every cell of non-zero winding (a cell with holes
  // has one cycle for its outline and one per hole).
  std::vector<OverlayCell> cells;
};

// Points closer than `near` are one point: a point within `near` of a
// segment cuts it there, and crossings within `near` of a point meet there.
ChainOverlay overlay_chains(std::vector<glm::dvec2> points, const std::vector<OverlaySegment>& segments,
                            double near);

}  // namespace procex

// One call behind a "Mesh placement" node: a mesh placed at the resolutions
// of a named anchor (one per footprint edge it resolved on), once each, in a
// row or a grid on each resolution's face, or stretched between two anchors
// on the same edge (a pillar from a ground anchor to an eave anchor). Absent
// resolutions are reported, not errors (issue 4: the feature is simply not
// there, as when a dormer's roof edge has vanished at its height).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/anchor.h"
#include "core/placement/cut_openings.h"
#include "core/placement/facade_split.h"
#include "core/placement/placement.h"
#include "core/placement/repeat.h"

namespace procex {

struct MeshPlacementSpec {
  enum class Mode : std::uint8_t { Single, Row, Grid, Stretch, Tiles };
  Mode mode = Mode::Single;
  std::string anchor;      // ResolvedAnchor::name; for Stretch, where the mesh's bottom (y lo) goes
  std::string top_anchor;  // Stretch: the anchor its top (y hi) follows, on the same edge
  // Fractions of the mesh's bounds (Box3::at) put on each frame's origin; by
  // default the middle of its bottom back edge: a window stands on its anchor.
  // A grid cell's origin is its centre, so (0.5, 0.5, 0) centres a mesh in
  // it. Stretch uses the x and z fractions only.
  glm::dvec3 pivot{0.5, 0.0, 0.0};
  glm::dvec3 scale{1.0};   // Single, and Row / Grid without fit
  glm::dvec3 offset{0.0};  // metres along, up and out of the face, applied last in every mode
  Repeat columns;          // Row and Grid: along each resolution's span
  Repeat rows;             // Grid: up the face from z_from to z_to (world heights)
  double z_from = 0.0, z_to = 0.0;
  bool z_to_top = false;   // Grid: the rows end at the top of the anchor's face instead (needs place_mesh's cover)
  bool fit = false;        // Row, Grid and Tiles: fill each cell (less margin) instead of pivot and scale
  double margin = 0.0;
  std::string tag;         // Instance::tag
  int floor_from = 0, floor_to = 1 << 30;  // Tiles: the floors placed in
};

struct PlaceMeshReport {
  std::size_t instances = 0;
  std::vector<std::string> absent;  // one line per resolution that placed nothing, with the reason
  std::size_t dropped = 0;          // Row and Grid items not wholly on their face (see `cover`)
  // Per instance placed, in order: its mesh's bounds seen along its frame's
  // normal (the anchor's, or the tile's), the opening it would cut.
  std::vector<Opening> outlines;
};

class FaceCover;

// Adds the mesh (once) and its instances to `result`; each instance's source
// edge is its anchor's edge. With `cover` (the faces of the building the
// anchors were resolved on), a Row or Grid item whose mesh's bounds, seen
// along the face's normal, do not lie wholly on the anchor's face is dropped
// and counted: no window above the roof line, across a set-back or past a
// corner. Stretch items are not: they span their own two anchors, and often
// stand free of the face on purpose (a pillar under a jetty, moved out). Throws PlacementError, leaving `result` as it
// was, if no resolution carries the anchor's name (the message lists the
// names there are), or for a bad spec (repetition, fit or frame errors,
// naming the anchor and edge).
PlaceMeshReport place_mesh(PlacementResult& result, const PlaceableMesh& mesh,
                           const std::vector<ResolvedAnchor>& anchors, const MeshPlacementSpec& spec,
                           const FaceCover* cover = nullptr);

// Tiles mode: the mesh in every facade tile named spec.anchor on a floor from
// spec.floor_from to spec.floor_to, fitted to the tile (less spec.margin) or
// put at spec.pivot on its bottom centre, scaled; then offset. Tiles are on
// their faces already (split_facades), so none is dropped. Throws
// PlacementError for a bad fit.
PlaceMeshReport place_in_tiles(PlacementResult& result, const PlaceableMesh& mesh, const std::vector<FacadeTile>& tiles,
                               const MeshPlacementSpec& spec);

}  // namespace procex

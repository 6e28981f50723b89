// Plan edits (paper 3.5, 4.6, fig. 6, 20, 21): at an anchor, new edges are
// inserted into the sweep's cross-section, each following its own profile, so
// a chimney rises through a roof, a dormer grows out of it, a bay window or a
// buttress stands out of a wall. The edit is placed by an anchor, so it stays
// where it belongs when the footprint or the profiles change.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/anchor.h"
#include "core/geom/footprint.h"

namespace procex {

struct PlanEdit {
  enum class Kind : std::uint8_t {
    // An arbitrary polyline replaces part of the edge. Nothing keeps it from
    // crossing the rest of the cross-section: the mesh's validation reports it.
    Forced,
    // A protrusion grown from a vanishingly small one by a nested sweep
    // (fig. 21): where it runs into other parts of the cross-section the nested
    // sweep resolves the collision, so the result stays a manifold.
    Natural,
  };
  std::string name;
  // Where and when: the anchor's plan position on each edge it selects, at its
  // height. Selection by profile and edge ids as for anchors (footprint edges only).
  Anchor at;
  Kind kind = Kind::Forced;
  // Forced: the polyline in the anchor's frame at that height, x along the
  // edge from the anchor, y outward from the face (negative: into the
  // building). It starts and ends on the edge (y = 0), the end further along
  // than the start; the part of the edge between them is replaced.
  std::vector<glm::dvec2> shape;
  // Natural: a protrusion `width` wide centred on the anchor, grown `depth`
  // outward (negative: a recess into the building), each side moving out by
  // `spread` on the way (positive: wider at the front).
  double width = 0.0;
  double depth = 0.0;
  double spread = 0.0;
  // Moves the step along the edge from the anchor (metres): copies of one
  // edit side by side (a row of dormers) share their anchor.
  double offset = 0.0;
  // The inserted edges in order along the step (forced: one per shape
  // segment; natural: first side, front, second side). Their profiles (indices
  // into Footprint::profiles) start at the edit's height; their ids name their
  // faces in the output.
  std::vector<EdgeSpec> edges;
  // Tag of the horizontal faces the edit makes at its height (the floor of a
  // bay window, the sill of a recess).
  std::string tag = "step";

  bool operator==(const PlanEdit&) const = default;
};

}  // namespace procex

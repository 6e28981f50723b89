// The sweep's output before it becomes an OpenMesh mesh: shared vertices and
// planar faces, each face a list of loops (first the outer boundary, then any
// holes), each naming where it came from.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/anchor.h"

namespace procex {

enum class FaceKind : std::uint8_t {
  Base,  // the footprint itself, facing down
  Side,  // a wall or roof face swept by one footprint edge
  Cap,   // a horizontal face closing the sweep at its maximum height, facing up
};

struct SurfaceFace {
  FaceKind kind = FaceKind::Side;
  std::int32_t source_edge = -1;  // EdgeSpec::id for Side faces, -1 otherwise
  // loops[0] is the outer boundary, counter-clockwise seen from outside the
  // solid (so the right-hand normal points out); loops[1..] are holes, clockwise.
  std::vector<std::vector<std::uint32_t>> loops;
  std::string tag;  // the profile segment's tag ("wall", "roof", ...), may be empty
};

struct Surface {
  std::vector<glm::dvec3> vertices;
  std::vector<SurfaceFace> faces;
  std::vector<ResolvedAnchor> anchors;  // one per anchor and selected edge, in order
  // One per plan edit and selected edge, in order: the anchor frame where the
  // edit was inserted, or absent with the reason (edge gone, no room on it).
  std::vector<ResolvedAnchor> plan_edits;
  // Where rounding defeats one clustering scale the sweep runs again at the
  // next (engine::Tolerances::retry_relative): the scale it closed at,
  // relative to the footprint's extent, and how many it tried before.
  double tolerance_relative = 0.0;
  int retries = 0;
};

}  // namespace procex

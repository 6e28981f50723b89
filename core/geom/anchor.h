// Anchors (paper 3.4, 4.2, fig. 29): a point on a footprint edge (the plan
// anchor) paired with a point on a profile (the profile anchor, a height). The
// sweep resolves an anchor when it reaches that height: if the edge still
// exists there, the anchor becomes a position and a frame on the edge's face;
// otherwise it is absent. Features placed at anchors follow the footprint and
// the profiles when either changes (the persistence problem).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace procex {

struct PlanAnchor {
  enum class Mode : std::uint8_t {
    Fraction,   // value in [0, 1]: that fraction of the edge's length at the anchor's height
    FromStart,  // value metres from the footprint edge's start, carried up its face
    FromEnd,    // value metres back from the footprint edge's end, carried up its face
  };
  Mode mode = Mode::Fraction;
  double value = 0.5;

  bool operator==(const PlanAnchor&) const = default;
};

struct Anchor {
  std::string name;
  PlanAnchor plan;
  double height = 0.0;  // the profile anchor: where on the profile, as a height
  // Which edges carry the anchor: every edge using profile `profile` (an index
  // into Footprint::profiles; -1: every edge), narrowed to `edges` (EdgeSpec
  // ids) when that is not empty. One anchor resolves once per selected edge.
  int profile = -1;
  std::vector<std::int32_t> edges;

  bool operator==(const Anchor&) const = default;
};

// Where a feature sits: origin on the face, `along` the edge direction at that
// height, `normal` the face's outward normal, `up` in the face, perpendicular to
// `along` and pointing up the slope (world up on a vertical wall). Right-handed:
// cross(along, up) == normal.
struct Frame {
  glm::dvec3 origin{0.0};
  glm::dvec3 along{1.0, 0.0, 0.0};
  glm::dvec3 up{0.0, 0.0, 1.0};
  glm::dvec3 normal{0.0, -1.0, 0.0};
};

// Why an anchor or a plan edit is absent: a closed set, so reports and tests
// count and check absences by kind (`reason` says it in words, with numbers).
enum class Absence : std::uint8_t {
  None,        // present
  AboveSweep,  // the sweep (the roof) ends below its height
  EdgeGone,    // its edge no longer exists at its height
  OffEdge,     // its point lies beyond the ends of the edge there
  NoRoom,      // a plan edit's step reaches past the end of the face it is on
  TooShort,    // a segment of a plan edit's shape is below the sweep's resolution
  Crossing,    // a plan edit's shape crosses the outline or itself
  Unselected,  // its selection names no edge of this footprint
};

struct ResolvedAnchor {
  std::string name;           // Anchor::name
  std::size_t anchor = 0;     // index into the anchors the sweep was given
  std::int32_t edge_id = -1;  // the footprint edge (EdgeSpec::id) it resolved on
  bool present = false;       // false: the edge no longer exists there (see `reason`)
  Absence absence = Absence::None;  // why it is absent, by kind
  std::string reason;         // why it is absent, for reports
  Frame frame;                // valid when present
  // The part of the edge's face at the anchor's height that contains the
  // anchor (its ends on the sweep plane), so repetitions can adapt to the
  // facade's length there. Valid when present.
  glm::dvec3 span_from{0.0}, span_to{0.0};
};

}  // namespace procex

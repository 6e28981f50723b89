// Labels of footprint edges for assigning profiles by example (paper 3.7):
// length (short / medium / long), orientation to the street (street / side /
// back), the compass angle of the outward normal, and whether the edge bounds
// a hole, and whether it is a party wall (shared with a neighbouring
// footprint).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/geom/footprint.h"

namespace procex {

enum class LengthClass { Short, Medium, Long };
enum class Orientation { Street, Side, Back };

struct EdgeLabels {
  std::size_t loop = 0, edge = 0;  // position in the footprint
  std::int32_t id = -1;            // EdgeSpec::id
  double length = 0;
  LengthClass length_class = LengthClass::Medium;
  Orientation orientation = Orientation::Side;
  double normal_deg = 0;  // outward normal, degrees counter-clockwise from +x, in [0, 360)
  bool inner = false;     // bounds a hole (odd nesting depth)
  bool party = false;     // its id is in LabelOptions::party
};

struct LabelOptions {
  double short_below = 4.0;  // metres
  double long_above = 12.0;  // metres
  // Direction from the building towards the street, degrees counter-clockwise
  // from +x; nullopt: the outward normal of the longest outer edge that is
  // not a party wall (a lot's longest edge is often the one it shares).
  std::optional<double> street_deg;
  // Ids of the edges shared with neighbouring footprints (core/geom/party_walls.h).
  std::vector<std::int32_t> party;
  // Ids of the edges that face a street line (core/geom/street_edges.h). When
  // there are any, they are the street edges, and the others side or back
  // against the longest one's outward normal (unless street_deg says).
  std::vector<std::int32_t> street;
};

// One entry per edge, loops in order. Outward normals follow the nesting
// (a hole's edges face into the hole), whatever the loops' orientation.
std::vector<EdgeLabels> label_edges(const Footprint& footprint, const LabelOptions& options);

}  // namespace procex

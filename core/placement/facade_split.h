// A facade divided into floors and bays (issue 15, CGA's split): the vertical
// faces of each footprint edge, plane by plane (a set-back's upper wall is a
// plane of its own), cut into floors counted up from one world height and, on
// each floor, into bays across the plane's width. Each tile keeps its frame
// on the face (its bottom centre, the face's axes), its size, floor and bay,
// for Mesh Placement; a tile is kept only where the faces cover it wholly
// (FaceCover), so none floats above the roof line, across a set-back or past
// a corner.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/geom/anchor.h"
#include "core/mesh/mesh.h"
#include "core/placement/split.h"

namespace procex {

struct FacadeTile {
  std::string name;          // FacadeSplitSpec::name: what Mesh Placement asks for
  std::int32_t edge_id = -1;  // the footprint edge whose face it is on
  Frame frame;               // origin: the tile's bottom centre; the face's axes
  double width = 0.0, height = 0.0;
  std::int32_t floor = 0, bay = 0;  // from z_from up, from the plane's start along the edge
};

struct FacadeSplitSpec {
  std::string name = "tile";
  SplitSpec floors;  // up from z_from
  SplitSpec bays;    // across each plane, from its start along the edge's direction
  double z_from = 0.0;
};

struct FacadeTiles {
  std::vector<FacadeTile> tiles;  // by plane, floor, bay
  std::size_t dropped = 0;        // tiles within a plane's bounds that its faces do not cover
};

// Splits the faces `wall` accepts (vertical ones only; others are skipped).
// Throws PlacementError for a split of too many cells.
FacadeTiles split_facades(const Mesh& mesh, const std::function<bool(Mesh::FaceHandle)>& wall, const FacadeSplitSpec& spec);

}  // namespace procex

// Every epsilon procex uses, named, in one place. Lengths are relative to a
// length scale (a footprint's or a mesh's bounding-box diagonal), so a
// footprint in millimetres and one in kilometres behave the same.
#pragma once

#include "core/geom/footprint.h"

namespace procex {

// Consecutive footprint vertices closer than this * length_scale() are merged
// into one (the shorter edge between them is dropped, with a note).
inline constexpr double kVertexMergeRelative = 1e-9;

// A loop whose |signed area| is below this * length_scale()^2 is degenerate.
inline constexpr double kLoopAreaRelative = 1e-18;

// Polygon triangulation (mesh faces with holes, validation): a vertex is
// straight when |sin(turn angle)| is below this.
inline constexpr double kStraightTurnSine = 1e-12;

// Mesh validation: distance tolerance (planarity, intersections) relative to
// the mesh's bounding-box diagonal when ValidationOptions::tolerance <= 0.
// Larger than the sweep's clustering tolerances, which move vertices off the
// exact plane intersections by up to their own size.
inline constexpr double kMeshDistanceRelative = 1e-7;

// The characteristic length of a footprint: the diagonal of the bounding box
// of its finite points (0 if it has none).
double length_scale(const Footprint& footprint);

// The distance below which two footprint points count as the same point:
// kVertexMergeRelative * length_scale, but never below a few ulps of the
// largest coordinate (a small footprint far from the origin).
double merge_distance(const Footprint& footprint);

}  // namespace procex

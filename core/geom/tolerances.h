// Every epsilon procex uses, named, in one place. Lengths are relative to a
// length scale (a footprint's or a mesh's bounding-box diagonal), so a
// footprint in millimetres and one in kilometres behave the same.
#pragma once

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

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

// Faces of a solid leaving one edge at angles (radians) closer than this
// leave it the same way: they overlap there (core/geom/round_edge.h).
inline constexpr double kSameWayAngle = 1e-9;

// Mesh validation: distance tolerance (planarity, intersections) relative to
// the mesh's bounding-box diagonal when ValidationOptions::tolerance <= 0.
// Ten times the sweep's clustering tolerances: a cluster's vertex is the best
// fit of planes that meet only to within those, and a fast corner carries
// that offset along. At the first scale, 1e-8, fits are off by more than
// ten times that (three of the 6,000 buildings of
// data/synthetic/d_city_6000.json, by up to 2e-7), so no roof is held closer
// than this.
inline constexpr double kMeshDistanceRelative = 1e-6;

// What a roof the sweep made at clustering scale `made_relative`
// (Surface::tolerance_relative; a retry's is up to 1e-5) is held to, by the
// same rule: events that far apart were one, and its faces are their planes
// only to within that (a 2,226-vertex jittered star closed at 1e-5 with faces
// 2.7 mm off their edges' planes, 1.35 times its clustering distance).
inline double mesh_distance_relative(double made_relative) {
  return std::max(kMeshDistanceRelative, 10.0 * made_relative);
}

// The sweep engine's tolerances. Distances scale with the input's extent.
struct SweepTolerances {
  double scale = 1.0;       // characteristic length of the input (bounding-box extent)
  double relative = 1e-7;   // the clustering distances below, relative to scale
  // How far rounding may have moved one point of the plan from another where
  // it stands (before the local frame): two ulps of its coordinates' magnitude.
  double rounding = 0.0;

  // Where rounding makes a sweep fail at the default clustering distance, it
  // runs again with these, in order (a near-coincidence at one scale is
  // usually clear at another); the output is checked closed, and each face
  // simple, each time. The last is the finest, a last resort: where thousands
  // of corners racing at up to 2,300 m per m of rise converge on one point (a
  // jittered star's centre), their events lie micrometres apart, and every
  // scale from 1e-8 up joins events there that are not one (in large_stars
  // seed 1, 13 collisions over 27 micrometres whose planes miss their fitted
  // point by 2.4 delta3, and a loop turns inside out). Tried last, it changes
  // no roof that closes at the others.
  static constexpr double retry_relative[] = {1e-8, 1e-7, 1e-6, 1e-5, 1e-10};
  // The coarsest of them, at which rounding is taken to be beaten.
  static constexpr double coarsest_relative = *std::max_element(std::begin(retry_relative), std::end(retry_relative));

  // Paper delta2: events whose heights differ by less than this form one cluster.
  double height() const { return relative * scale; }
  // Heights closer than this differ only by rounding (the first scale's
  // delta2, or the scale's own where it is finer): events there are one
  // instant, whatever their order.
  double simultaneous() const { return std::min(relative, retry_relative[0]) * scale; }
  // Paper delta3: events within this plan distance at one height are one point.
  double position() const { return relative * scale; }
  // How far off its neighbours' line a corner may lie and still be one drawn
  // straight (rounding's, with a margin of 32). Bent by more, the lines of
  // edges of different slopes cross there, and their corner runs along them
  // one way, which the weighted skeleton follows; bent by less, it has no way
  // and the volume rule picks a slope (paper 4.5).
  double straight() const { return 32.0 * rounding; }
  // Paper delta1: how far a collision may lie outside an edge's span and still hit it.
  double span_margin() const { return relative * scale; }
  // How far rounding may have put a meeting of planes of this conditioning
  // (engine::meeting_condition) from where the plan as drawn has it: each of
  // its lines carries about an ulp of the extent. Events that close to each
  // other may be one, whatever order rounding put them in: a batch and a
  // cluster take them in where this passes delta2 and delta3. Never past the
  // coarsest clustering distance, at which rounding is taken to be beaten.
  // None where the planes do not meet in one point (three walls of the
  // nested sweep of a step): the corners' own rules place such an event.
  double meeting_slack(double condition) const {
    if (!(condition < HUGE_VAL)) return 0.0;
    return std::min(std::numeric_limits<double>::epsilon() * scale * condition, most_meeting_slack());
  }
  // What meeting_slack gives at the most, whatever the planes: events further
  // apart than this and delta3 are apart without working their slack out.
  double most_meeting_slack() const { return coarsest_relative * scale; }
  // Beyond this height the sweep is considered to run away (no closing event).
  double runaway_height() const { return 1e7 * scale; }

  // Dimensionless: sine of the angle below which two edge directions are parallel.
  static constexpr double parallel_sin = 1e-10;
  // Dimensionless: slopes (tan of the angle) closer than this make coplanar faces.
  static constexpr double same_slope = 1e-9;
  // Radians: rays leaving a collision this close in angle may be taken in either
  // order (the sliver between them has no width worth keeping).
  static constexpr double sliver_angle = 1e-4;
  // Dimensionless: a corner moving faster than this (plan distance per unit of
  // height, relative to its planes' slopes) has no usable direction.
  static constexpr double max_speed = 1e6;
  // Angles within 90 degrees by less than this are treated as horizontal.
  static constexpr double max_slope = 1e6;
};

// Roof overhangs (core/mesh/roof_overhang.h).

// Points of the slab closer than this * the roof's extent are one vertex: the
// roof's planes are fitted to a sweep's faces, which meet only to within its
// clustering distance (SweepTolerances::relative), so three planes through
// one corner of it may meet a little apart.
inline constexpr double kRoofWeldRelative = 1e-7;

// A roof face whose unit normal rises less than this is refused: it is a wall
// (or faces down), and running it past the walls would run it sideways.
inline constexpr double kRoofLeastUpward = 1e-3;

// Mesh placement (core/placement).

// A frame's axes must be unit and perpendicular to within this (dimensionless):
// frames come from the sweep already orthonormal, so this only catches
// hand-made or corrupted frames.
inline constexpr double kFrameOrthonormality = 1e-6;

// A transform whose |det| of its 3x3 part is below this * scale^3 (scale: its
// largest column) collapses a mesh to a plane.
inline constexpr double kSingularDeterminantRelative = 1e-12;

// Repetition counts: length / spacing within this (relative) of an integer
// counts as that integer, so 10 m at 2.5 m gives 4 cells whatever the rounding.
inline constexpr double kRepeatCountRelative = 1e-9;

// A node matrix is written as one glTF matrix when its columns are orthogonal
// to within this (cosine of their angle); otherwise it is split into TRS nodes.
// The file holds matrices in float32, whose rounding leaves orthogonal
// columns at cosines up to about 4e-7 (3 products of 2^-24 errors each way).
inline constexpr double kTrsColumnCosine = 1e-6;

// The characteristic length of a footprint: the diagonal of the bounding box
// of its finite points (0 if it has none).
double length_scale(const Footprint& footprint);

// A few ulps of the footprint's largest coordinate: points closer than this
// may differ only by the rounding of their coordinates.
double rounding_distance(const Footprint& footprint);

// The distance below which two footprint points count as the same point:
// kVertexMergeRelative * length_scale, but never below a few ulps of the
// largest coordinate (a small footprint far from the origin).
double merge_distance(const Footprint& footprint);

}  // namespace procex

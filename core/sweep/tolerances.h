// Every epsilon the sweep uses, in one place. Distances scale with the input's
// size, so a footprint in millimetres or in kilometres behaves the same.
#pragma once

namespace procex::engine {

struct Tolerances {
  double scale = 1.0;  // characteristic length of the input (bounding-box extent)

  // Paper delta2: events whose heights differ by less than this form one cluster.
  double height() const { return 1e-7 * scale; }
  // Paper delta3: events within this plan distance at one height are one point.
  double position() const { return 1e-7 * scale; }
  // Paper delta1: how far a collision may lie outside an edge's span and still hit it.
  double span_margin() const { return 1e-7 * scale; }
  // Two corners closer than this at the same height are the same output vertex.
  double vertex_merge() const { return 1e-9 * scale; }
  // Beyond this height the sweep is considered to run away (no closing event).
  double runaway_height() const { return 1e7 * scale; }

  // Dimensionless: sine of the angle below which two edge directions are parallel.
  static constexpr double parallel_sin = 1e-10;
  // Radians: rays leaving a collision this close in angle may be taken in either
  // order (the sliver between them has no width worth keeping).
  static constexpr double sliver_angle = 1e-4;
  // Dimensionless: a corner moving faster than this (plan distance per unit of
  // height, relative to its planes' slopes) has no usable direction.
  static constexpr double max_speed = 1e6;
  // Dimensionless: slopes (tan of the angle) closer than this make coplanar faces.
  static constexpr double same_slope = 1e-9;
  // Angles within 90 degrees by less than this are treated as horizontal.
  static constexpr double max_slope = 1e6;
};

}  // namespace procex::engine

// Property checks on a swept roof that do not use the engine's code: each
// recomputes what the roof must be from the footprint alone (edge lines,
// angles, profiles) and compares it with the Surface. Every check returns one
// line per problem (at most a few of each kind); empty means it holds.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/footprint.h"
#include "core/mesh/surface.h"
#include "core/sweep/sweep.h"
#include "tests/support/generators/plan_transform.h"

namespace procex::testing {

// The length of the footprint's bounding-box diagonal.
double plan_diagonal(const Footprint& footprint);

// Positions agree within this: the mesh validator's tolerance for a roof made
// at clustering scale `made_relative` (Surface::tolerance_relative; 0: the
// first scale or finer), of the footprint's bounding-box diagonal, plus the rounding of its
// largest coordinate.
double roof_tolerance(const Footprint& footprint, double made_relative = 0.0);
// The same for `roof`, made at its own scale, of the plan extent of the
// footprint and the roof together: a wall leaning out under a high cap
// carries the roof beyond its plan (a spike leaning out, 0.00015 rad wide,
// reached 35 km from a 100 m plan at 9.7 m,
// generated_random_polygons_walls_5943), and what meets out there is known
// to that extent's digits. Not its height: a roof capped far above its
// last event to show it has a top is known to its plan's.
double roof_tolerance(const Footprint& footprint, const Surface& roof);

// build_mesh + validate: closed, 2-manifold, oriented, planar faces, no
// self-intersection, every pair of triangles searched even where the
// validator proves them apart (height_field.h); a crossing the proof covered
// is named too.
std::vector<std::string> check_valid_mesh(const Surface& surface);

// Every face with a footprint edge's id lies on a plane of that edge: the
// plane through the edge leaning at its angle, or one of its profile's
// segments (the last one extended). Caps lie at max_height, the base at 0.
// Edges that run straight on from each other with different angles share the
// angle the options' ambiguity rule picks (paper 4.5), here and below.
std::vector<std::string> check_faces_on_planes(const Footprint& footprint, const SweepOptions& options,
                                               const Surface& surface, double tol);

// For roofs whose every edge leans inward (0 < angle < 90, no profiles, no
// plan edits): the faces seen from above tile the footprint exactly once (no
// face faces down, projected areas sum to the footprint's within 1e-9
// relative plus coordinate rounding), and at sampled points the roof height
// is that of the source edge's plane; on a convex footprint it is the lower
// envelope of all planes, and with one angle everywhere it is at most the
// distance to the boundary over tan(angle) (the wavefront at time t keeps at
// least t from the footprint's edges). `seed` picks the sample points.
std::vector<std::string> check_inward_roof(const Footprint& footprint, const SweepOptions& options,
                                           const Surface& surface, double tol, unsigned seed);

// The largest difference in height between two roofs over the same plan, at
// `samples` points drawn (by `seed`) over the first's bounding box where both
// have a face that is not vertical above the point; NaN if no point was
// covered by both.
double largest_height_difference(const Surface& a, const Surface& b, int samples, unsigned seed);

// The same for roof a of `footprint` and roof b of a neighbour of it (its
// vertices moved), each difference divided by the lever of its point: moving
// an edge's ends by up to d moves its line by up to max(1, 2|t| / l) d at a
// point t along the edge from its middle (l the edge's length), so a face
// wider than its edge moves more on its far parts. At a point, the larger
// lever of the two faces over it.
double largest_levered_height_difference(const Footprint& footprint, const Surface& a, const Surface& b, int samples,
                                         unsigned seed);

// The enclosed volume by the divergence theorem over the surface's faces.
double surface_volume(const Surface& surface);

// The volume under a roof whose cross-section at height h has area
// a0 + a1 h + a2 h^2 up to h_end (a rectangle's or a regular polygon's
// offsets before they vanish): the integral of the offset areas.
double volume_of_offset_areas(double a0, double a1, double a2, double h_end);

// The footprint transformed; a mirror reverses every loop, each edge keeping
// its spec, so loops keep their orientation and edges their ids.
Footprint transformed(const Footprint& footprint, const PlanTransform& t);

// The roof of the transformed input against the transformed roof: every
// vertex of each within tol of one of the other, and the same total face
// area per source edge; or, where seams between coplanar faces moved, the
// same height everywhere (within 4 tol per unit of the steepest slope).
std::vector<std::string> compare_transformed(const Surface& original, const PlanTransform& t,
                                             const Surface& of_transformed, double tol);

}  // namespace procex::testing

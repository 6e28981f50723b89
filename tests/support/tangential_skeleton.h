// The straight skeleton of a tangential polygon in closed form: where every
// edge's line is at one distance r from a centre inside the polygon (a
// regular polygon, a star of alternating radii), the edges' lines moved in
// by t are tangent to the circle of radius r - t, so the wavefront is the
// polygon scaled about the centre by (r - t) / r. Nothing happens until every
// edge vanishes at once: one node, at the centre at time r, reached from
// every corner by its bisector. CGAL takes minutes and gigabytes for such a
// plan of thousands of vertices, every event at that one point (the size
// class, TESTING.md); this is the same skeleton, exactly.
#pragma once

#include <optional>

#include "core/geom/footprint.h"
#include "tests/support/cgal_skeleton.h"

namespace procex::testing {

// The skeleton of `footprint`, in the oracle's terms (nodes as (x, y, time),
// ridges, faces per edge), if it is one loop whose edges' lines are all at
// one distance from the mean of its vertices, within 1e-9 of its diagonal;
// else none.
std::optional<CgalSkeleton> tangential_skeleton(const Footprint& footprint);

}  // namespace procex::testing

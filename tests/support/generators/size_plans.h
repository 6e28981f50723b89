// Class (c) of issue 12: many vertices. Stars (alternating radii), regular
// polygons and random star-shaped polygons (random points sorted by angle
// about the centre, at random radii: about half their corners reflex), and
// jittered stars: each radius moved by up to a millimetre, so that thousands
// of events fall within a few jitters of one height rather than exactly at it.
// And random simple polygons that are not star-shaped: random points joined
// in the order of a space-filling curve, their crossings undone by 2-opt.
#pragma once

#include <random>

#include "tests/support/generators/grid_plans.h"

namespace procex::testing {

NamedPlan regular_polygon(std::size_t n, double radius);
NamedPlan star(std::size_t n, double outer, double inner);
NamedPlan jittered_star(std::size_t n, double outer, double inner, double jitter, std::mt19937_64& rng);
NamedPlan random_star_shaped(std::size_t n, double radius, std::mt19937_64& rng);
// n points drawn evenly over a square of side `size`, joined in the order of
// a Hilbert curve through it, then while two edges cross the path between
// them is reversed (2-opt: each reversal shortens the loop, so it ends): a
// simple polygon winding through the square with pockets inside pockets,
// about half its corners reflex, which no point sees whole.
NamedPlan random_simple_polygon(std::size_t n, double size, std::mt19937_64& rng);

}  // namespace procex::testing

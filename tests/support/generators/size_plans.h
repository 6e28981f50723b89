// Class (c) of issue 12: many vertices. Stars (alternating radii), regular
// polygons and random star-shaped polygons (random points sorted by angle
// about the centre, at random radii: about half their corners reflex), and
// jittered stars: each radius moved by up to a millimetre, so that thousands
// of events fall within a few jitters of one height rather than exactly at it.
#pragma once

#include <random>

#include "tests/support/generators/grid_plans.h"

namespace procex::testing {

NamedPlan regular_polygon(std::size_t n, double radius);
NamedPlan star(std::size_t n, double outer, double inner);
NamedPlan jittered_star(std::size_t n, double outer, double inner, double jitter, std::mt19937_64& rng);
NamedPlan random_star_shaped(std::size_t n, double radius, std::mt19937_64& rng);

}  // namespace procex::testing

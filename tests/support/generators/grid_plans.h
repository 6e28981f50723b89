// Class (a) of issue 12: plans snapped to an integer grid, where events
// coincide exactly: random polyomino outlines (with holes), letter plans whose
// wing widths come from a small set so that widths coincide, and either with
// extra vertices along their edges.
#pragma once

#include <random>
#include <string>

#include "tests/support/generators/plan_transform.h"

namespace procex::testing {

struct NamedPlan {
  std::string name;  // what it is, for messages ("polyomino of 37 cells", "H 4/8 x 16")
  Plan loops;        // outer loops counter-clockwise, holes clockwise
};

// The outline of a random 4-connected set of grid cells, 4 to max_vertices
// vertices; enclosed empty cells make holes. Cells touching only at a corner
// are filled in, so no two loops touch.
NamedPlan polyomino_plan(std::mt19937_64& rng, std::size_t max_vertices = 400);

// A rectangle, L, T, U, H, E, F, plus, comb, stairs or courtyard on the grid.
NamedPlan letter_plan(std::mt19937_64& rng);

// Up to three extra vertices at grid points inside some edges (a loop that
// runs straight on through them).
NamedPlan with_collinear_vertices(NamedPlan plan, std::mt19937_64& rng);

}  // namespace procex::testing

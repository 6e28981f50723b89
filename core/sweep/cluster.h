// Clustering (paper 4.3, delta3): the collisions a batch found at one height,
// grouped into the events they are by where they happen in the plan.
#pragma once

#include <array>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// A potential event found real: the planes that meet at p and the corners
// that arrive there (one for a split, a collapsing edge's two). Both are few
// and fixed, so they are held in place: a batch makes one per candidate, and
// two vectors each were a ninth of the city's allocations.
struct Collision {
  glm::dvec2 p;
  double z;
  std::array<int, 3> edges;
  std::array<int, 2> ends;
  int ends_used;
  std::span<const int> corners() const { return {ends.data(), static_cast<std::size_t>(ends_used)}; }
};

// cluster's working lists, kept from one batch to the next (BatchScratch).
struct ClusterLists {
  struct Point {
    long long x, y;  // its cell
    int i;           // its collision
    bool operator<(const Point& o) const { return std::tie(x, y, i) < std::tie(o.x, o.y, o.i); }
  };
  std::vector<int> parent;
  std::vector<std::pair<int, int>> by_corner;  // (corner, collision), sorted
  std::vector<int> roots;                      // one collision per group joined through corners
  std::vector<Point> grid;                     // sorted: each cell's points are a run
  std::vector<int> group_of;                   // by root collision
  std::vector<double> radius;                  // by collision: delta3, or its meeting's slack past that (-1: not yet)
  std::vector<std::vector<int>> spare;         // lists of groups a batch had and the next did not
  std::vector<std::pair<double, int>> by_x;    // a cell's points by x (any_within)
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int i, int j) { parent[find(i)] = find(j); }
};

// Clusters collisions at one height closer than delta3 in the plan (or than
// the slack of either's meeting, where that passes delta3), in first-member
// order. Collisions that share a corner there are one event
// (a corner meeting many planes at once, the corners of a regular polygon
// meeting at its centre): they are joined through their corners first (each
// to the first collision of the corner), then one point per such group is
// compared with the others. The groups are the same whatever order they are
// joined in. `groups` keeps the lists it had (their storage, not their
// members).
void cluster(const State& st, const std::vector<Collision>& cs, ClusterLists& lists,
             std::vector<std::vector<int>>& groups);

}  // namespace procex::engine

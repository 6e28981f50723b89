#include "core/sweep/cluster.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

namespace procex::engine {
namespace {

// Up to this many roots are compared pair by pair: most batches hold a few
// collisions, and the grid's sort and searches cost more than the pairs.
constexpr std::size_t kPairwiseUpTo = 8;

// lists.grid: the roots by the cell of side `side` they lie in.
const std::vector<ClusterLists::Point>& roots_in_cells(const std::vector<Collision>& cs, ClusterLists& lists,
                                                      double side) {
  std::vector<ClusterLists::Point>& grid = lists.grid;
  grid.clear();
  for (int i : lists.roots)
    grid.push_back({static_cast<long long>(std::floor(cs[i].p.x / side)),
                    static_cast<long long>(std::floor(cs[i].p.y / side)), i});
  std::sort(grid.begin(), grid.end());
  return grid;
}

// Whether a point of grid[from, to) lies within `radius` of one of grid[there,
// there_end). Two cells of thousands of points each that lie apart (a jittered
// star's centre) are compared by the box around each cell's points first,
// then only the points near the other's box, through those sorted by x: not
// pair by pair. The boxes' distances are taken wider than the radius by more
// than rounding can take off a distance, so they pass every pair it does.
bool any_within(const std::vector<Collision>& cs, ClusterLists& lists, std::size_t from, std::size_t to,
                std::size_t there, std::size_t there_end, double radius) {
  const std::vector<ClusterLists::Point>& grid = lists.grid;
  const auto within = [&](int a, int b) { return glm::length(cs[a].p - cs[b].p) <= radius; };
  if ((to - from) * (there_end - there) <= 1024) {
    for (std::size_t a = from; a < to; ++a)
      for (std::size_t b = there; b < there_end; ++b)
        if (within(grid[a].i, grid[b].i)) return true;
    return false;
  }
  struct Box {
    glm::dvec2 lo{HUGE_VAL}, hi{-HUGE_VAL};
    double distance(glm::dvec2 p) const {
      return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec2(0.0)));
    }
  };
  const auto box_of = [&](std::size_t i, std::size_t end) {
    Box b;
    for (; i < end; ++i) {
      b.lo = glm::min(b.lo, cs[grid[i].i].p);
      b.hi = glm::max(b.hi, cs[grid[i].i].p);
    }
    return b;
  };
  const Box a_box = box_of(from, to), b_box = box_of(there, there_end);
  const double wide = radius * (1.0 + 1e-9);
  const glm::dvec2 gap = glm::max(glm::max(a_box.lo - b_box.hi, b_box.lo - a_box.hi), glm::dvec2(0.0));
  if (glm::length(gap) > wide) return false;
  std::vector<std::pair<double, int>>& by_x = lists.by_x;
  by_x.clear();
  for (std::size_t b = there; b < there_end; ++b) {
    const glm::dvec2 p = cs[grid[b].i].p;
    if (a_box.distance(p) <= wide) by_x.push_back({p.x, grid[b].i});
  }
  std::sort(by_x.begin(), by_x.end());
  for (std::size_t a = from; a < to; ++a) {
    const glm::dvec2 p = cs[grid[a].i].p;
    if (b_box.distance(p) > wide) continue;
    for (auto b = std::lower_bound(by_x.begin(), by_x.end(), std::pair<double, int>{p.x - wide, INT_MIN});
         b != by_x.end() && b->first <= p.x + wide; ++b)
      if (within(grid[a].i, b->second)) return true;
  }
  return false;
}

// Joins the roots within `radius` of each other through a plan grid. Its
// cells are two thirds of `radius` wide, so any two points in one cell are
// within it and a cell joins as a whole, without a comparison; two cells (at
// most two apart) are compared point by point only while their groups are
// apart, and only until one pair is close enough. Thousands of corners of a
// jittered star racing through its centre within one delta2, each meeting
// the planes at its own height, are joined in as many steps, not compared
// pair by pair (hundreds of thousands of points in a few cells). It joins
// the same pairs as comparing every pair: a cell's diagonal (0.94 radius)
// stays within the radius after rounding, and points three cells apart are
// more than the radius apart.
void join_by_grid(const std::vector<Collision>& cs, ClusterLists& lists, double radius) {
  const std::vector<ClusterLists::Point>& grid = roots_in_cells(cs, lists, radius / 1.5);
  const auto cell_end = [&](std::size_t from) {
    std::size_t to = from + 1;
    while (to < grid.size() && grid[to].x == grid[from].x && grid[to].y == grid[from].y) ++to;
    return to;
  };
  for (std::size_t from = 0, to; from < grid.size(); from = to) {
    to = cell_end(from);
    for (std::size_t k = from + 1; k < to; ++k) lists.join(grid[k].i, grid[from].i);
  }
  for (std::size_t from = 0, to; from < grid.size(); from = to) {
    to = cell_end(from);
    for (long long dx = -2; dx <= 2; ++dx)
      for (long long dy = -2; dy <= 2; ++dy) {
        if (dx < 0 || (dx == 0 && dy <= 0)) continue;  // each pair of cells once
        const long long x = grid[from].x + dx, y = grid[from].y + dy;
        const std::size_t there =
            std::lower_bound(grid.begin(), grid.end(), ClusterLists::Point{x, y, 0}) - grid.begin();
        if (there == grid.size() || grid[there].x != x || grid[there].y != y) continue;
        if (lists.find(grid[from].i) != lists.find(grid[there].i) &&
            any_within(cs, lists, from, to, there, cell_end(there), radius))
          lists.join(grid[from].i, grid[there].i);
      }
  }
}

// Joins each root whose radius passes delta3 (a meeting rounding may have
// put further off: State::meeting_slack) with the roots within it, and
// within their own, through a grid of cells as wide as the largest radius.
template <class Radius>
void join_uncertain(const std::vector<Collision>& cs, ClusterLists& lists, double delta3, const Radius& radius) {
  double side = 0.0;
  for (int i : lists.roots) side = std::max(side, radius(i));
  if (side <= delta3) return;
  const std::vector<ClusterLists::Point>& grid = roots_in_cells(cs, lists, side);
  for (const ClusterLists::Point& a : grid) {
    if (radius(a.i) <= delta3) continue;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const long long x = a.x + dx, y = a.y + dy;
        for (auto b = std::lower_bound(grid.begin(), grid.end(), ClusterLists::Point{x, y, 0});
             b != grid.end() && b->x == x && b->y == y; ++b)
          if (lists.find(a.i) != lists.find(b->i) &&
              glm::length(cs[a.i].p - cs[b->i].p) <= std::max(radius(a.i), radius(b->i)))
            lists.join(b->i, a.i);
      }
  }
}

// Sets the number of groups, moving lists between them and the spares
// rather than freeing and making them: made afresh for a batch's groups,
// they were 100,000 of the city's allocations.
void resize_groups(std::vector<std::vector<int>>& groups, std::size_t n, ClusterLists& lists) {
  for (; groups.size() > n; groups.pop_back()) lists.spare.push_back(std::move(groups.back()));
  for (; groups.size() < n; groups.back().clear()) {
    if (lists.spare.empty()) {
      groups.emplace_back();
    } else {
      groups.push_back(std::move(lists.spare.back()));
      lists.spare.pop_back();
    }
  }
}

}  // namespace

void cluster(const State& st, const std::vector<Collision>& cs, ClusterLists& lists,
             std::vector<std::vector<int>>& groups) {
  // Most batches hold a single collision: its own cluster, nothing to join.
  if (cs.size() <= 1) {
    resize_groups(groups, cs.size(), lists);
    if (!cs.empty()) groups[0].assign(1, 0);
    return;
  }
  const double delta3 = st.tol().position();
  // A meeting's slack is worked out only where it decides: for a pair
  // further apart than delta3 but not than any slack can reach, and for
  // join_uncertain. Most pairs of a batch are within delta3 (one corner's
  // collisions) or far apart (events of one height elsewhere in the plan).
  std::vector<double>& radius = lists.radius;
  radius.assign(cs.size(), -1.0);
  const auto radius_of = [&](int i) {
    if (radius[i] < 0.0) {
      const Collision& c = cs[i];
      radius[i] = std::max(delta3, st.meeting_slack(c.edges[0], c.edges[1], c.edges[2], c.corners()));
    }
    return radius[i];
  };
  const double reach = std::max(delta3, st.tol().most_meeting_slack());
  const auto near = [&](int i, int j) {
    const double d = glm::length(cs[i].p - cs[j].p);
    return d <= delta3 || (d <= reach && d <= std::max(radius_of(i), radius_of(j)));
  };
  std::vector<int>& parent = lists.parent;
  parent.resize(cs.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::pair<int, int>>& by_corner = lists.by_corner;
  by_corner.clear();
  for (int i = 0; i < static_cast<int>(cs.size()); ++i)
    for (int c : cs[i].corners()) by_corner.push_back({c, i});
  std::sort(by_corner.begin(), by_corner.end());
  for (int i = 0; i < static_cast<int>(cs.size()); ++i)
    for (int c : cs[i].corners()) {
      const int f = std::lower_bound(by_corner.begin(), by_corner.end(), std::pair<int, int>{c, 0})->second;
      if (f != i && near(i, f)) lists.join(i, f);
    }
  std::vector<int>& roots = lists.roots;
  roots.clear();
  for (int i = 0; i < static_cast<int>(cs.size()); ++i)
    if (lists.find(i) == i) roots.push_back(i);
  if (roots.size() > kPairwiseUpTo) {
    join_by_grid(cs, lists, delta3);
    join_uncertain(cs, lists, delta3, radius_of);
  } else {
    for (std::size_t a = 0; a < roots.size(); ++a)
      for (std::size_t b = a + 1; b < roots.size(); ++b)
        if (near(roots[a], roots[b])) lists.join(roots[b], roots[a]);
  }
  std::vector<int>& group_of = lists.group_of;
  group_of.assign(cs.size(), kNone);
  int count = 0;
  for (int i = 0; i < static_cast<int>(cs.size()); ++i) {
    int& g = group_of[lists.find(i)];
    if (g == kNone) {
      if (groups.size() == static_cast<std::size_t>(count)) resize_groups(groups, count + 1, lists);
      groups[count].clear();
      g = count++;
    }
    groups[g].push_back(i);
  }
  resize_groups(groups, static_cast<std::size_t>(count), lists);
}

}  // namespace procex::engine

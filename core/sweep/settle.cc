#include "core/sweep/settle.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/sweep/ambiguity.h"
#include "core/sweep/spike.h"

namespace procex::engine {
namespace {

// A loop with no area left (two corners, or all edges on one line) ends here:
// its spans become horizontal ridges. On a line, a span's ridge passes through
// every other corner of the loop that lies on it, so faces meet vertex to vertex.
bool close_if_degenerate(State& st, int start) {
  std::size_t walked = 0;
  int c = start;
  const glm::dvec2 d0 = st.edges[st.corners[start].next_edge].dir;
  double worst_turn = 0.0, extent = 0.0;
  const glm::dvec2 p0 = st.position(start, st.height);
  // On one line as runs_straight judges a plan: the edges' directions part by
  // less than the clustering distance over the loop (edges of a plan far from
  // the origin, on one grid line in exact terms, differ by 1e-10 rad).
  const auto collinear = [&] {
    return worst_turn <= Tolerances::parallel_sin || worst_turn * extent <= st.tol().position();
  };
  do {
    ++walked;
    worst_turn = std::max(worst_turn, std::abs(cross(st.edges[st.corners[c].next_edge].dir, d0)));
    extent = std::max(extent, glm::length(st.position(c, st.height) - p0));
    // Both only grow: a loop of three corners off one line has area, and the
    // rest of it (thousands of corners, for every corner made) is not walked.
    if (walked > 2 && !collinear()) return false;
    c = st.corners[c].next;
    if (walked > st.corners.size()) throw SweepError("sweep: corrupt loop at height " + std::to_string(st.height), st.height, {});
  } while (c != start);
  // Listed only now: nearly every loop walked has area (settle asks for every
  // corner made).
  std::vector<int> loop;
  loop.reserve(walked);
  c = start;
  do {
    loop.push_back(c);
    c = st.corners[c].next;
  } while (c != start);
  std::vector<std::uint32_t> v;
  std::vector<double> along;
  for (int x : loop) {
    // Corners meeting at one point of the line share its vertex.
    const glm::dvec2 px = st.position(x, st.height);
    auto same = std::find_if(v.begin(), v.end(), [&](std::uint32_t u) {
      return glm::length(glm::dvec2(st.vertices[u]) - px) <= st.tol().position();
    });
    if (same != v.end()) {
      st.emit_trajectory(x, *same);
      v.push_back(*same);
    } else {
      v.push_back(st.vertex_now(x));
    }
    along.push_back(glm::dot(px, d0));
  }
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::size_t j = (i + 1) % loop.size();
    // The ridge runs from the span's end back to its start, through the corners between.
    std::vector<std::pair<double, std::uint32_t>> path;
    const double lo = std::min(along[i], along[j]), hi = std::max(along[i], along[j]);
    for (std::size_t m = 0; m < loop.size(); ++m)
      if (v[m] != v[i] && v[m] != v[j] && along[m] > lo && along[m] < hi) path.push_back({along[m], v[m]});
    std::sort(path.begin(), path.end());
    if (along[j] > along[i]) std::reverse(path.begin(), path.end());
    path.erase(std::unique(path.begin(), path.end(),
                           [](const auto& a, const auto& b) { return a.second == b.second; }),
               path.end());
    std::uint32_t from = v[j];
    for (const auto& [t, id] : path) {
      st.emit_top(st.corners[loop[i]].next_edge, id, from);
      from = id;
    }
    st.emit_top(st.corners[loop[i]].next_edge, v[i], from);
  }
  for (int x : loop) st.corners[x].alive = false;
  return true;
}

}  // namespace

void settle(State& st, const std::vector<int>& made, std::vector<int>& live) {
  live.clear();
  // Corners made in settling one are settled before the next of `made`; the
  // stack is needed only then (a spike folds, neighbours are ambiguous).
  std::vector<int> pending;
  for (const int first : made) {
    for (int n = first;;) {
      if (st.corners[n].alive && !close_if_degenerate(st, n)) {
        std::vector<int> replaced;
        if (st.corners[n].motion == Motion::Ridge) {
          replaced = close_spike(st, n);
        } else if (ambiguous(st, n)) {
          replaced = resolve_ambiguity(st, n, st.tol().position());
        } else {
          live.push_back(n);
        }
        pending.insert(pending.end(), replaced.rbegin(), replaced.rend());
      }
      if (pending.empty()) break;
      n = pending.back();
      pending.pop_back();
    }
  }
}

}  // namespace procex::engine

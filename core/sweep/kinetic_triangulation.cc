#include "core/sweep/kinetic_triangulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/convex_partition.h"
#include "core/geom/cross.h"
#include "core/geom/nesting.h"
#include "core/geom/segment_distance.h"

namespace procex::engine {
namespace {

// Rebuilding the whole triangulation costs a pass over every corner: past
// this many, the sweep is better off listing splits the old way.
constexpr std::size_t kMostRebuilds = 64;
// A cavity widened this many times over (each time by the triangles across
// the spokes new spans cross) is given up on.
constexpr int kMostWidenings = 64;
// Cycles of the rim longer than this are not searched for crossing spans.
constexpr std::size_t kMostSearched = 256;
// Triangles walked round a batch's neighbourhood of k places before its
// corners list every live plane instead: this and 16 per place.
constexpr std::size_t kMostWalked = 512;

// A triangle's corners may meet at a point (a regular polygon's centre, a
// split's two new corners), and a cluster moves the corners it makes to its
// mean point, up to its clustering distance `slack` across a side: flat up to
// that is not inside out.
bool inside_out(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double slack) {
  const glm::dvec2 ab = b - a, ac = c - a;
  const double longest = std::sqrt(std::max({glm::dot(ab, ab), glm::dot(ac, ac), glm::dot(c - b, c - b)}));
  return cross(ab, ac) < -slack * longest;
}

std::uint64_t side_key(int a, int b) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 | static_cast<std::uint32_t>(b);
}

}  // namespace

void KineticTriangulation::clear() {
  tris_.clear();
  free_.clear();
  vtri_.clear();
  heap_ = {};
  relinked_.clear();
  facing_.clear();
  tangled_.clear();
  handed_.clear();
  cavity_.clear();
  work_ = {};
  clock_ = -HUGE_VAL;
}

int KineticTriangulation::add_tri(int a, int b, int c) {
  int t;
  if (!free_.empty()) {
    t = free_.back();
    free_.pop_back();
  } else {
    t = static_cast<int>(tris_.size());
    tris_.emplace_back();
    cavity_.push_back(0);
  }
  Tri& x = tris_[t];
  x.v[0] = a, x.v[1] = b, x.v[2] = c;
  x.n[0] = x.n[1] = x.n[2] = kNone;
  x.version = ++version_;
  x.alive = true;
  const int need = std::max({a, b, c}) + 1;
  if (static_cast<int>(vtri_.size()) < need) vtri_.resize(static_cast<std::size_t>(need), kNone);
  vtri_[a] = vtri_[b] = vtri_[c] = t;
  return t;
}

void KineticTriangulation::drop_tri(int t) {
  Tri& x = tris_[t];
  x.alive = false;
  x.version = ++version_;
  for (int v : x.v)
    if (vtri_[v] == t) vtri_[v] = kNone;
  free_.push_back(t);
}

void KineticTriangulation::tangle(int a, int b, int c) {
  ++work_.tangled;
  tangled_.insert(tangled_.end(), {a, b, c});
}

int KineticTriangulation::side_of(int t, int a, int b) const {
  const Tri& x = tris_[t];
  for (int i = 0; i < 3; ++i)
    if (x.v[(i + 1) % 3] == a && x.v[(i + 2) % 3] == b) return i;
  return -1;
}

void KineticTriangulation::fan(int c, std::vector<int>& out) const {
  const int start = c < static_cast<int>(vtri_.size()) ? vtri_[c] : kNone;
  if (start == kNone) return;
  const auto index = [&](int t) {
    const Tri& x = tris_[t];
    return x.v[0] == c ? 0 : x.v[1] == c ? 1 : 2;
  };
  out.push_back(start);
  // Counter-clockwise round c until a span (c is on the loops), or round to the start.
  int cur = start;
  for (std::size_t steps = 0; steps <= tris_.size(); ++steps) {
    const int next = tris_[cur].n[(index(cur) + 1) % 3];
    if (next == kNone) break;
    if (next == start) return;
    out.push_back(next);
    cur = next;
  }
  cur = start;
  for (std::size_t steps = 0; steps <= tris_.size(); ++steps) {
    const int next = tris_[cur].n[(index(cur) + 2) % 3];
    if (next == kNone) break;
    out.push_back(next);
    cur = next;
  }
}

bool KineticTriangulation::hand(const State& st, int c, int e) {
  if (static_cast<std::size_t>(c) >= handed_.size()) handed_.resize(st.corners.size());
  std::vector<int>& h = handed_[c];
  if (std::find(h.begin(), h.end(), e) != h.end()) return false;
  h.push_back(e);
  facing_.push_back({c, e});
  return true;
}

void KineticTriangulation::settle(const State& st, int t, double now, int fresh) {
  Tri& x = tris_[t];
  x.version = ++version_;
  for (int v : x.v)
    if (!st.corners[v].alive) return;
  for (int i = 0; i < 3; ++i)
    if (x.n[i] == kNone) hand(st, x.v[i], st.corners[x.v[(i + 1) % 3]].next_edge);
  // Twice the signed area, C + B s + A s^2, s above `now`.
  glm::dvec2 q[3], w[3];
  for (int i = 0; i < 3; ++i) {
    q[i] = st.position(x.v[i], now);
    w[i] = st.corners[x.v[i]].velocity;
    if (!std::isfinite(q[i].x) || !std::isfinite(q[i].y) || !std::isfinite(w[i].x) || !std::isfinite(w[i].y)) return;
  }
  const glm::dvec2 e1 = q[1] - q[0], e2 = q[2] - q[0], f1 = w[1] - w[0], f2 = w[2] - w[0];
  const double C = cross(e1, e2), B = cross(e1, f2) + cross(f1, e2), A = cross(f1, f2);
  // The first s >= 0 where the area goes down through zero. Flat or inside
  // out now (rounding, or a corner moved to its cluster's point): now if it
  // is shrinking, else where it turns down again, if it does.
  double s = HUGE_VAL;
  const double disc = B * B - 4.0 * A * C;
  const double qq = disc >= 0.0 ? -0.5 * (B + std::copysign(std::sqrt(disc), B)) : 0.0;
  // The larger root of a downward parabola, the smaller of an upward one.
  const auto root = [&](bool larger) {
    double r1 = qq / A, r2 = qq != 0.0 ? C / qq : r1;
    if (r1 > r2) std::swap(r1, r2);
    return larger ? r2 : r1;
  };
  if (C <= 0.0) {
    if (B < 0.0 || (B == 0.0 && A < 0.0)) s = 0.0;
    else if (A < 0.0 && disc >= 0.0) s = std::max(root(true), 0.0);
  } else if (A == 0.0) {
    if (B < 0.0) s = -C / B;
  } else if (disc >= 0.0) {
    const double r = root(A < 0.0);
    if (r >= 0.0) s = r;
  }
  if (!(s < HUGE_VAL)) return;
  // The corner between the other two where they line up reaches the side
  // opposite it, the longest; where all three meet, no side is crossed (the
  // sweep's event there takes them).
  glm::dvec2 p[3];
  for (int i = 0; i < 3; ++i) p[i] = q[i] + w[i] * s;
  double longest = 0.0, longest_now = 0.0;
  int k = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec2 d = p[(i + 2) % 3] - p[(i + 1) % 3], dn = q[(i + 2) % 3] - q[(i + 1) % 3];
    if (glm::dot(d, d) > longest) longest = glm::dot(d, d), k = i;
    longest_now = std::max(longest_now, glm::dot(dn, dn));
  }
  if (longest <= 1e-14 * longest_now) return;
  // The spoke a flip made now is not flipped back now: rounding may tell
  // the corners' order along their line either way.
  if (s == 0.0 && k == fresh) return;
  heap_.push({now + s, t, x.version, static_cast<std::uint8_t>(k)});
}

void KineticTriangulation::flip(const State& st, int t, int k, double now) {
  // x = v[k] reaches the spoke (a, b); across it lies (y, b, a). The
  // quadrilateral x, a, y, b takes the other diagonal, x to y.
  const int o = tris_[t].n[k];
  const int j = side_of(o, tris_[t].v[(k + 2) % 3], tris_[t].v[(k + 1) % 3]);
  if (j < 0) return;
  Tri& a_ = tris_[t];
  Tri& b_ = tris_[o];
  const int x = a_.v[k], a = a_.v[(k + 1) % 3], b = a_.v[(k + 2) % 3], y = b_.v[j];
  const int ta = a_.n[(k + 2) % 3];  // across (x, a)
  const int tb = a_.n[(k + 1) % 3];  // across (b, x)
  const int na = b_.n[(j + 1) % 3];  // across (a, y)
  const int nb = b_.n[(j + 2) % 3];  // across (y, b)
  a_.v[0] = x, a_.v[1] = a, a_.v[2] = y;
  a_.n[0] = na, a_.n[1] = o, a_.n[2] = ta;
  b_.v[0] = x, b_.v[1] = y, b_.v[2] = b;
  b_.n[0] = nb, b_.n[1] = tb, b_.n[2] = t;
  const auto repoint = [&](int across, int from, int to) {
    if (across == kNone) return;
    for (int& n : tris_[across].n)
      if (n == from) n = to;
  };
  repoint(na, o, t);
  repoint(tb, t, o);
  vtri_[x] = vtri_[a] = vtri_[y] = t;
  vtri_[b] = o;
  ++work_.flips;
  settle(st, t, now, 1);
  settle(st, o, now, 2);
}

bool KineticTriangulation::add_region(const State& st, const std::vector<std::vector<int>>& loops,
                                      const std::vector<std::vector<glm::dvec2>>& points, std::size_t outer,
                                      const std::vector<std::size_t>& holes, std::vector<int>& made) {
  std::vector<std::vector<glm::dvec2>> region{points[outer]};
  std::vector<int> corner(loops[outer]);
  for (std::size_t h : holes) {
    region.push_back(points[h]);
    corner.insert(corner.end(), loops[h].begin(), loops[h].end());
  }
  std::vector<std::vector<std::uint32_t>> pieces;
  try {
    pieces = convex_partition(region);
  } catch (const std::invalid_argument&) {
    return false;  // a hole outside its region: the loops cross
  }
  const double slack = 4.0 * st.tol().position();
  for (const auto& piece : pieces)
    for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
      const int a = corner[piece[0]], b = corner[piece[k]], c = corner[piece[k + 1]];
      if (inside_out(st.position(a, now(st)), st.position(b, now(st)), st.position(c, now(st)), slack)) tangle(a, b, c);
      made.push_back(add_tri(a, b, c));
    }
  return true;
}

bool KineticTriangulation::build(const State& st) {
  tris_.clear();
  free_.clear();
  cavity_.clear();
  vtri_.assign(st.corners.size(), kNone);
  heap_ = {};
  relinked_.clear();
  clock_ = std::max(clock_, st.height);
  // The live loops, as corners and as points.
  std::vector<std::vector<int>> loops;
  std::vector<std::vector<glm::dvec2>> points;
  std::vector<char> seen(st.corners.size(), 0);
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) {
    if (!st.corners[c].alive || seen[c]) continue;
    std::vector<int> loop;
    std::vector<glm::dvec2> at;
    for (int k = c; k != c || loop.empty(); k = st.corners[k].next) {
      if (k == kNone || !st.corners[k].alive || seen[k]) return false;
      seen[k] = 1;
      loop.push_back(k);
      at.push_back(st.position(k, now(st)));
    }
    if (loop.size() < 3) return false;
    loops.push_back(std::move(loop));
    points.push_back(std::move(at));
  }
  const LoopNesting nesting = loop_nesting(points);
  std::vector<std::vector<std::size_t>> holes(loops.size());
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const bool hole = nesting.depth[i] % 2 == 1;
    if ((twice_signed_area(points[i]) > 0.0) == hole) return false;  // material turns left, holes right
    if (hole) holes[static_cast<std::size_t>(nesting.parent[i])].push_back(i);
  }
  std::vector<int> made;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (nesting.depth[i] % 2 == 0 && !add_region(st, loops, points, i, holes[i], made)) return false;
  }
  std::vector<std::pair<std::uint64_t, int>> sides;  // (undirected side, triangle * 3 + side)
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = tris_[t].v[(i + 1) % 3], b = tris_[t].v[(i + 2) % 3];
      sides.push_back({side_key(std::min(a, b), std::max(a, b)), 3 * t + i});
    }
  std::sort(sides.begin(), sides.end());
  for (std::size_t r = 0; r < sides.size();) {
    std::size_t end = r + 1;
    while (end < sides.size() && sides[end].first == sides[r].first) ++end;
    const int t = sides[r].second / 3, i = sides[r].second % 3;
    if (end - r == 2) {
      const int u = sides[r + 1].second / 3, j = sides[r + 1].second % 3;
      tris_[t].n[i] = u;
      tris_[u].n[j] = t;
    } else if (end - r != 1 || st.corners[tris_[t].v[(i + 1) % 3]].next != tris_[t].v[(i + 2) % 3]) {
      return false;  // a side in three triangles, or one alone that is not a span
    }
    r = end;
  }
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t) settle(st, t, now(st));
  return true;
}

bool KineticTriangulation::rebuild(const State& st) {
  if (++work_.rebuilds > kMostRebuilds) return false;
  return build(st);
}

bool KineticTriangulation::update(const State& st) {
  if (relinked_.empty()) return true;
  ++work_.updates;
  ++stamp_;
  cavity_tris_.clear();
  for (int c : relinked_) {
    relinked_fan_.clear();
    fan(c, relinked_fan_);
    for (int t : relinked_fan_) take(st, t);
  }
  const bool done = !cavity_tris_.empty() && retriangulate(st);
  relinked_.clear();
  return done || rebuild(st);
}

bool KineticTriangulation::rim(const State& st, std::vector<Side>& sides, std::vector<std::vector<int>>& cycles) {
  cycles.clear();
  // The cavity's rim: spokes to triangles that stay, and spans still live.
  // A triangle beyond it with a dead corner (whose fan was not found whole
  // from it) is taken in, and the rim worked out again.
  for (bool widened = true; widened;) {
    widened = false;
    sides.clear();
    for (std::size_t ti = 0; ti < cavity_tris_.size(); ++ti) {
      const Tri& x = tris_[cavity_tris_[ti]];
      for (int i = 0; i < 3; ++i) {
        const int u = x.v[(i + 1) % 3], w = x.v[(i + 2) % 3];
        if (x.n[i] == kNone) {
          if (st.corners[u].alive && st.corners[w].alive && st.corners[u].next == w) sides.push_back({u, w, kNone, -1});
          continue;
        }
        if (cavity_[x.n[i]] == stamp_) continue;
        const Tri& o = tris_[x.n[i]];
        if (std::all_of(o.v, o.v + 3, [&](int v) { return st.corners[v].alive; })) {
          sides.push_back({u, w, x.n[i], side_of(x.n[i], w, u)});
        } else {
          take(st, x.n[i]);
          widened = true;
        }
      }
    }
    if (widened) ++work_.widenings;
  }
  // The spans the sweep made: round every relinked corner, and every corner new to the triangulation.
  std::vector<std::uint64_t> spans;
  const auto add_span = [&](int u) {
    const int w = st.corners[u].next;
    if (w != kNone && st.corners[w].alive) spans.push_back(side_key(u, w));
  };
  for (int c : relinked_) {
    if (!st.corners[c].alive) continue;
    add_span(c);
    if (st.corners[c].prev != kNone) add_span(st.corners[c].prev);
  }
  for (const Side& s : sides)
    if (s.across == kNone) spans.push_back(side_key(s.from, s.to));
  std::sort(spans.begin(), spans.end());
  spans.erase(std::unique(spans.begin(), spans.end()), spans.end());
  std::erase_if(sides, [](const Side& s) { return s.across == kNone; });
  for (std::uint64_t key : spans) sides.push_back({static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu), kNone, -1});
  // The rim's sides into cycles: at a corner several leave (the region
  // touches itself there), the one turning furthest right from where the
  // walk came in keeps the region on the left.
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.from < b.from; });
  std::vector<char> used(sides.size(), 0);
  const auto leaving = [&](int v) {
    return std::equal_range(sides.begin(), sides.end(), Side{v, 0, 0, 0},
                            [](const Side& a, const Side& b) { return a.from < b.from; });
  };
  for (std::size_t s0 = 0; s0 < sides.size(); ++s0) {
    if (used[s0]) continue;
    std::vector<int> cycle;
    std::size_t s = s0;
    for (std::size_t steps = 0;; ++steps) {
      if (steps > sides.size()) return false;
      used[s] = 1;
      cycle.push_back(sides[s].from);
      const int from = sides[s].from, v = sides[s].to;
      if (v == sides[s0].from) break;
      const auto [lo, hi] = leaving(v);
      const glm::dvec2 pv = st.position(v, now(st));
      const glm::dvec2 back = st.position(from, now(st)) - pv;
      std::size_t best = sides.size();
      double best_turn = HUGE_VAL;
      for (auto it = lo; it != hi; ++it) {
        const auto i = static_cast<std::size_t>(it - sides.begin());
        if (used[i]) continue;
        const glm::dvec2 d = st.position(it->to, now(st)) - pv;
        // The angle clockwise from `back` to d, in (0, 2 pi].
        double turn = std::atan2(cross(d, back), glm::dot(d, back));
        if (turn <= 0.0) turn += 2.0 * std::numbers::pi;
        if (turn < best_turn) best_turn = turn, best = i;
      }
      if (best == sides.size()) return false;
      s = best;
    }
    cycles.push_back(std::move(cycle));
  }
  return true;
}

void KineticTriangulation::take(const State& st, int t) {
  if (cavity_[t] == stamp_) return;
  cavity_[t] = stamp_;
  cavity_tris_.push_back(t);
  // The corners that died with it leave their whole fans to fill.
  for (int v : tris_[t].v)
    if (!st.corners[v].alive) {
      fan_.clear();
      fan(v, fan_);
      for (int f : fan_)
        if (cavity_[f] != stamp_) {
          cavity_[f] = stamp_;
          cavity_tris_.push_back(f);
        }
    }
}

bool KineticTriangulation::retriangulate(const State& st) {
  std::vector<Side> sides;
  std::vector<std::vector<int>> cycles;
  for (int round = 0;; ++round) {
    if (round == kMostWidenings || !rim(st, sides, cycles)) return false;
    // A new span crossing a spoke of the rim: the corner the sweep made lies
    // beyond the cavity (a fast corner's fan), which takes in the triangle
    // across. Long cycles (a regular polygon's centre) are not searched.
    const std::size_t before = cavity_tris_.size();
    for (const auto& cycle : cycles) {
      const std::size_t n = cycle.size();
      if (n > kMostSearched) continue;
      for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = st.position(cycle[i], now(st)), b = st.position(cycle[(i + 1) % n], now(st));
        for (std::size_t j = i + 2; j < n; ++j) {
          if ((j + 1) % n == i) continue;
          const glm::dvec2 c = st.position(cycle[j], now(st)), d = st.position(cycle[(j + 1) % n], now(st));
          if (!(cross(b - a, c - a) * cross(b - a, d - a) < 0.0 && cross(d - c, a - c) * cross(d - c, b - c) < 0.0))
            continue;
          for (const Side& sd : sides)
            if (sd.across != kNone && ((sd.from == cycle[i] && sd.to == cycle[(i + 1) % n]) ||
                                       (sd.from == cycle[j] && sd.to == cycle[(j + 1) % n])))
              take(st, sd.across);
        }
      }
    }
    if (cavity_tris_.size() == before) break;
    ++work_.widenings;
  }
  work_.cavity_triangles += cavity_tris_.size();
  for (int t : cavity_tris_) drop_tri(t);
  // The rim's corners keep the triangles beyond it, which fan() starts from.
  for (const Side& s : sides)
    if (s.across != kNone) vtri_[s.from] = vtri_[s.to] = s.across;
  return fill(st, cycles, sides);
}

bool KineticTriangulation::fill(const State& st, const std::vector<std::vector<int>>& cycles,
                                const std::vector<Side>& sides) {
  std::vector<std::vector<glm::dvec2>> points(cycles.size());
  std::vector<double> area(cycles.size());
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    for (int c : cycles[i]) points[i].push_back(st.position(c, now(st)));
    area[i] = twice_signed_area(points[i]);
  }
  // Holes go in the smallest region round them.
  std::vector<std::vector<std::size_t>> holes(cycles.size());
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    if (area[i] >= 0.0 || cycles[i].size() < 3) continue;
    std::size_t best = cycles.size();
    for (std::size_t j = 0; j < cycles.size(); ++j)
      if (area[j] > 0.0 && cycles[j].size() >= 3 && point_in_loop(points[i][0], points[j]) &&
          (best == cycles.size() || area[j] < area[best]))
        best = j;
    if (best < cycles.size()) holes[best].push_back(i);
    else area[i] = 0.0;  // no region round it: a loop crossed by rounding, fanned as it runs (below)
  }
  std::vector<int> made;
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    if (cycles[i].size() < 3 || area[i] < 0.0) continue;
    if (area[i] == 0.0 && twice_signed_area(points[i]) < 0.0) {
      for (std::size_t k = 1; k + 1 < cycles[i].size(); ++k) {
        made.push_back(add_tri(cycles[i][0], cycles[i][k], cycles[i][k + 1]));
        tangle(cycles[i][0], cycles[i][k], cycles[i][k + 1]);
      }
      continue;
    }
    if (!add_region(st, cycles, points, i, holes[i], made)) return false;
  }
  // Join the new triangles to each other, then across the rim.
  std::vector<std::pair<std::uint64_t, int>> own;
  for (int t : made)
    for (int i = 0; i < 3; ++i) own.push_back({side_key(tris_[t].v[(i + 1) % 3], tris_[t].v[(i + 2) % 3]), 3 * t + i});
  std::sort(own.begin(), own.end());
  const auto find = [&](int a, int b) {
    const auto it = std::lower_bound(own.begin(), own.end(), std::make_pair(side_key(a, b), -1));
    return it != own.end() && it->first == side_key(a, b) ? it->second : -1;
  };
  std::vector<std::pair<std::uint64_t, const Side*>> rim;
  for (const Side& s : sides)
    if (s.across != kNone) rim.push_back({side_key(s.from, s.to), &s});
  std::sort(rim.begin(), rim.end());
  for (const auto& [key, ti] : own) {
    const int t = ti / 3, i = ti % 3;
    const int u = tris_[t].v[(i + 1) % 3], w = tris_[t].v[(i + 2) % 3];
    if (const int o = find(w, u); o >= 0) {
      tris_[t].n[i] = o / 3;
      continue;
    }
    const auto it = std::lower_bound(rim.begin(), rim.end(), std::make_pair(key, static_cast<const Side*>(nullptr)));
    if (it != rim.end() && it->first == key) {
      const Side& s = *it->second;
      if (s.across_side < 0) return false;
      tris_[t].n[i] = s.across;
      tris_[s.across].n[s.across_side] = t;
      continue;
    }
    if (st.corners[u].next != w) return false;  // neither joined nor a span
  }
  // A rim spoke no new triangle took: the region beyond it closed up to it.
  for (const auto& [key, s] : rim)
    if (!std::binary_search(own.begin(), own.end(), std::make_pair(key, -1),
                            [](const auto& a, const auto& b) { return a.first < b.first; })) {
      if (st.corners[s->to].next != s->from) return false;
      tris_[s->across].n[s->across_side] = kNone;
      made.push_back(s->across);
    }
  for (int t : made) settle(st, t, now(st));
  return true;
}

double KineticTriangulation::Box::distance(glm::dvec2 p) const {
  return glm::length(p - glm::clamp(p, lo, hi));
}

double KineticTriangulation::Box::distance(glm::dvec2 a, glm::dvec2 b) const {
  // Zero where the segment enters the box (clipped to its slabs, Liang and
  // Barsky); else the nearest of its ends to the box or the box's corners to it.
  double t0 = 0.0, t1 = 1.0;
  const glm::dvec2 d = b - a;
  bool crosses = true;
  for (int axis = 0; axis < 2 && crosses; ++axis) {
    if (d[axis] == 0.0) {
      crosses = a[axis] >= lo[axis] && a[axis] <= hi[axis];
      continue;
    }
    double u = (lo[axis] - a[axis]) / d[axis], v = (hi[axis] - a[axis]) / d[axis];
    if (u > v) std::swap(u, v);
    t0 = std::max(t0, u);
    t1 = std::min(t1, v);
    crosses = t0 <= t1;
  }
  if (crosses) return 0.0;
  return std::min({distance(a), distance(b), distance_to_segment(lo, a, b), distance_to_segment(hi, a, b),
                   distance_to_segment({lo.x, hi.y}, a, b), distance_to_segment({hi.x, lo.y}, a, b)});
}

bool KineticTriangulation::hand_around(const State& st, const std::vector<Place>& places, double reach,
                                       double rise) {
  // Places within reach of each other are one neighbourhood (chained, as the
  // sweep clusters its collisions), found through a grid whose cells are
  // within reach across: a cell's places are one, and two cells next to each
  // other are joined by the first pair of their places within reach.
  const int count = static_cast<int>(places.size());
  hood_.resize(places.size());
  std::iota(hood_.begin(), hood_.end(), 0);
  const auto root = [&](int i) {
    while (hood_[i] != i) i = hood_[i] = hood_[hood_[i]];
    return i;
  };
  const double side = reach / std::numbers::sqrt2;
  // Far-away coordinates over a fine reach are kept inside the cell type
  // (clamped cells only join more places, never fewer).
  const auto cell = [side](double x) {
    return static_cast<std::int64_t>(std::clamp(std::floor(x / side), -0x1p62, 0x1p62));
  };
  cells_.clear();
  for (int i = 0; i < count; ++i) cells_.push_back({{cell(places[i].p.x), cell(places[i].p.y)}, i});
  std::sort(cells_.begin(), cells_.end());
  const auto run_end = [&](auto from) {
    return std::find_if(from, cells_.end(), [&](const auto& e) { return e.first != from->first; });
  };
  for (auto a = cells_.begin(); a != cells_.end();) {
    const auto a_end = run_end(a);
    for (auto i = a + 1; i != a_end; ++i) hood_[root(i->second)] = root(a->second);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::pair key{a->first.first + dx, a->first.second + dy};
        if (key <= a->first) continue;  // each pair of cells once
        const auto b = std::lower_bound(cells_.begin(), cells_.end(), std::pair{key, 0});
        if (b == cells_.end() || b->first != key || root(b->second) == root(a->second)) continue;
        const auto b_end = run_end(b);
        bool joined = false;
        for (auto i = a; i != a_end && !joined; ++i)
          for (auto j = b; j != b_end && !joined; ++j)
            if (glm::length(places[i->second].p - places[j->second].p) <= reach) {
              hood_[root(j->second)] = root(i->second);
              joined = true;
            }
      }
    a = a_end;
  }
  near_corners_.clear();
  near_edges_.clear();
  // Each neighbourhood's box and lowest height; its events' corners and edges.
  boxes_.assign(places.size(), {});
  for (int i = 0; i < count; ++i) {
    const Place& q = places[i];
    Box& box = boxes_[root(i)];
    box.lo = glm::min(box.lo, q.p);
    box.hi = glm::max(box.hi, q.p);
    box.z = std::min(box.z, q.z);
    const int hood = root(i);
    const Corner& k = st.corners[q.corner];
    near_corners_.push_back({hood, q.corner});
    near_edges_.insert(near_edges_.end(), {{hood, k.prev_edge}, {hood, k.next_edge}});
    if (q.other != kNone) {
      near_corners_.push_back({hood, q.other});
      near_edges_.push_back({hood, st.corners[q.other].next_edge});
    }
    if (q.edge != kNone) near_edges_.push_back({hood, q.edge});
  }
  // How far from a box a corner may be now and still reach it within the batch.
  const auto allowance = [&](int c) { return reach + rise * glm::length(st.corners[c].velocity); };
  // Out from the triangles round each neighbourhood's corners, across every
  // spoke near its box.
  walked_.resize(tris_.size(), 0);
  crowded_.assign(places.size(), 0);
  hood_order_.clear();
  for (int i = 0; i < count; ++i) hood_order_.push_back({root(i), i});
  std::sort(hood_order_.begin(), hood_order_.end());
  for (std::size_t r = 0; r < hood_order_.size();) {
    const int hood = hood_order_[r].first;
    const Box& box = boxes_[hood];
    // A place alone needs no walk: a corner reaching it through triangles it
    // does not face flips its way there before the batch (collapse_through),
    // and the walk out of a corner of many triangles (a comb's bar cut into
    // a fan) would cost them all at each of its events.
    if (r + 1 == hood_order_.size() || hood_order_[r + 1].first != hood) {
      ++r;
      continue;
    }
    ++walk_;
    walk_tris_.clear();
    const std::size_t first = r;
    for (; r < hood_order_.size() && hood_order_[r].first == hood; ++r) {
      const std::size_t from = walk_tris_.size();
      fan(places[hood_order_[r].second].corner, walk_tris_);
      // Fans of a hood's corners overlap: each triangle is walked once.
      std::size_t kept = from;
      for (std::size_t w = from; w < walk_tris_.size(); ++w)
        if (walked_[walk_tris_[w]] != walk_) walked_[walk_tris_[w]] = walk_, walk_tris_[kept++] = walk_tris_[w];
      walk_tris_.resize(kept);
    }
    // Where the triangles near the box are many (a comb's bar and teeth
    // collapsing onto one line at once: every spoke runs by every tooth),
    // its corners list every live plane instead.
    const std::size_t most = kMostWalked + 16 * (r - first);
    for (std::size_t w = 0; w < walk_tris_.size(); ++w) {
      if (w == most) {
        crowded_[hood] = 1;
        break;
      }
      ++work_.walked;
      const Tri& x = tris_[walk_tris_[w]];
      glm::dvec2 at[3];
      for (int j = 0; j < 3; ++j) {
        at[j] = st.position(x.v[j], box.z);
        if (box.distance(at[j]) <= allowance(x.v[j])) near_corners_.push_back({hood, x.v[j]});
      }
      for (int j = 0; j < 3; ++j) {
        const int a = x.v[(j + 1) % 3], b = x.v[(j + 2) % 3];
        if (box.distance(at[(j + 1) % 3], at[(j + 2) % 3]) > std::max(allowance(a), allowance(b))) continue;
        if (x.n[j] == kNone) {
          near_edges_.push_back({hood, st.corners[a].next_edge});
        } else if (walked_[x.n[j]] != walk_) {
          walked_[x.n[j]] = walk_;
          walk_tris_.push_back(x.n[j]);
        }
      }
    }
  }
  // Each neighbourhood's corners and edges, once each.
  for (auto* found : {&near_corners_, &near_edges_}) {
    std::sort(found->begin(), found->end());
    found->erase(std::unique(found->begin(), found->end()), found->end());
  }
  edge_mark_.resize(st.edges.size(), 0);
  const std::size_t was = facing_.size();
  auto edges = near_edges_.begin();
  for (auto corners = near_corners_.begin(); corners != near_corners_.end();) {
    const int hood = corners->first;
    while (edges != near_edges_.end() && edges->first < hood) ++edges;
    const auto edges_end = std::find_if(edges, near_edges_.end(), [&](const auto& e) { return e.first != hood; });
    for (; corners != near_corners_.end() && corners->first == hood; ++corners) {
      const int c = corners->second;
      const Corner& k = st.corners[c];
      if (!k.alive || !st.may_split(c)) continue;
      if (crowded_[hood]) {
        tangled_.push_back(c);
        continue;
      }
      if (static_cast<std::size_t>(c) >= handed_.size()) handed_.resize(st.corners.size());
      std::vector<int>& h = handed_[c];
      ++mark_;
      for (int e : h) edge_mark_[e] = mark_;
      for (auto e = edges; e != edges_end; ++e) {
        if (edge_mark_[e->second] == mark_ || e->second == k.prev_edge || e->second == k.next_edge) continue;
        edge_mark_[e->second] = mark_;
        h.push_back(e->second);
        facing_.push_back({c, e->second});
      }
    }
    edges = edges_end;
  }
  return facing_.size() > was || !tangled_.empty();
}

bool KineticTriangulation::collapse_through(const State& st, double z) {
  // The sweep takes a corner reaching a span at that height, give or take
  // its clustering; a triangle standing well past it was passed by.
  const double past = st.height - 2.0 * st.tol().height();
  std::vector<Collapse> later;
  // Flips that undo each other at one height would spin here.
  const std::size_t most = 4 * tris_.size() + 1024;
  for (std::size_t popped = 0; !heap_.empty() && heap_.top().z <= z; ++popped) {
    if (popped > most) return false;
    const Collapse e = heap_.top();
    heap_.pop();
    const Tri& x = tris_[e.tri];
    if (!x.alive || x.version != e.version) continue;
    clock_ = std::max(clock_, e.z);
    if (x.n[e.vertex] != kNone) {
      flip(st, e.tri, e.vertex, e.z);
      continue;
    }
    if (e.z > past) {
      later.push_back(e);
      continue;
    }
    // Still standing: the sweep saw the corner pass the span's end, where
    // rounding had it reach the span. Which corner is between the others is
    // asked again as they are now (another corner reaching a spoke, a flip).
    ++work_.repairs;
    tangle(x.v[0], x.v[1], x.v[2]);
    settle(st, e.tri, now(st));
  }
  for (const Collapse& e : later) heap_.push(e);
  return true;
}

bool KineticTriangulation::consistent(const State& st) const {
  std::size_t alive = 0;
  for (int t = 0; t < static_cast<int>(tris_.size()); ++t) {
    const Tri& x = tris_[t];
    // A loop that closed at once (no corner relinked) leaves its triangles behind.
    if (!x.alive || std::none_of(x.v, x.v + 3, [&](int v) { return st.corners[v].alive; })) continue;
    ++alive;
    for (int i = 0; i < 3; ++i) {
      const int u = x.v[(i + 1) % 3], w = x.v[(i + 2) % 3];
      if (!st.corners[u].alive) return false;
      if (x.n[i] == kNone ? st.corners[u].next != w : !tris_[x.n[i]].alive || side_of(x.n[i], w, u) < 0) return false;
    }
  }
  // Loops of three corners or more, and which turn right (holes).
  std::vector<char> seen(st.corners.size(), 0);
  std::size_t corners = 0, loops = 0, holes = 0;
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) {
    if (!st.corners[c].alive || seen[c]) continue;
    std::vector<glm::dvec2> loop;
    for (int k = c; !seen[k]; k = st.corners[k].next) {
      seen[k] = 1;
      loop.push_back(st.position(k, st.height));
    }
    if (loop.size() < 3) continue;
    for (int k = c;; ) {
      if (k >= static_cast<int>(vtri_.size()) || vtri_[k] == kNone) return false;
      if ((k = st.corners[k].next) == c) break;
    }
    corners += loop.size();
    ++loops;
    if (twice_signed_area(loop) < 0.0) ++holes;
  }
  // Per region of V corners and H holes, V + 2 H - 2 triangles.
  return alive == corners + 2 * holes - 2 * (loops - holes);
}

}  // namespace procex::engine

#include "core/sweep/plane_index.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "core/sweep/meeting_heights.h"

namespace procex::engine {
namespace {

constexpr std::int32_t kLeaf = -1;
// Planes a leaf holds: tested side by side (meeting_heights vectorizes), so a
// few more than the bound's arithmetic costs.
constexpr std::size_t kLeafMost = 16;
// Planes past the trees are tested one by one until this many are new.
constexpr std::size_t kTreeLeast = 256;
// The bounds' slack for rounding, relative to the magnitudes rounded
// (meeting_heights rounds within a few 1e-16 of them).
constexpr double kSlack = 1e-12;

// [lo, hi] * s.
void scaled(double lo, double hi, double s, double& out_lo, double& out_hi) {
  const double a = lo * s, b = hi * s;
  out_lo = std::min(a, b);
  out_hi = std::max(a, b);
}

}  // namespace

PlaneIndex::Tree PlaneIndex::build(const Planes& planes, std::size_t from, std::size_t to, glm::dvec2 near) {
  Tree t;
  t.from = from;
  t.to = to;
  const std::size_t m = to - from;
  // The origin nearest every line in the least-squares sense (a star's or a
  // polygon's centre): offsets from it are small where lines pass near it, and
  // the bounds' n.(p - origin) is short for a corner of the plan.
  double a = 0.0, b = 0.0, d = 0.0, ex = 0.0, ey = 0.0;
  for (std::size_t j = from; j < to; ++j) {
    a += planes.nx[j] * planes.nx[j];
    b += planes.nx[j] * planes.ny[j];
    d += planes.ny[j] * planes.ny[j];
    ex += planes.nx[j] * planes.c[j];
    ey += planes.ny[j] * planes.c[j];
  }
  const double det = a * d - b * b;
  if (std::isfinite(det) && det > 1e-9 * (a + d) * (a + d)) t.origin = {(d * ex - b * ey) / det, (a * ey - b * ex) / det};
  if (!std::isfinite(t.origin.x) || !std::isfinite(t.origin.y)) t.origin = glm::dvec2(0.0);

  std::vector<double> offset(m);  // c - n.origin, by position from `from`
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t g = from + j;
    offset[j] = planes.c[g] - (planes.nx[g] * t.origin.x + planes.ny[g] * t.origin.y);
    t.c_abs = std::max({t.c_abs, std::abs(planes.c[g]), std::abs(offset[j])});
    t.k_abs = std::max(t.k_abs, std::abs(planes.k[g]));
  }
  t.c_abs += std::abs(t.origin.x) + std::abs(t.origin.y);
  // A change of normal by dn moves a corner's distance by dn |p - origin|, a
  // change of offset by as much: split along whichever spreads the node's
  // bound more, for corners as far from the origin as the one asking.
  const double radius = glm::length(near - t.origin);
  const double reach = std::isfinite(radius) ? std::max(radius, 1e-300) : 1.0;

  std::vector<std::uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  const auto axis_value = [&](int axis, std::uint32_t j) {
    const std::size_t g = from + j;
    return axis == 0 ? planes.nx[g] * reach : axis == 1 ? planes.ny[g] * reach : offset[j];
  };
  t.nodes.push_back({0, 0, 0, 0, 0, 0, 0, 0, 0, static_cast<std::uint32_t>(m), kLeaf});
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const std::uint32_t lo = t.nodes[i].begin, hi = t.nodes[i].end;
    double box[3][2], kb[2] = {HUGE_VAL, -HUGE_VAL};
    for (auto& axis : box) axis[0] = HUGE_VAL, axis[1] = -HUGE_VAL;
    for (std::uint32_t s = lo; s < hi; ++s) {
      for (int axis = 0; axis < 3; ++axis) {
        const double value = axis == 0 ? planes.nx[from + order[s]] : axis == 1 ? planes.ny[from + order[s]]
                                                                                 : offset[order[s]];
        box[axis][0] = std::min(box[axis][0], value);
        box[axis][1] = std::max(box[axis][1], value);
      }
      kb[0] = std::min(kb[0], planes.k[from + order[s]]);
      kb[1] = std::max(kb[1], planes.k[from + order[s]]);
    }
    Node& node = t.nodes[i];
    node.nx_lo = box[0][0], node.nx_hi = box[0][1];
    node.ny_lo = box[1][0], node.ny_hi = box[1][1];
    node.c_lo = box[2][0], node.c_hi = box[2][1];
    node.k_lo = kb[0], node.k_hi = kb[1];
    if (hi - lo <= kLeafMost) continue;
    const double spread[3] = {(box[0][1] - box[0][0]) * reach, (box[1][1] - box[1][0]) * reach,
                              box[2][1] - box[2][0]};
    const int axis = static_cast<int>(std::max_element(spread, spread + 3) - spread);
    const std::uint32_t mid = lo + (hi - lo) / 2;
    std::nth_element(order.begin() + lo, order.begin() + mid, order.begin() + hi,
                     [&](std::uint32_t x, std::uint32_t y) { return axis_value(axis, x) < axis_value(axis, y); });
    t.nodes[i].left = static_cast<std::int32_t>(t.nodes.size());
    t.nodes.push_back({0, 0, 0, 0, 0, 0, 0, 0, lo, mid, kLeaf});
    t.nodes.push_back({0, 0, 0, 0, 0, 0, 0, 0, mid, hi, kLeaf});
  }
  t.nx.resize(m);
  t.ny.resize(m);
  t.k.resize(m);
  t.c.resize(m);
  t.edge.resize(m);
  t.index.resize(m);
  for (std::size_t s = 0; s < m; ++s) {
    const std::size_t g = from + order[s];
    t.nx[s] = planes.nx[g];
    t.ny[s] = planes.ny[g];
    t.k[s] = planes.k[g];
    t.c[s] = planes.c[g];
    t.edge[s] = planes.edge[g];
    t.index[s] = static_cast<std::uint32_t>(g);
  }
  return t;
}

void PlaneIndex::extend(const Planes& planes, std::size_t size, glm::dvec2 near) {
  if (size < indexed_ + kTreeLeast) return;
  trees_.push_back(build(planes, indexed_, size, near));
  indexed_ = size;
  // Each tree about twice the next: a plane is rebuilt into O(log n) trees,
  // and a search starts from O(log n) roots.
  while (trees_.size() >= 2) {
    const Tree& last = trees_.back();
    const Tree& before = trees_[trees_.size() - 2];
    if (before.to - before.from >= 2 * (last.to - last.from)) break;
    Tree merged = build(planes, before.from, last.to, near);
    trees_.pop_back();
    trees_.back() = std::move(merged);
  }
}

std::pair<double, double> PlaneIndex::rates(const Tree& t, const Node& n, const Query& q) {
  double vx_lo, vx_hi, vy_lo, vy_hi;
  scaled(n.nx_lo, n.nx_hi, q.v.x, vx_lo, vx_hi);
  scaled(n.ny_lo, n.ny_hi, q.v.y, vy_lo, vy_hi);
  const double slack = kSlack * (std::abs(q.v.x) + std::abs(q.v.y) + t.k_abs);
  return {vx_lo + vy_lo - n.k_hi - slack, vx_hi + vy_hi - n.k_lo + slack};
}

double PlaneIndex::bound(const Tree& t, const Node& n, const Query& q, double h0) {
  // The corner's signed distance to a plane's line, n.(p - origin) - c' - k z,
  // and the rate it changes at, n.v - k, over the node's ranges.
  const glm::dvec2 r = q.p - t.origin;
  double ax_lo, ax_hi, ay_lo, ay_hi, kz_lo, kz_hi;
  scaled(n.nx_lo, n.nx_hi, r.x, ax_lo, ax_hi);
  scaled(n.ny_lo, n.ny_hi, r.y, ay_lo, ay_hi);
  scaled(n.k_lo, n.k_hi, q.z, kz_lo, kz_hi);
  const double slack_d =
      kSlack * (std::abs(q.p.x) + std::abs(q.p.y) + std::abs(r.x) + std::abs(r.y) + t.c_abs + t.k_abs * std::abs(q.z));
  const double d_lo = ax_lo + ay_lo - n.c_hi - kz_hi - slack_d;
  const double d_hi = ax_hi + ay_hi - n.c_lo - kz_lo + slack_d;
  const auto [r_lo, r_hi] = rates(t, n, q);
  // Coefficients not all finite bound nothing: such a node is visited first.
  if (std::isnan(d_lo + d_hi + r_lo + r_hi)) return -HUGE_VAL;
  // Planes of one direction and slope (the collinear edges of a grid plan)
  // approach the corner at one rate, which the ranges above only bound: the
  // rate itself, worked out as meeting_heights does to the bit, tells whether
  // any of them can meet it. A comb's reflex corners run along the line of
  // every edge between its teeth; bounded, those nodes kept the search from
  // ever passing them.
  if (n.nx_lo == n.nx_hi && n.ny_lo == n.ny_hi && n.k_lo == n.k_hi) {
    const double rate = n.nx_lo * q.v.x + n.ny_lo * q.v.y - n.k_lo;
    if (!(rate < 0.0 || (rate > 0.0 && q.outward))) return HUGE_VAL;
  }
  // A list worked out again skips the nodes it has queued every meeting of:
  // from inside only, each at most d_hi / -r_hi above z.
  if (q.after.edge >= 0 && !q.outward && r_hi < 0.0) {
    const double highest = q.z + std::max(d_hi, 0.0) / -r_hi * (1.0 + 1e-9) + kSlack * std::abs(q.z);
    if (highest < std::max(q.after.at, q.z)) return HUGE_VAL;
    // Or seen from where the corner is at the last queued: every line
    // already behind it there was met below.
    if (q.after.at > q.z) {
      const double a_hi = distance_at(t, n, q, q.after.at).second;
      if (a_hi < 0.0) {
        const double met = q.after.at + a_hi / -r_lo;
        if (met + (met - q.z) * 1e-9 + kSlack * std::abs(q.after.at) < q.after.at) return HUGE_VAL;
      }
    }
  }
  // The meeting's height above z is d / -rate: from inside (rate < 0) at
  // least d_lo / -r_lo, from outside (rate > 0, d < 0) at least -d_hi / r_hi.
  // No lower than `earliest` either: a plane the corner is already past by
  // more than that (most lines of a polygon, which run on beyond their
  // edges) never meets it.
  const double past = (q.z - q.earliest + kSlack * std::abs(q.z)) * (1.0 + 1e-9);
  double above = HUGE_VAL;
  if (r_lo < 0.0 && d_hi >= -past * -r_lo) above = std::min(above, d_lo > 0.0 ? d_lo / -r_lo : 0.0);
  if (q.outward && r_hi > 0.0 && d_lo <= past * r_hi) above = std::min(above, d_hi < 0.0 ? -d_hi / r_hi : 0.0);
  if (above == HUGE_VAL) return HUGE_VAL;
  // Less the rounding of the division and the sum.
  const double lowest = q.z + above * (1.0 - 1e-9) - kSlack * std::abs(q.z);
  const double nearer = h0 > q.z ? std::max(lowest, bound_from(t, n, q, h0, r_lo, r_hi)) : lowest;
  return above > 0.0 && nearer > q.cap ? HUGE_VAL : nearer;
}

std::pair<double, double> PlaneIndex::distance_at(const Tree& t, const Node& n, const Query& q, double h0) {
  const double dz = h0 - q.z;
  const glm::dvec2 r0 = q.p + q.v * dz - t.origin;
  double ax_lo, ax_hi, ay_lo, ay_hi, kz_lo, kz_hi;
  scaled(n.nx_lo, n.nx_hi, r0.x, ax_lo, ax_hi);
  scaled(n.ny_lo, n.ny_hi, r0.y, ay_lo, ay_hi);
  scaled(n.k_lo, n.k_hi, h0, kz_lo, kz_hi);
  // Rounding of r0 and of the sums here, and of meeting_heights' distance at
  // z, which this one equals in exact arithmetic.
  const double slack = kSlack * (std::abs(q.p.x) + std::abs(q.p.y) + (std::abs(q.v.x) + std::abs(q.v.y)) * dz +
                                 std::abs(t.origin.x) + std::abs(t.origin.y) + std::abs(r0.x) + std::abs(r0.y) +
                                 t.c_abs + t.k_abs * (std::abs(q.z) + std::abs(h0)));
  return {ax_lo + ay_lo - n.c_hi - kz_hi - slack, ax_hi + ay_hi - n.c_lo - kz_lo + slack};
}

double PlaneIndex::bound_from(const Tree& t, const Node& n, const Query& q, double h0, double r_lo, double r_hi) {
  const double dz = h0 - q.z;
  const auto [d_lo, d_hi] = distance_at(t, n, q, h0);
  if (std::isnan(d_lo + d_hi)) return -HUGE_VAL;
  // From inside every plane still ahead of the corner at h0 (d_lo >= 0)
  // meets it no lower than the fastest approach gives; from outside, every
  // plane still behind (d_hi <= 0). A plane that may have been met by h0
  // bounds nothing here.
  double above = HUGE_VAL;
  if (r_lo < 0.0) above = d_lo >= 0.0 ? dz + d_lo / -r_lo : -HUGE_VAL;
  if (q.outward && r_hi > 0.0) above = std::min(above, d_hi <= 0.0 ? dz - d_hi / r_hi : -HUGE_VAL);
  if (above == -HUGE_VAL || above == HUGE_VAL) return -HUGE_VAL;
  return q.z + above * (1.0 - 1e-9) - kSlack * std::abs(q.z);
}

std::optional<std::size_t> PlaneIndex::lowest(const Planes& planes, const Query& q, std::size_t hold,
                                              std::vector<Meeting>& out, std::vector<Meeting>& within,
                                              Scratch& scratch) {
  out.clear();
  within.clear();
  ++searches_;
  std::size_t tested = 0;
  const MeetingEarlier earlier{q.z};
  const bool after = q.after.edge >= 0;
  std::size_t worked = 0;
  // `out` is a heap whose front is the highest held.
  const auto consider = [&](double at, int edge) {
    ++worked;
    const Meeting s{at, edge};
    if (after && !earlier(q.after, s)) return;
    if (std::max(at, q.z) <= q.through) {
      within.push_back(s);
      return;
    }
    if (out.size() < hold) {
      out.push_back(s);
      std::push_heap(out.begin(), out.end(), earlier);
    } else if (earlier(s, out.front())) {
      std::pop_heap(out.begin(), out.end(), earlier);
      out.back() = s;
      std::push_heap(out.begin(), out.end(), earlier);
    }
  };
  const auto test = [&](const double* nx, const double* ny, const double* k, const double* c, std::size_t n) {
    scratch.meet.resize(n);
    meeting_heights(nx, ny, k, c, n, q, scratch.meet.data());
  };
  if (q.size > indexed_) {
    const std::size_t n = q.size - indexed_;
    test(planes.nx + indexed_, planes.ny + indexed_, planes.k + indexed_, planes.c + indexed_, n);
    for (std::size_t j = 0; j < n; ++j)
      if (scratch.meet[j] != HUGE_VAL) consider(scratch.meet[j], planes.edge[indexed_ + j]);
  }
  // Nodes to visit, lowest bound first (a min-heap).
  auto& open = scratch.open;
  open.clear();
  const auto later = [](const auto& x, const auto& y) { return x.first > y.first; };
  const auto push = [&](std::size_t tree, std::int32_t node, double h0) {
    const double b = bound(trees_[tree], trees_[tree].nodes[node], q, h0);
    if (b == HUGE_VAL) return;
    open.push_back({b, (static_cast<std::uint64_t>(tree) << 32) | static_cast<std::uint32_t>(node)});
    std::push_heap(open.begin(), open.end(), later);
  };
  for (std::size_t i = 0; i < trees_.size(); ++i)
    if (trees_[i].from < q.size) push(i, 0, q.z);
  while (!open.empty()) {
    const auto [b, id] = open.front();
    // Every meeting left is queued at or above b: those held are the lowest
    // once b is past the highest of them (at b itself, a lower edge may wait),
    // which is above q.through.
    const double top = out.size() == hold ? std::max(out.front().at, q.z) : HUGE_VAL;
    if (b > top) break;
    std::pop_heap(open.begin(), open.end(), later);
    open.pop_back();
    const Tree& t = trees_[id >> 32];
    const Node& node = t.nodes[id & 0xffffffffu];
    // Bounded again from where the corner is at the highest held meeting:
    // lines through a star's centre all pass near the corner there, however
    // their normals differ, where from the corner's own place they did not.
    // The bound from the corner's own place is b, no higher than top (or
    // -HUGE_VAL: coefficients not all finite, which bound nothing).
    if (top != HUGE_VAL && top > q.z && b != -HUGE_VAL) {
      const auto [r_lo, r_hi] = rates(t, node, q);
      if (bound_from(t, node, q, top, r_lo, r_hi) > top) continue;
    }
    if (node.left != kLeaf) {
      const double h0 = top != HUGE_VAL ? top : b;
      push(id >> 32, node.left, h0);
      push(id >> 32, node.left + 1, h0);
      continue;
    }
    const std::size_t n = node.end - node.begin;
    tested += n;
    if (tested > std::max(q.size / kGiveUpPast, kGiveUpLeast) + within.size()) {
      ++given_up_;
      // Not searched again: its trees would only hold memory (as much as the
      // planes again, for as long as any list of the set lives).
      if (!worth_searching()) trees_ = {};
      return std::nullopt;
    }
    test(t.nx.data() + node.begin, t.ny.data() + node.begin, t.k.data() + node.begin, t.c.data() + node.begin, n);
    for (std::size_t j = 0; j < n; ++j)
      if (scratch.meet[j] != HUGE_VAL && t.index[node.begin + j] < q.size)
        consider(scratch.meet[j], t.edge[node.begin + j]);
  }
  return worked;
}

}  // namespace procex::engine

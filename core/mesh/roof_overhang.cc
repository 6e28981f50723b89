#include "core/mesh/roof_overhang.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <numeric>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/geom/convex_clip.h"
#include "core/geom/cross.h"
#include "core/geom/error.h"
#include "core/geom/nesting.h"
#include "core/geom/polygon3.h"
#include "core/geom/tolerances.h"

namespace procex {
namespace {

using Polygon = std::vector<glm::dvec2>;

// A roof plane as a height over the plan.
struct Plane {
  glm::dvec2 slope;
  double height;
  double z(glm::dvec2 p) const { return glm::dot(slope, p) + height; }
  // The plane moved t along its upward unit normal.
  Plane raised(double t) const { return {slope, height + t * std::sqrt(1 + glm::dot(slope, slope))}; }
};

std::string text(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string text(glm::dvec3 p) { return "(" + text(p.x) + ", " + text(p.y) + ", " + text(p.z) + ")"; }

void check_size(double v, const char* name, bool zero_allowed) {
  if (std::isfinite(v) && (v > 0 || (zero_allowed && v == 0))) return;
  throw InputError(std::string(name) + " must be a finite number " + (zero_allowed ? "of 0 or more" : "above 0") +
                   ", not " + text(v));
}

// Where the lines na . x = ba and nb . x = bb meet (Cramer's rule).
glm::dvec2 lines_meet(glm::dvec2 na, double ba, glm::dvec2 nb, double bb) {
  return glm::dvec2(ba * nb.y - na.y * bb, na.x * bb - ba * nb.x) / cross(na, nb);
}

// Andrew's monotone chain, counter-clockwise, leaving out points within
// `tolerance` of the line through their neighbours.
Polygon convex_hull(Polygon points, double tolerance) {
  std::sort(points.begin(), points.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  Polygon hull(2 * points.size());
  std::size_t k = 0;
  const auto turns_left = [&](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return cross(a - o, b - o) > tolerance * glm::length(b - o);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && !turns_left(hull[k - 2], hull[k - 1], points[i])) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && !turns_left(hull[k - 2], hull[k - 1], points[i])) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Narrower than `width` everywhere: nothing a face should be made of.
bool thin(const Polygon& p, double width) {
  double longest = 0;
  for (std::size_t i = 0; i < p.size(); ++i) longest = std::max(longest, glm::length(p[(i + 1) % p.size()] - p[i]));
  return p.size() < 3 || std::abs(twice_signed_area(p)) <= width * longest;
}

// The part of `region` where planes[i] is the lowest (to within `margin` in plan).
Polygon lowest(const Polygon& region, const std::vector<Plane>& planes, std::size_t i, double margin) {
  Polygon r = region;
  for (std::size_t j = 0; j < planes.size() && !r.empty(); ++j)
    if (j != i) r = clip_to_half_plane(r, planes[j].slope - planes[i].slope, planes[j].height - planes[i].height, margin);
  return r;
}

double lowest_z(const std::vector<Plane>& planes, glm::dvec2 p) {
  double z = HUGE_VAL;
  for (const Plane& q : planes) z = std::min(z, q.z(p));
  return z;
}

struct Face {
  std::vector<glm::dvec3> points;
  const char* tag;
};

// The faces as one surface, points closer than `distance` made one vertex;
// faces left with fewer than three corners are dropped (their edges cancel).
// `kept`, if given, receives the index in `faces` of each face kept.
Surface weld(const std::vector<Face>& faces, double distance, std::vector<std::size_t>* kept = nullptr) {
  std::vector<glm::dvec3> points;
  for (const Face& f : faces) points.insert(points.end(), f.points.begin(), f.points.end());
  std::vector<std::size_t> order(points.size()), root(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::iota(root.begin(), root.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points[a].x < points[b].x; });
  const auto find = [&](std::size_t a) {
    while (root[a] != a) a = root[a] = root[root[a]];
    return a;
  };
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && points[order[j]].x - points[order[i]].x <= distance; ++j) {
      const glm::dvec3 d = glm::abs(points[order[j]] - points[order[i]]);
      if (d.y <= distance && d.z <= distance) {
        const std::size_t a = find(order[i]), b = find(order[j]);
        root[std::max(a, b)] = std::min(a, b);
      }
    }
  Surface s;
  std::vector<std::uint32_t> vertex(points.size(), UINT32_MAX);
  std::size_t next = 0;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const Face& f = faces[k];
    std::vector<std::uint32_t> loop;
    for (std::size_t i = 0; i < f.points.size(); ++i, ++next) {
      const std::size_t r = find(next);
      if (vertex[r] == UINT32_MAX) {
        vertex[r] = static_cast<std::uint32_t>(s.vertices.size());
        s.vertices.push_back(points[r]);
      }
      if (loop.empty() || loop.back() != vertex[r]) loop.push_back(vertex[r]);
    }
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    if (loop.size() < 3) continue;
    s.faces.push_back({FaceKind::Side, -1, {std::move(loop)}, f.tag});
    if (kept) kept->push_back(k);
  }
  return s;
}


bool same_plane(const Plane& a, const Plane& b, glm::dvec2 at, double extent, double tolerance) {
  return std::abs(a.z(at) - b.z(at)) <= tolerance && glm::length(a.slope - b.slope) * extent <= tolerance;
}

// The point nearest `from` that meets each row's a . x = b (a of unit
// length): the rows independent of those before them met exactly (their
// directions made orthonormal one by one), and the largest amount by which
// any row is missed, as where more planes meet than a point needs.
std::pair<glm::dvec3, double> nearest_meeting(const std::vector<std::pair<glm::dvec3, double>>& rows, glm::dvec3 from) {
  std::vector<glm::dvec3> basis;
  glm::dvec3 x = from;
  for (const auto& [a, b] : rows) {
    glm::dvec3 q = a;
    for (const glm::dvec3& e : basis) q -= glm::dot(q, e) * e;
    const double length = glm::length(q);
    if (basis.size() == 3 || length <= 1e-9) continue;
    // Moving along q alone keeps the rows met so far and meets this one.
    x += (b - glm::dot(a, x)) / length * (q / length);
    basis.push_back(q / length);
  }
  double missed = 0;
  for (const auto& [a, b] : rows) missed = std::max(missed, std::abs(glm::dot(a, x) - b));
  return {x, missed};
}

bool segments_cross(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d, double margin) {
  const auto side = [&](glm::dvec2 o, glm::dvec2 e, glm::dvec2 p) {
    const double s = cross(e - o, p - o) / std::max(glm::length(e - o), 1e-300);
    return s > margin ? 1 : s < -margin ? -1 : 0;
  };
  return side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
}

// A roof with valleys, run out face by face. Past each edge of its outline
// the face over that edge carries on out to the edge's line moved out by its
// reach; where two faces meet on the outline, the crease between them (a
// hip, a valley, a ridge at a gable) runs on straight to the outer line, as a
// skeleton of the outline run out would have it. The top is that surface
// with every face moved up along its normal by the thickness, each corner
// where its planes (and the fascia's) meet again. The slab keeps its faces
// and corners: where thickening would turn a face inside out, or planes that
// met at one corner no longer do, it is refused.
Surface roof_with_valleys(const std::vector<std::vector<glm::dvec3>>& roof, const std::vector<Plane>& face_planes,
                          const RoofOverhang& o, double extent, double tolerance, double weld_distance) {
  std::vector<Face> in;
  for (const auto& f : roof) in.push_back({f, "underside"});
  std::vector<std::size_t> kept;
  const Surface r = weld(in, weld_distance, &kept);
  const auto plan = [&](std::uint32_t v) { return glm::dvec2(r.vertices[v].x, r.vertices[v].y); };
  // Directed edges: each shared by two faces running opposite ways, or on the outline.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edge_face;
  std::vector<std::set<std::size_t>> faces_at(r.vertices.size());
  for (std::size_t f = 0; f < r.faces.size(); ++f) {
    const auto& loop = r.faces[f].loops[0];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      faces_at[loop[i]].insert(f);
      if (!edge_face.insert({{loop[i], loop[(i + 1) % loop.size()]}, f}).second)
        throw InputError("two roof faces overlap along the edge from " + text(r.vertices[loop[i]]) +
                         ": the roof must be one surface seen from above");
    }
  }
  std::map<std::uint32_t, std::pair<std::uint32_t, std::size_t>> outline_next;  // vertex -> (next, face)
  for (const auto& [e, f] : edge_face)
    if (!edge_face.count({e.second, e.first}) && !outline_next.insert({e.first, {e.second, f}}).second)
      throw InputError("the roof's outline touches itself at " + text(r.vertices[e.first]) +
                       ": run out parts that meet only at a corner separately");

  struct Side {
    glm::dvec2 a, u, n;  // a point on it, along it, outward
    double reach;
  };
  struct Loop {
    std::vector<std::uint32_t> v;      // outline corners, the roof on their left
    std::vector<std::size_t> face;     // the face over v[i] -> v[i + 1]
    std::vector<std::size_t> side_of;  // the side v[i] -> v[i + 1] lies on
    std::vector<Side> sides;
    std::vector<glm::dvec2> miter;     // where side s's outer line meets side s + 1's
    std::vector<glm::dvec2> outer;     // the outline run out, in order
  };
  std::vector<Loop> loops;
  std::set<std::uint32_t> done;
  for (const auto& [start, unused] : outline_next) {
    if (done.count(start)) continue;
    Loop l;
    for (std::uint32_t v = start; done.insert(v).second;) {
      const auto it = outline_next.find(v);
      if (it == outline_next.end())
        throw InputError("the roof's outline is broken at " + text(r.vertices[v]) + ": its faces must meet edge to edge");
      if (glm::length(plan(it->second.first) - plan(v)) <= weld_distance)
        throw InputError("the roof's outline rises straight up at " + text(r.vertices[v]) +
                         ": a wall rises through the roof there, and only a roof that is one surface seen from above "
                         "can be run out");
      l.v.push_back(v), l.face.push_back(it->second.second);
      v = it->second.first;
    }
    const std::size_t n = l.v.size();
    // Sides: runs of edges along one line, starting after a turn.
    const auto turns = [&](std::size_t i) {  // at v[i]
      const glm::dvec2 a = plan(l.v[(i + n - 1) % n]), b = plan(l.v[i]), c = plan(l.v[(i + 1) % n]);
      return glm::dot(b - a, c - b) <= 0 || std::abs(cross(glm::normalize(c - a), b - a)) > tolerance;
    };
    std::size_t first = 0;
    while (first < n && !turns(first)) ++first;
    if (first == n) throw InputError("the roof's outline at " + text(r.vertices[l.v[0]]) + " encloses no area");
    std::rotate(l.v.begin(), l.v.begin() + first, l.v.end());
    std::rotate(l.face.begin(), l.face.begin() + first, l.face.end());
    l.side_of.resize(n);
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i + 1;
      while (j < n && !turns(j)) ++j;
      double low = HUGE_VAL, high = -HUGE_VAL;
      for (std::size_t k = i; k <= j; ++k) low = std::min(low, r.vertices[l.v[k % n]].z), high = std::max(high, r.vertices[l.v[k % n]].z);
      const glm::dvec2 u = glm::normalize(plan(l.v[j % n]) - plan(l.v[i]));
      l.sides.push_back({plan(l.v[i]), u, {u.y, -u.x}, high - low <= tolerance ? o.eave : o.verge});
      for (std::size_t k = i; k < j; ++k) l.side_of[k] = l.sides.size() - 1;
      i = j;
    }
    const std::size_t sides = l.sides.size();
    for (std::size_t s = 0; s < sides; ++s) {
      const Side &p = l.sides[s], &q = l.sides[(s + 1) % sides];
      const double det = cross(p.n, q.n);
      if (std::abs(det) <= 1e-9)
        throw InputError("the roof's outline doubles back at " + text(glm::dvec3(q.a, 0)) + ": a wall rises through the roof there (a gable inside its outline?), and only a roof that is one surface seen from above can be run out");
      l.miter.push_back(lines_meet(p.n, glm::dot(p.n, p.a) + p.reach, q.n, glm::dot(q.n, q.a) + q.reach));
    }
    loops.push_back(std::move(l));
  }

  // Past each outline edge, a cell of its face's plane; where faces change
  // on the outline, the crease between them runs out to where it leaves the
  // run-out outline (the first outer line it meets at an outward corner, the
  // second at an inward one).
  std::vector<Face> under;
  std::vector<std::size_t> under_plane;
  for (std::size_t f = 0; f < r.faces.size(); ++f) {
    Face face{{}, "underside"};
    for (std::uint32_t v : r.faces[f].loops[0]) face.points.push_back(r.vertices[v]);
    under.push_back(std::move(face)), under_plane.push_back(kept[f]);
  }
  for (Loop& l : loops) {
    const std::size_t n = l.v.size();
    // At each corner v[i]: the points the outline run out passes there, and
    // whether the cell before v[i] ends at the last of them (else the first).
    std::vector<std::vector<glm::dvec2>> chain(n);
    std::vector<bool> before_takes_all(n, false);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t prev = (i + n - 1) % n;
      const Side &sp = l.sides[l.side_of[prev]], &sn = l.sides[l.side_of[i]];
      const bool corner = l.side_of[prev] != l.side_of[i];
      const glm::dvec2 v = plan(l.v[i]);
      const glm::dvec2 foot = corner ? l.miter[l.side_of[prev]] : v + sn.reach * sn.n;
      const Plane &p = face_planes[kept[l.face[prev]]], &q = face_planes[kept[l.face[i]]];
      if (same_plane(p, q, v, extent, tolerance)) {
        chain[i] = {foot};
        continue;
      }
      for (std::size_t f : faces_at[l.v[i]])
        if (!same_plane(face_planes[kept[f]], p, v, extent, tolerance) && !same_plane(face_planes[kept[f]], q, v, extent, tolerance))
          throw InputError("more than two roof planes meet on the roof's outline at " + text(r.vertices[l.v[i]]) +
                           ": there is no one crease to run out past the walls there");
      glm::dvec2 d = glm::normalize(glm::dvec2(-(p.slope - q.slope).y, (p.slope - q.slope).x));
      if (glm::dot(d, sp.n) + glm::dot(d, sn.n) < 0) d = -d;
      const double dp = glm::dot(d, sp.n), dn = glm::dot(d, sn.n);
      if (dp <= 1e-9 || dn <= 1e-9)
        throw InputError("the crease between two roof faces at " + text(r.vertices[l.v[i]]) +
                         " runs along the wall, not out past it: it cannot be run out");
      const double tp = sp.reach / dp, tn = sn.reach / dn;
      if (!corner || std::abs(tp - tn) <= weld_distance) {
        chain[i] = {corner ? foot : v + tp * d};
        continue;
      }
      const bool outward = cross(sp.u, sn.u) > 0;
      const bool leaves_by_prev = outward == (tp < tn);
      if (leaves_by_prev) {
        chain[i] = {v + tp * d, foot};
      } else {
        chain[i] = {foot, v + tn * d};
        before_takes_all[i] = true;
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      l.outer.insert(l.outer.end(), chain[i].begin(), chain[i].end());
      const std::size_t j = (i + 1) % n;
      Polygon cell = before_takes_all[i] ? Polygon{chain[i].back()} : chain[i];
      if (before_takes_all[j]) cell.insert(cell.end(), chain[j].begin(), chain[j].end());
      else cell.push_back(chain[j].front());
      const Plane& plane = face_planes[kept[l.face[i]]];
      Face face{{}, "soffit"};
      for (glm::dvec2 c : cell) face.points.push_back({c.x, c.y, plane.z(c)});
      cell.push_back(plan(l.v[j])), cell.push_back(plan(l.v[i]));
      if (thin(cell, weld_distance)) continue;  // a flush side
      face.points.push_back(r.vertices[l.v[j]]), face.points.push_back(r.vertices[l.v[i]]);
      under.push_back(std::move(face)), under_plane.push_back(kept[l.face[i]]);
    }
    // The outline run out must go forwards along each side.
    for (std::size_t k = 0; k < l.outer.size(); ++k) {
      const glm::dvec2 a = l.outer[k], b = l.outer[(k + 1) % l.outer.size()];
      if (glm::length(b - a) <= weld_distance) continue;
      const bool forwards = std::any_of(l.sides.begin(), l.sides.end(), [&](const Side& s) {
        const auto on = [&](glm::dvec2 x) { return std::abs(glm::dot(s.n, x - s.a) - s.reach) <= 4 * weld_distance; };
        return on(a) && on(b) && glm::dot(b - a, s.u) > 0;
      });
      if (!forwards)
        throw InputError("run out by the eave (" + text(o.eave) + " m) and verge (" + text(o.verge) + " m), the roof's edge near " +
                         text(glm::dvec3(a, 0)) + " would fold over itself: the overhang is too wide for the walls there");
    }
  }
  // No two parts of the run-out outline may cross (two wings' overhangs meeting, a courtyard closed up).
  for (std::size_t la = 0; la < loops.size(); ++la)
    for (std::size_t lb = la; lb < loops.size(); ++lb) {
      const auto &A = loops[la].outer, &B = loops[lb].outer;
      for (std::size_t i = 0; i < A.size(); ++i)
        for (std::size_t j = la == lb ? i + 2 : 0; j < B.size(); ++j) {
          if (la == lb && i == 0 && j == B.size() - 1) continue;
          if (segments_cross(A[i], A[(i + 1) % A.size()], B[j], B[(j + 1) % B.size()], weld_distance))
            throw InputError("run out by the eave (" + text(o.eave) + " m) and verge (" + text(o.verge) +
                             " m), the overhang near " + text(glm::dvec3(A[i], 0)) +
                             " would run into another part of it: make the overhang narrower");
        }
    }

  std::vector<std::size_t> under_kept;
  const Surface u = weld(under, weld_distance, &under_kept);
  // Each corner of the underside moved to where its planes, raised by the
  // thickness, meet again (and the fascia's, on the outer edge).
  std::vector<std::vector<std::size_t>> planes_at(u.vertices.size());
  for (std::size_t f = 0; f < u.faces.size(); ++f)
    for (std::uint32_t v : u.faces[f].loops[0]) planes_at[v].push_back(under_plane[under_kept[f]]);
  std::vector<std::vector<std::pair<double, std::uint32_t>>> along;  // per side: (distance along, vertex)
  std::vector<std::size_t> first_side;
  for (const Loop& l : loops) first_side.push_back(along.size()), along.resize(along.size() + l.sides.size());
  std::vector<glm::dvec3> top(u.vertices.size());
  for (std::uint32_t v = 0; v < u.vertices.size(); ++v) {
    const glm::dvec3 x = u.vertices[v];
    std::vector<std::pair<glm::dvec3, double>> rows;
    std::vector<std::size_t> distinct;
    for (std::size_t pi : planes_at[v]) {
      const Plane& p = face_planes[pi];
      if (std::any_of(distinct.begin(), distinct.end(), [&](std::size_t q) { return same_plane(face_planes[q], p, {x.x, x.y}, extent, tolerance); }))
        continue;
      distinct.push_back(pi);
      const Plane raised = p.raised(o.thickness);
      const glm::dvec3 a(-p.slope.x, -p.slope.y, 1);
      rows.push_back({a / glm::length(a), raised.height / glm::length(a)});
    }
    for (std::size_t li = 0; li < loops.size(); ++li) {
      const Loop& l = loops[li];
      for (std::size_t s = 0; s < l.sides.size(); ++s) {
        const Side& side = l.sides[s];
        const glm::dvec2 from = l.miter[(s + l.sides.size() - 1) % l.sides.size()], to = l.miter[s];
        const double at = glm::dot(glm::dvec2(x.x, x.y) - from, side.u), length = glm::dot(to - from, side.u);
        if (std::abs(glm::dot(side.n, glm::dvec2(x.x, x.y) - side.a) - side.reach) > 4 * weld_distance ||
            at < -4 * weld_distance || at > length + 4 * weld_distance)
          continue;
        along[first_side[li] + s].push_back({at, v});
        rows.push_back({{side.n.x, side.n.y, 0}, glm::dot(side.n, side.a) + side.reach});
      }
    }
    const auto [point, missed] = nearest_meeting(rows, x);
    if (!(missed <= tolerance))
      throw InputError("the roof's planes meeting at " + text(x) + " no longer meet at one point when raised by the thickness (" +
                       text(o.thickness) + " m): give the faces there one pitch, or make the slab thinner");
    top[v] = point;
  }

  std::vector<Face> faces;
  for (std::size_t f = 0; f < u.faces.size(); ++f) {
    const auto& loop = u.faces[f].loops[0];
    Face bottom{{}, u.faces[f].tag == "soffit" ? "soffit" : "underside"}, up{{}, "roof"};
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      const glm::dvec3 e = u.vertices[b] - u.vertices[a];
      if (glm::dot(top[b] - top[a], e) <= weld_distance * glm::length(e))
        throw InputError("the slab is too thick (" + text(o.thickness) + " m) for the roof near " + text(u.vertices[a]) + " to " + text(u.vertices[b]) +
                         ": raised by it, a face there would turn inside out; make the slab thinner");
      bottom.points.push_back(u.vertices[a]), up.points.push_back(top[a]);
    }
    std::reverse(bottom.points.begin(), bottom.points.end());
    faces.push_back(std::move(bottom)), faces.push_back(std::move(up));
  }
  for (auto& side : along) {
    if (side.size() < 2) continue;
    std::sort(side.begin(), side.end());
    Face f{{}, "fascia"};
    for (const auto& [at, v] : side) f.points.push_back(u.vertices[v]);
    for (auto it = side.rbegin(); it != side.rend(); ++it) f.points.push_back(top[it->second]);
    faces.push_back(std::move(f));
  }
  return weld(faces, weld_distance);
}

}  // namespace

Surface roof_overhang(const std::vector<std::vector<glm::dvec3>>& roof, const RoofOverhang& o) {
  check_size(o.eave, "eave", true);
  check_size(o.verge, "verge", true);
  check_size(o.thickness, "thickness", false);
  if (roof.empty()) throw InputError("there is no roof to run past the walls");
  glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (std::size_t f = 0; f < roof.size(); ++f)
    for (const glm::dvec3& p : roof[f]) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InputError("roof face " + std::to_string(f) + " has a point that is not finite");
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
  const double extent = glm::length(hi - lo);
  for (const auto& [v, name] : {std::pair{o.eave, "eave"}, {o.verge, "verge"}, {o.thickness, "thickness"}})
    if (v > 100 * extent)
      throw InputError(std::string(name) + " (" + text(v) + " m) is more than 100 times the roof's extent (" +
                       text(extent) + " m)");
  // Checks at the roof's scale; points made one at the slab's.
  const double tolerance = kMeshDistanceRelative * extent;
  const double weld_distance = kRoofWeldRelative * (extent + 2 * std::max(o.eave, o.verge) + o.thickness);

  std::vector<Plane> planes;
  Polygon plan;
  double plan_area = 0;  // of the faces, each seen from above
  for (std::size_t f = 0; f < roof.size(); ++f) {
    const std::vector<glm::dvec3>& face = roof[f];
    const glm::dvec3 n = face.size() >= 3 ? newell_normal(face) : glm::dvec3(0);
    const double length = glm::length(n);
    if (!(n.z > kRoofLeastUpward * length))
      throw InputError("roof face " + std::to_string(f) + (face.empty() ? std::string() : " at " + text(face[0])) +
                       (length == 0 ? " has no area" : " is vertical or faces down") +
                       ": only faces that look up can run past the walls (is a wall tagged as roof?)");
    plan_area += n.z / 2;
    glm::dvec3 centroid(0);
    for (const glm::dvec3& p : face) centroid += p / static_cast<double>(face.size()), plan.push_back({p.x, p.y});
    planes.push_back({{-n.x / n.z, -n.y / n.z}, glm::dot(n, centroid) / n.z});
  }
  // A roof is convex when no plane of it passes below a point of it; then
  // each face, planar and between its corners, is where its plane is the
  // lowest, and (checked next) covering its convex outline once, the roof is
  // the lowest of its planes there.
  for (const auto& face : roof)
    for (const glm::dvec3& p : face)
      if (lowest_z(planes, {p.x, p.y}) < p.z - tolerance)
        return roof_with_valleys(roof, planes, o, extent, tolerance, weld_distance);
  const Polygon hull = convex_hull(plan, tolerance);
  double perimeter = 0;
  for (std::size_t k = 0; k < hull.size(); ++k) perimeter += glm::length(hull[(k + 1) % hull.size()] - hull[k]);
  const double hull_area = hull.size() >= 3 ? twice_signed_area(hull) / 2 : 0.0;
  if (hull.size() < 3 || std::abs(plan_area - hull_area) > tolerance * perimeter)
    throw InputError("the roof covers " + text(plan_area) + " m2 of its " + text(hull_area) +
                     " m2 outline seen from above: it must cover a convex outline once, with no gap (a courtyard, "
                     "a dormer, a flat part with another tag) and no overlap");
  // Faces in one plane (a face split round a hole) are one plane.
  std::vector<Plane> distinct;
  for (const Plane& p : planes)
    if (std::none_of(distinct.begin(), distinct.end(), [&](const Plane& q) {
          return std::all_of(hull.begin(), hull.end(), [&](glm::dvec2 c) { return std::abs(p.z(c) - q.z(c)) <= tolerance; });
        }))
      distinct.push_back(p);

  // Each side of the outline runs out by the eave if the roof's edge over it
  // is level, else (a gable's rake) by the verge.
  const std::size_t n = hull.size();
  std::vector<double> reach(n);
  std::vector<glm::dvec2> outward(n);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 a = hull[k], along = hull[(k + 1) % n] - a;
    const double length = glm::length(along);
    const glm::dvec2 u = along / length;
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (const auto& face : roof)
      for (const glm::dvec3& p : face) {
        const glm::dvec2 q = glm::dvec2(p.x, p.y) - a;
        if (std::abs(cross(u, q)) <= tolerance && glm::dot(u, q) >= -tolerance && glm::dot(u, q) <= length + tolerance)
          low = std::min(low, p.z), high = std::max(high, p.z);
      }
    reach[k] = high - low <= tolerance ? o.eave : o.verge;
    outward[k] = {u.y, -u.x};
  }
  // Corner k of the outline run out: on both neighbouring sides' lines moved out.
  Polygon outer(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = (k + n - 1) % n;
    outer[k] = hull[k] + lines_meet(outward[j], reach[j], outward[k], reach[k]);
  }

  std::vector<Face> faces;
  Polygon bottom_points, top_points;  // in plan, for the fascia
  const auto add = [&](const Polygon& cell, const Plane& plane, bool up, const char* tag, Polygon& seen) {
    Face f{{}, tag};
    for (glm::dvec2 p : cell) f.points.push_back({p.x, p.y, plane.z(p)});
    if (!up) std::reverse(f.points.begin(), f.points.end());
    faces.push_back(std::move(f));
    seen.insert(seen.end(), cell.begin(), cell.end());
  };
  // The underside: over the building, and over each side's band past the walls.
  std::vector<std::pair<Polygon, const char*>> windows{{hull, "underside"}};
  for (std::size_t k = 0; k < n; ++k)
    if (reach[k] > weld_distance) windows.push_back({{hull[k], outer[k], outer[(k + 1) % n], hull[(k + 1) % n]}, "soffit"});
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const Polygon region = lowest(outer, distinct, i, weld_distance);
    if (thin(region, weld_distance)) continue;
    for (const auto& [window, tag] : windows) {
      const Polygon cell = clip_to_convex(region, window, weld_distance);
      if (!thin(cell, weld_distance)) add(cell, distinct[i], false, tag, bottom_points);
    }
  }
  std::vector<Plane> top(distinct.size());
  std::transform(distinct.begin(), distinct.end(), top.begin(), [&](const Plane& p) { return p.raised(o.thickness); });
  for (std::size_t i = 0; i < top.size(); ++i) {
    const Polygon region = lowest(outer, top, i, weld_distance);
    if (!thin(region, weld_distance)) add(region, top[i], true, "roof", top_points);
  }
  // The fascia: each side of the run-out outline from the underside up to the
  // top, through every corner either has there.
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 a = outer[k], along = outer[(k + 1) % n] - a;
    const double length = glm::length(along);
    // The corners on this side, in order along it (those within the weld
    // distance of its ends are its ends).
    const auto on_side = [&](const Polygon& points) {
      std::vector<std::pair<double, glm::dvec2>> at{{0.0, a}, {length, outer[(k + 1) % n]}};
      for (glm::dvec2 p : points) {
        const double s = glm::dot(p - a, along) / length;
        if (std::abs(cross(along, p - a)) / length <= weld_distance && s > weld_distance && s < length - weld_distance)
          at.push_back({s, p});
      }
      std::sort(at.begin(), at.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      at.erase(std::unique(at.begin(), at.end(), [&](const auto& x, const auto& y) { return y.first - x.first <= weld_distance; }),
               at.end());
      return at;
    };
    Face f{{}, "fascia"};
    for (const auto& [s, p] : on_side(bottom_points)) f.points.push_back({p.x, p.y, lowest_z(distinct, p)});
    const auto up = on_side(top_points);
    for (auto it = up.rbegin(); it != up.rend(); ++it) f.points.push_back({it->second.x, it->second.y, lowest_z(top, it->second)});
    faces.push_back(std::move(f));
  }
  // The corners cut from the planes meet the roof's own corners only to
  // within the sweep's clustering (the planes are fitted to its faces), as
  // far as the checks above allow: they are made one at that distance.
  return weld(faces, tolerance);
}

}  // namespace procex

#include "core/mesh/roof_overhang.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/geom/convex_clip.h"
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

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

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
Surface weld(const std::vector<Face>& faces, double distance) {
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
  for (const Face& f : faces) {
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
    if (loop.size() >= 3) s.faces.push_back({FaceKind::Side, -1, {std::move(loop)}, f.tag});
  }
  return s;
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
        throw InputError("the roof is not convex at " + text(p) +
                         ": another of its planes passes below it, as over a valley; overhangs need a roof whose "
                         "creases are all ridges, hips or breaks of slope (a convex plan)");
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
    const glm::dvec2 a = outward[j], b = outward[k];
    outer[k] = hull[k] + glm::dvec2(reach[j] * b.y - a.y * reach[k], a.x * reach[k] - reach[j] * b.x) / cross(a, b);
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
  return weld(faces, weld_distance);
}

}  // namespace procex

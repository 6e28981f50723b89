#include "tests/support/roof_properties.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/geom/tolerances.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "tests/support/point_set.h"

namespace procex::testing {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr std::size_t kShown = 4;  // problems of one kind listed before they are only counted

struct Bounds {
  glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  double max_abs = 0.0;
  double diagonal() const { return glm::length(hi - lo); }
  void add(glm::dvec2 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    max_abs = std::max({max_abs, std::abs(p.x), std::abs(p.y)});
  }
  // What rounding of the largest coordinate may move a point by.
  double rounding() const { return 64.0 * std::numeric_limits<double>::epsilon() * max_abs; }
  // The validator's distance at clustering scale `relative` of the diagonal,
  // plus the rounding.
  double tolerance(double relative) const { return mesh_distance_relative(relative) * diagonal() + rounding(); }
};

Bounds bounds(const Footprint& fp) {
  Bounds b;
  for (const Loop& loop : fp.loops)
    for (const glm::dvec2& p : loop.points) b.add(p);
  return b;
}

struct EdgeLine {
  glm::dvec2 a, b;
  EdgeSpec spec;
  glm::dvec2 before{0.0}, after{0.0};  // the far ends of its neighbours: the previous edge's start, the next one's end
  // Distance of p from the edge's line, positive on the footprint's side (left).
  double inward(glm::dvec2 p) const {
    const glm::dvec2 d = b - a, q = p - a;
    return (d.x * q.y - d.y * q.x) / glm::length(d);
  }
  // Distance of p from the edge segment.
  double distance(glm::dvec2 p) const {
    const glm::dvec2 d = b - a;
    const double t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p - (a + t * d));
  }
};

// Neighbouring edges that run straight on (same direction, |sin| of the turn
// below 1e-9, or the corner off its neighbours' line by no more than the
// rounding of the coordinates) with different angles are the paper's ambiguous
// case (4.5): their planes meet only in the base line. The rule of the sweep's
// options picks one angle for the whole run: the steepest (smallest from
// vertical) to maximise the volume, the shallowest to minimise it. Runs holding
// a profiled edge keep their own angles (a profile's planes are checked
// segment by segment).
void resolve_straight_runs(std::vector<EdgeLine>& loop, Ambiguity rule, double rounding) {
  const std::size_t n = loop.size();
  const auto straight_into = [&](std::size_t j) {  // the corner at the start of edge j
    const EdgeLine &in = loop[(j + n - 1) % n], &out = loop[j];
    const glm::dvec2 a = glm::normalize(in.b - in.a), b = glm::normalize(out.b - out.a);
    const double sine = std::abs(a.x * b.y - a.y * b.x);
    const double shorter = std::min(glm::length(in.b - in.a), glm::length(out.b - out.a));
    return glm::dot(a, b) > 0.0 && (sine < 1e-9 || sine * shorter <= rounding);
  };
  std::size_t start = 0;
  while (start < n && straight_into(start)) ++start;
  if (start == n) return;
  for (std::size_t i = 0; i < n;) {
    std::size_t len = 1;
    while (i + len < n && straight_into((start + i + len) % n)) ++len;
    bool plain = true;
    double pick = loop[(start + i) % n].spec.angle_deg;
    for (std::size_t m = 0; m < len; ++m) {
      const EdgeSpec& s = loop[(start + i + m) % n].spec;
      plain = plain && s.profile < 0;
      pick = rule == Ambiguity::MaximizeVolume ? std::min(pick, s.angle_deg) : std::max(pick, s.angle_deg);
    }
    if (plain)
      for (std::size_t m = 0; m < len; ++m) loop[(start + i + m) % n].spec.angle_deg = pick;
    i += len;
  }
}

// Each edge's line and the angle its plane leans at.
std::map<std::int32_t, EdgeLine> edges_by_id(const Footprint& fp, Ambiguity rule) {
  const double rounding = bounds(fp).rounding();
  std::map<std::int32_t, EdgeLine> out;
  for (const Loop& loop : fp.loops) {
    std::vector<EdgeLine> lines;
    const std::size_t n = loop.points.size();
    for (std::size_t i = 0; i < n; ++i)
      lines.push_back({loop.points[i], loop.points[(i + 1) % n], loop.edges[i], loop.points[(i + n - 1) % n],
                       loop.points[(i + 2) % n]});
    resolve_straight_runs(lines, rule, rounding);
    for (const EdgeLine& e : lines) out[e.spec.id] = e;
  }
  return out;
}

// Counts problems of one kind, keeping the first few lines.
class Problems {
 public:
  void add(const std::string& kind, const std::string& line) {
    if (++counts_[kind] <= kShown) lines_.push_back(line);
  }
  std::vector<std::string> take() {
    for (const auto& [kind, n] : counts_)
      if (n > kShown) lines_.push_back(std::to_string(n) + " " + kind + " in all");
    return std::move(lines_);
  }

 private:
  std::vector<std::string> lines_;
  std::map<std::string, std::size_t> counts_;
};

std::string face_name(const Surface& s, std::size_t fi) {
  return "face " + std::to_string(fi) + " (edge " + std::to_string(s.faces[fi].source_edge) + ")";
}

std::string point_text(glm::dvec3 p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

// A face's plan, relative to `origin` so that far-away coordinates keep their digits.
struct PlanFace {
  std::vector<std::vector<glm::dvec2>> loops;
  double area = 0.0;  // signed: positive when the face looks up
  double perimeter = 0.0;
  glm::dvec3 normal{0.0};  // Newell normal (length twice the area)
  glm::dvec3 point{0.0};   // a vertex, relative to origin
  std::int32_t edge = -1;  // the footprint edge of a side face
};

double shoelace(const std::vector<glm::dvec2>& loop) {
  double a = 0.0;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    a += loop[j].x * loop[i].y - loop[i].x * loop[j].y;
  return 0.5 * a;
}

PlanFace plan_face(const Surface& s, const SurfaceFace& f, glm::dvec3 origin) {
  PlanFace out;
  for (const auto& loop : f.loops) {
    std::vector<glm::dvec2> plan;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const glm::dvec3 p = s.vertices[loop[i]] - origin, q = s.vertices[loop[(i + 1) % loop.size()]] - origin;
      plan.emplace_back(p.x, p.y);
      out.normal += glm::cross(p, q);
      out.perimeter += glm::length(q - p);
    }
    out.area += shoelace(plan);
    out.loops.push_back(std::move(plan));
  }
  if (!f.loops.empty() && !f.loops[0].empty()) out.point = s.vertices[f.loops[0][0]] - origin;
  if (f.kind == FaceKind::Side) out.edge = f.source_edge;
  return out;
}

bool inside_loops(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p) {
  bool inside = false;
  for (const auto& pts : loops)
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++)
      if ((pts[i].y > p.y) != (pts[j].y > p.y) &&
          p.x < (pts[j].x - pts[i].x) * (p.y - pts[i].y) / (pts[j].y - pts[i].y) + pts[i].x)
        inside = !inside;
  return inside;
}

double distance_to_loops(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& pts : loops)
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
      const glm::dvec2 d = pts[i] - pts[j];
      const double dd = glm::dot(d, d);
      const double t = dd > 0.0 ? std::clamp(glm::dot(p - pts[j], d) / dd, 0.0, 1.0) : 0.0;
      best = std::min(best, glm::length(p - (pts[j] + t * d)));
    }
  return best;
}

}  // namespace

double plan_diagonal(const Footprint& footprint) { return bounds(footprint).diagonal(); }

double roof_tolerance(const Footprint& footprint, double made_relative) {
  return bounds(footprint).tolerance(made_relative);
}

double roof_tolerance(const Footprint& footprint, const Surface& roof) {
  Bounds b = bounds(footprint);
  for (const glm::dvec3& v : roof.vertices) b.add(glm::dvec2(v));
  return b.tolerance(roof.tolerance_relative);
}

std::vector<std::string> check_valid_mesh(const Surface& surface) {
  try {
    ValidationOptions options = roof_validation(surface);
    options.search_proven_pairs = true;
    const ValidationReport v = validate(build_mesh(surface), options);
    if (v.ok()) return {};
    std::vector<std::string> out{std::string("mesh does not validate:") + (v.closed ? "" : " not closed") +
                                 (v.manifold ? "" : " not 2-manifold") + (v.oriented ? "" : " not oriented") +
                                 (v.planar ? "" : " not planar") +
                                 (v.self_intersection_free ? "" : " self-intersecting") +
                                 (v.proof_contradicted ? " (and triangles the proof over its base covered cross)" : "")};
    for (std::size_t i = 0; i < v.problems.size() && i < kShown; ++i) out.push_back(v.problems[i]);
    return out;
  } catch (const std::exception& e) {
    return {std::string("build_mesh: ") + e.what()};
  }
}

namespace {

// Where a profiled edge and a straight-on neighbour step by different amounts
// at one height, the jog between their new lines is the end of the one that
// stepped further out (core/sweep/horizontal_event.cc): a plane across the
// edge's line, leaning at one of its profile's slopes. Where along the line
// it stands depends on the neighbour, so only its direction and slope are checked.
// A corner whose vertex lies within `tol` of its neighbours' line is one the
// output cannot tell from straight, and may take a jog too: across the
// corner's turn, so the jog may turn from e's line by as much as the corner.
bool on_a_jog(const EdgeLine& e, const Profile& profile, const PlanFace& face, double tol) {
  const double length = glm::length(face.normal);
  if (!(length > 0.0)) return false;
  const glm::dvec3 n = face.normal / length;
  const double across = std::hypot(n.x, n.y);
  if (across == 0.0) return false;
  const glm::dvec2 d = glm::normalize(e.b - e.a);
  double turn = 0.0;  // the largest sine of a turn at e's ends that the tolerance cannot see
  const auto corner = [&](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
    const glm::dvec2 u = glm::normalize(q - p), w = glm::normalize(r - q);
    const double sine = std::abs(u.x * w.y - u.y * w.x);
    if (glm::dot(u, w) > 0.0 && sine * std::min(glm::distance(p, q), glm::distance(q, r)) <= tol)
      turn = std::max(turn, sine);
  };
  corner(e.before, e.a, e.b);
  corner(e.a, e.b, e.after);
  if (std::abs(n.x * d.y - n.y * d.x) / across > 1e-6 + turn) return false;
  const double slope = std::abs(n.z) / across;
  for (std::size_t i = 0; i + 1 < profile.points.size(); ++i) {
    const glm::dvec2 p = profile.points[i], q = profile.points[i + 1];
    if (q.y == p.y) continue;
    if (std::abs(slope - std::abs((q.x - p.x) / (q.y - p.y))) <= 1e-6 * (1.0 + slope)) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> check_faces_on_planes(const Footprint& footprint, const SweepOptions& options,
                                               const Surface& surface, double tol) {
  Problems problems;
  const auto edges = edges_by_id(footprint, options.ambiguity);
  const glm::dvec3 origin(footprint.loops.at(0).points.at(0), 0.0);
  for (std::size_t fi = 0; fi < surface.faces.size(); ++fi) {
    const SurfaceFace& f = surface.faces[fi];
    // Largest distance of the face's vertices from a plane given as a signed
    // distance function of a point.
    const auto off_by = [&](const auto& distance) {
      double worst = 0.0;
      for (const auto& loop : f.loops)
        for (std::uint32_t v : loop) worst = std::max(worst, std::abs(distance(surface.vertices[v])));
      return worst;
    };
    const auto height = [&](double h) { return [h](glm::dvec3 p) { return p.z - h; }; };
    if (f.kind == FaceKind::Base) {
      if (off_by(height(0.0)) > tol) problems.add("base faces off z = 0", face_name(surface, fi) + ": base face not at z = 0");
      continue;
    }
    if (f.kind == FaceKind::Cap) {
      if (!options.max_height)
        problems.add("caps", face_name(surface, fi) + ": a cap without max_height");
      else if (off_by(height(*options.max_height)) > tol)
        problems.add("caps off max_height", face_name(surface, fi) + ": cap not at max_height " +
                                                std::to_string(*options.max_height));
      continue;
    }
    const auto edge = edges.find(f.source_edge);
    if (edge == edges.end()) continue;  // a plan edit's edge: its line is the edit's, not the footprint's
    const EdgeLine& e = edge->second;
    // The plane of a segment from profile point p to q (x outward, y up),
    // extended beyond q when it is the profile's last.
    const auto segment_plane = [&](glm::dvec2 p, glm::dvec2 q) {
      return [&e, p, q](glm::dvec3 v) {
        if (q.y == p.y) return v.z - p.y;
        const double outward = p.x + (v.z - p.y) * (q.x - p.x) / (q.y - p.y);
        return (e.inward({v.x, v.y}) + outward) / std::hypot(1.0, (q.x - p.x) / (q.y - p.y));
      };
    };
    double best = std::numeric_limits<double>::infinity();
    if (e.spec.profile >= 0) {
      const Profile& profile = footprint.profiles.at(static_cast<std::size_t>(e.spec.profile));
      for (std::size_t i = 0; i + 1 < profile.points.size(); ++i)
        best = std::min(best, off_by(segment_plane(profile.points[i], profile.points[i + 1])));
    } else {
      best = off_by(segment_plane({0.0, 0.0}, {-std::tan(e.spec.angle_deg * kDegree), 1.0}));
    }
    if (best > tol && e.spec.profile >= 0 && on_a_jog(e, footprint.profiles.at(static_cast<std::size_t>(e.spec.profile)),
                                                      plan_face(surface, f, origin), tol))
      continue;
    if (best > tol)
      problems.add("faces off their edge's plane", face_name(surface, fi) + " is " + std::to_string(best) +
                                                       " off every plane of its edge (tolerance " + std::to_string(tol) + ")");
  }
  return problems.take();
}

std::vector<std::string> check_inward_roof(const Footprint& footprint, const SweepOptions& options,
                                           const Surface& surface, double tol, unsigned seed) {
  Problems problems;
  const Bounds b = bounds(footprint);
  const glm::dvec3 origin(footprint.loops.at(0).points.at(0), 0.0);
  const glm::dvec2 o(origin.x, origin.y);
  const auto edges = edges_by_id(footprint, options.ambiguity);

  std::vector<std::vector<glm::dvec2>> plan_loops;
  double area = 0.0, perimeter = 0.0;
  bool uniform = true;
  double min_tan = std::numeric_limits<double>::infinity();
  for (const Loop& loop : footprint.loops) {
    std::vector<glm::dvec2> pts;
    for (std::size_t i = 0; i < loop.points.size(); ++i) {
      pts.push_back(loop.points[i] - o);
      perimeter += glm::length(loop.points[(i + 1) % loop.points.size()] - loop.points[i]);
      uniform = uniform && loop.edges[i].angle_deg == footprint.loops[0].edges[0].angle_deg;
      min_tan = std::min(min_tan, std::tan(loop.edges[i].angle_deg * kDegree));
    }
    area += shoelace(pts);
    plan_loops.push_back(std::move(pts));
  }
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * b.max_abs;
  const double z_tol = tol * (1.0 + 1.0 / min_tan);

  // Seen from above every roof face looks up, and together they cover the footprint once.
  std::vector<PlanFace> faces(surface.faces.size());
  double covered = 0.0;
  for (std::size_t fi = 0; fi < surface.faces.size(); ++fi) {
    if (surface.faces[fi].kind == FaceKind::Base) continue;
    faces[fi] = plan_face(surface, surface.faces[fi], origin);
    covered += faces[fi].area;
    if (faces[fi].area < -tol * faces[fi].perimeter)
      problems.add("faces looking down", face_name(surface, fi) + " looks down (plan area " +
                                             std::to_string(faces[fi].area) + ") on an inward roof");
  }
  if (std::abs(covered - area) > 1e-9 * area + rounding * perimeter)
    problems.add("tiling", "roof faces cover " + std::to_string(covered) + " in plan, the footprint " +
                               std::to_string(area));

  const bool convex = footprint.loops.size() == 1 && [&] {
    const auto& p = plan_loops[0];
    for (std::size_t i = 0; i < p.size(); ++i) {
      const glm::dvec2 d1 = p[(i + 1) % p.size()] - p[i], d2 = p[(i + 2) % p.size()] - p[(i + 1) % p.size()];
      if (d1.x * d2.y - d1.y * d2.x < 0.0) return false;
    }
    return true;
  }();
  const auto plane_height = [&](const EdgeLine& e, glm::dvec2 p) {
    return e.inward(p) / std::tan(e.spec.angle_deg * kDegree);
  };

  // Samples keep clear of borders by ten times the finest scale's tolerance,
  // not `tol`: a roof made at a coarse scale (a jittered star's apex closed
  // at 1e-5) is held to ten times that, a margin wider than its thin faces.
  const double margin = 10.0 * roof_tolerance(footprint);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, 1.0);
  constexpr int kSamples = 24, kTries = 400;
  int sampled = 0;
  for (int attempt = 0; attempt < kTries && sampled < kSamples; ++attempt) {
    const glm::dvec2 local = b.lo - o + glm::dvec2(ux(rng), ux(rng)) * (b.hi - b.lo);
    if (!inside_loops(plan_loops, local) || distance_to_loops(plan_loops, local) < margin) continue;
    // Points on a face's border are covered by two faces or none: not sampled.
    // Every face counts, however thin: a point further than the margin from
    // a face's border is inside it or not whatever its width. (Faces no wider
    // than `tol` were left out, and the 10,000-vertex jittered star of
    // large_stars seed 0, closed at 1e-5, held to 2.8 cm, had every point in
    // its 6 cm wide spike faces covered by none.)
    std::vector<std::size_t> over;
    bool on_border = false;
    for (std::size_t fi = 0; fi < faces.size() && !on_border; ++fi) {
      if (faces[fi].loops.empty()) continue;
      if (distance_to_loops(faces[fi].loops, local) < margin) on_border = true;
      else if (inside_loops(faces[fi].loops, local)) over.push_back(fi);
    }
    if (on_border) continue;
    ++sampled;
    const glm::dvec2 p = local + o;
    const std::string where = "at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
    if (over.size() != 1) {
      problems.add("points not covered once", std::to_string(over.size()) + " roof faces over the footprint point " + where);
      continue;
    }
    const std::size_t fi = over[0];
    const PlanFace& f = faces[fi];
    const double z = f.point.z - (f.normal.x * (local.x - f.point.x) + f.normal.y * (local.y - f.point.y)) / f.normal.z;
    const SurfaceFace& face = surface.faces[fi];
    const auto edge = edges.find(face.source_edge);
    const double own = face.kind == FaceKind::Cap ? *options.max_height
                       : edge != edges.end()      ? plane_height(edge->second, p)
                                                  : std::numeric_limits<double>::quiet_NaN();
    if (!(std::abs(z - own) <= z_tol))
      problems.add("heights off the face's own plane",
                   face_name(surface, fi) + " is at height " + std::to_string(z) + " " + where + ", its plane at " +
                       std::to_string(own));
    if (convex) {
      double envelope = options.max_height.value_or(std::numeric_limits<double>::infinity());
      for (const auto& [id, e] : edges) envelope = std::min(envelope, plane_height(e, p));
      if (std::abs(z - envelope) > z_tol)
        problems.add("heights off the lower envelope", "roof height " + std::to_string(z) + " " + where +
                                                           ", the lower envelope of the planes " + std::to_string(envelope));
    }
    if (uniform) {
      double boundary = std::numeric_limits<double>::infinity();
      for (const auto& [id, e] : edges) boundary = std::min(boundary, e.distance(p));
      const double limit = boundary / std::tan(footprint.loops[0].edges[0].angle_deg * kDegree);
      if (z > limit + z_tol)
        problems.add("heights above the distance bound", "roof height " + std::to_string(z) + " " + where +
                                                              " exceeds distance to the boundary / tan(angle) = " +
                                                              std::to_string(limit));
    }
  }
  // Points are drawn over the bounding box: where the part of the footprint
  // clear of the margins is a small share of it (a sliver along a diagonal),
  // every draw may miss. A miss is a problem only when about ten hits were due.
  const glm::dvec2 box = b.hi - b.lo;
  const double expected_hits = kTries * (area - 2.0 * margin * perimeter) / (box.x * box.y);
  if (sampled == 0 && expected_hits >= 10.0) problems.add("no samples", "no point of the footprint could be sampled");
  return problems.take();
}

namespace {

double height_on(const PlanFace& f, glm::dvec2 p) {
  return f.point.z - (f.normal.x * (p.x - f.point.x) + f.normal.y * (p.y - f.point.y)) / f.normal.z;
}

// The highest face over plan point p (relative to origin) that is not
// vertical, or nullptr: the roof seen from above. Under an overhang (a
// soffit, a lean, a ledge) several faces lie over p, and which comes first
// depends on the order the sweep made them, which a mirror reverses.
const PlanFace* face_over(const std::vector<PlanFace>& faces, glm::dvec2 p) {
  const PlanFace* top = nullptr;
  for (const PlanFace& f : faces)
    if (!f.loops.empty() && std::abs(f.normal.z) > 1e-12 * glm::length(f.normal) && inside_loops(f.loops, p) &&
        (top == nullptr || height_on(f, p) > height_on(*top, p)))
      top = &f;
  return top;
}

// Calls visit(origin, p, face of a, face of b) at `samples` points drawn (by `seed`)
// over a's bounding box where both roofs have a face that is not vertical;
// p and the faces are relative to the box's corner `origin`.
template <class Visit>
void sample_both(const Surface& a, const Surface& b, int samples, unsigned seed, Visit visit) {
  if (a.vertices.empty()) return;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& v : a.vertices) {
    lo = glm::min(lo, glm::dvec2(v));
    hi = glm::max(hi, glm::dvec2(v));
  }
  const glm::dvec3 origin(lo, 0.0);
  const auto plan = [&](const Surface& s) {
    std::vector<PlanFace> faces;
    for (const SurfaceFace& f : s.faces)
      if (f.kind != FaceKind::Base) faces.push_back(plan_face(s, f, origin));
    return faces;
  };
  const std::vector<PlanFace> fa = plan(a), fb = plan(b);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < samples; ++i) {
    const glm::dvec2 p = glm::dvec2(u(rng), u(rng)) * (hi - lo);
    const PlanFace *on_a = face_over(fa, p), *on_b = face_over(fb, p);
    if (on_a != nullptr && on_b != nullptr) visit(origin, p, *on_a, *on_b);
  }
}

}  // namespace

double largest_height_difference(const Surface& a, const Surface& b, int samples, unsigned seed) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  sample_both(a, b, samples, seed, [&](glm::dvec3, glm::dvec2 p, const PlanFace& fa, const PlanFace& fb) {
    const double d = std::abs(height_on(fa, p) - height_on(fb, p));
    worst = std::isnan(worst) ? d : std::max(worst, d);
  });
  return worst;
}

double largest_levered_height_difference(const Footprint& footprint, const Surface& a, const Surface& b, int samples,
                                         unsigned seed) {
  const auto edges = edges_by_id(footprint, Ambiguity::MaximizeVolume);
  double worst = std::numeric_limits<double>::quiet_NaN();
  sample_both(a, b, samples, seed, [&](glm::dvec3 origin, glm::dvec2 p, const PlanFace& fa, const PlanFace& fb) {
    const glm::dvec2 at = p + glm::dvec2(origin);
    const auto lever = [&](const PlanFace& f) {
      const auto e = edges.find(f.edge);
      if (e == edges.end()) return 1.0;
      const glm::dvec2 d = e->second.b - e->second.a;
      const double l = glm::length(d);
      return std::max(1.0, 2.0 * std::abs(glm::dot(at - 0.5 * (e->second.a + e->second.b), d / l)) / l);
    };
    const double difference = std::abs(height_on(fa, p) - height_on(fb, p)) / std::max(lever(fa), lever(fb));
    worst = std::isnan(worst) ? difference : std::max(worst, difference);
  });
  return worst;
}

double surface_volume(const Surface& surface) {
  if (surface.vertices.empty()) return 0.0;
  const glm::dvec3 o = surface.vertices[0];
  double v = 0.0;
  for (const SurfaceFace& f : surface.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 1; i + 1 < loop.size(); ++i)
        v += glm::dot(surface.vertices[loop[0]] - o,
                      glm::cross(surface.vertices[loop[i]] - o, surface.vertices[loop[i + 1]] - o)) / 6.0;
  return v;
}

double volume_of_offset_areas(double a0, double a1, double a2, double h_end) {
  return h_end * (a0 + h_end * (a1 / 2.0 + h_end * a2 / 3.0));
}

Footprint transformed(const Footprint& footprint, const PlanTransform& t) {
  Footprint out = footprint;
  for (Loop& loop : out.loops) {
    for (glm::dvec2& p : loop.points) p = t.apply(p);
    if (!t.mirrors()) continue;
    // Reversed, edge k runs from old point n-1-k to n-2-k: old edge n-2-k.
    const std::size_t n = loop.points.size();
    Loop reversed;
    for (std::size_t k = 0; k < n; ++k) {
      reversed.points.push_back(loop.points[n - 1 - k]);
      reversed.edges.push_back(loop.edges[(2 * n - 2 - k) % n]);
    }
    loop = std::move(reversed);
  }
  return out;
}

namespace {

// Where faces of collinear edges are coplanar, the seam between them, and a
// face closing to nothing at a point, are placed by the arithmetic (see
// skeleton_oracle.cc); a transform changes its rounding. Two roofs whose faces
// each lie on their own edge's plane (check_faces_on_planes) and whose heights
// agree everywhere are then the same roof.
bool same_heights(const Surface& moved, const Surface& other, double tol) {
  double rise = 1.0;  // the steepest face's height per plan distance
  for (const SurfaceFace& f : moved.faces) {
    if (f.kind == FaceKind::Base) continue;
    const PlanFace p = plan_face(moved, f, glm::dvec3(0.0));
    const double across = std::hypot(p.normal.x, p.normal.y);
    if (std::abs(p.normal.z) > 1e-3 * across) rise = std::max(rise, across / std::abs(p.normal.z));
  }
  const double worst = largest_height_difference(moved, other, 4000, 7);
  return worst <= 4.0 * tol * (1.0 + rise);  // false where no point is under both (NaN)
}

}  // namespace

std::vector<std::string> compare_transformed(const Surface& original, const PlanTransform& t,
                                             const Surface& of_transformed, double tol) {
  Problems problems;
  std::vector<glm::dvec3> moved;
  for (const glm::dvec3& v : original.vertices) moved.emplace_back(t.apply({v.x, v.y}), v.z * t.height_scale());
  Surface moved_roof = original;
  moved_roof.vertices = moved;
  const PointSet expected(moved), actual(of_transformed.vertices);
  for (const glm::dvec3& v : of_transformed.vertices)
    if (expected.nearest(v, tol) > tol)
      problems.add("extra vertices", "vertex " + point_text(v) + " of the " + t.name + " input's roof is not in the " +
                                          t.name + " roof");
  for (const glm::dvec3& v : moved)
    if (actual.nearest(v, tol) > tol)
      problems.add("missing vertices", "vertex " + point_text(v) + " of the " + t.name + " roof is not in the " +
                                            t.name + " input's roof");
  // Face area and perimeter per source edge (caps and base by kind).
  const auto areas = [](const Surface& s, double scale) {
    std::map<std::pair<int, std::int32_t>, glm::dvec2> out;
    for (const SurfaceFace& f : s.faces) {
      const PlanFace p = plan_face(s, f, s.vertices.empty() ? glm::dvec3(0.0) : s.vertices[0]);
      glm::dvec2& a = out[{static_cast<int>(f.kind), f.kind == FaceKind::Side ? f.source_edge : -1}];
      a += glm::dvec2(0.5 * glm::length(p.normal), p.perimeter) * glm::dvec2(scale * scale, scale);
    }
    return out;
  };
  const auto expected_areas = areas(original, t.height_scale()), actual_areas = areas(of_transformed, 1.0);
  for (const auto& [key, a] : expected_areas) {
    const auto it = actual_areas.find(key);
    const double got = it == actual_areas.end() ? 0.0 : it->second.x;
    if (std::abs(got - a.x) > 2.0 * tol * a.y + 1e-9 * a.x)
      problems.add("face areas", "edge " + std::to_string(key.second) + "'s faces have area " + std::to_string(got) +
                                     " in the " + t.name + " input's roof, " + std::to_string(a.x) + " in the " +
                                     t.name + " roof");
  }
  for (const auto& [key, a] : actual_areas)
    if (!expected_areas.count(key))
      problems.add("face areas", "edge " + std::to_string(key.second) + " has faces only in the " + t.name +
                                     " input's roof");
  // Seams between coplanar faces move area from one edge's faces to
  // another's, never in or out of the roof.
  glm::dvec2 total_expected(0.0), total_actual(0.0);
  for (const auto& [key, a] : expected_areas) total_expected += a;
  for (const auto& [key, a] : actual_areas) total_actual += a;
  const bool same_total = std::abs(total_actual.x - total_expected.x) <= 2.0 * tol * total_expected.y + 1e-9 * total_expected.x;
  std::vector<std::string> lines = problems.take();
  if (!lines.empty() && same_total && same_heights(moved_roof, of_transformed, tol)) return {};
  return lines;
}

}  // namespace procex::testing

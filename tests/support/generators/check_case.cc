#include "tests/support/generators/check_case.h"

#include <cmath>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/geom/nesting.h"
#include "core/geom/prepare.h"
#include "tests/support/roof_properties.h"
#include "tests/support/skeleton_oracle.h"

namespace procex::testing {
namespace {

bool inward_roof(const Footprint& fp, const SweepOptions& options) {
  if (!options.plan_edits.empty()) return false;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges)
      if (e.profile >= 0 || !(e.angle_deg > 0.0 && e.angle_deg < 90.0)) return false;
  return true;
}

bool one_angle(const Footprint& fp) {
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges)
      if (e.angle_deg != fp.loops[0].edges[0].angle_deg) return false;
  return true;
}

// The corners of a single loop, straight vertices dropped.
std::vector<glm::dvec2> corners(const Loop& loop) {
  std::vector<glm::dvec2> out;
  const std::size_t n = loop.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 d1 = loop.points[i] - loop.points[(i + n - 1) % n], d2 = loop.points[(i + 1) % n] - loop.points[i];
    if (std::abs(d1.x * d2.y - d1.y * d2.x) > 1e-9 * glm::length(d1) * glm::length(d2)) out.push_back(loop.points[i]);
  }
  return out;
}

// The volume under a rectangle's or a regular polygon's roof, one angle on
// every edge, by integrating its offset areas: a rectangle W x L shrinks to
// (W - 2hs)(L - 2hs) at height h, a regular polygon of inradius r to
// A (1 - hs / r)^2, with s = tan(angle), up to the ridge or max_height.
std::optional<double> closed_form_volume(const Footprint& fp, const SweepOptions& options) {
  if (fp.loops.size() != 1 || !inward_roof(fp, options) || !one_angle(fp)) return std::nullopt;
  const std::vector<glm::dvec2> c = corners(fp.loops[0]);
  const std::size_t n = c.size();
  const double s = std::tan(fp.loops[0].edges[0].angle_deg * M_PI / 180.0);
  const double cap = options.max_height.value_or(INFINITY);
  std::vector<double> sides(n);
  for (std::size_t i = 0; i < n; ++i) sides[i] = glm::distance(c[i], c[(i + 1) % n]);
  if (n == 4) {
    bool square_corners = true;
    for (std::size_t i = 0; i < 4; ++i)
      square_corners = square_corners && std::abs(glm::dot(c[(i + 1) % 4] - c[i], c[(i + 2) % 4] - c[(i + 1) % 4])) <=
                                             1e-12 * sides[i] * sides[(i + 1) % 4];
    if (square_corners) {
      const double w = std::min(sides[0], sides[1]), l = std::max(sides[0], sides[1]);
      return volume_of_offset_areas(w * l, -2.0 * s * (w + l), 4.0 * s * s, std::min(cap, w / (2.0 * s)));
    }
  }
  if (n < 5) return std::nullopt;
  const glm::dvec2 centre = std::accumulate(c.begin(), c.end(), glm::dvec2(0.0)) / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(sides[i] - sides[0]) > 1e-9 * sides[0] ||
        std::abs(glm::distance(c[i], centre) - glm::distance(c[0], centre)) > 1e-9 * sides[0])
      return std::nullopt;
  const double inradius = glm::distance(c[0], centre) * std::cos(M_PI / static_cast<double>(n));
  const double area = 0.5 * static_cast<double>(n) * sides[0] * inradius;
  return volume_of_offset_areas(area, -2.0 * area * s / inradius, area * s * s / (inradius * inradius),
                                std::min(cap, inradius / s));
}

// The area of a surface's top cap, seen from above.
double cap_area(const Surface& s) {
  double twice = 0.0;
  for (const SurfaceFace& f : s.faces) {
    if (f.kind != FaceKind::Cap) continue;
    for (const std::vector<std::uint32_t>& loop : f.loops) {
      std::vector<glm::dvec2> plan;
      for (std::uint32_t v : loop) plan.emplace_back(s.vertices[v]);
      twice += twice_signed_area(plan);
    }
  }
  return 0.5 * twice;
}

void add(std::vector<std::string>& to, const std::string& prefix, const std::vector<std::string>& lines) {
  for (const std::string& line : lines) to.push_back(prefix + line);
}

bool cgal_judges(const Footprint& fp, const SweepOptions& options) {
  return inward_roof(fp, options) && one_angle(fp) && !options.max_height;
}

// A quarter turn, a move to (5e5, 5e6), and a mirror, which turns FromStart
// anchors into FromEnd ones: not for plan edits.
std::vector<PlanTransform> case_transforms(const Footprint& fp, const SweepOptions& options) {
  glm::dvec2 lo(INFINITY);
  for (const Loop& loop : fp.loops)
    for (const glm::dvec2& p : loop.points) lo = glm::min(lo, p);
  std::vector<PlanTransform> transforms{PlanTransform::rotation(90), PlanTransform::translation(glm::dvec2(5e5, 5e6) - lo)};
  if (options.plan_edits.empty()) transforms.push_back(PlanTransform::mirror());
  return transforms;
}

}  // namespace

std::vector<std::pair<std::string, Footprint>> checked_plans(const Footprint& prepared, const SweepOptions& options,
                                                             const CheckSelection& selection) {
  std::vector<std::pair<std::string, Footprint>> out;
  if (selection.transforms)
    for (const PlanTransform& t : case_transforms(prepared, options)) out.emplace_back(t.name, transformed(prepared, t));
  if (selection.oracle && cgal_judges(prepared, options))
    out.emplace_back("CGAL's plan", without_straight_vertices(prepared));
  return out;
}

CaseResult check_case(const GeneratedCase& c, const CheckSelection& selection) {
  CaseResult r;
  Footprint fp;
  try {
    fp = prepare_footprint(c.footprint).footprint;
  } catch (const InputError& e) {
    r.refused = true;
    r.problems.push_back(std::string("prepare_footprint refused it: ") + e.what());
    return r;
  }
  const auto sweep_guarded = [&](const Footprint& f, const SweepOptions& o, const std::string& what) -> std::optional<Surface> {
    try {
      return sweep(f, o);
    } catch (const SweepOpenError& e) {
      // The engine says edges rise forever once its last event is past. Then
      // the plan capped well above that height is a valid solid, every face
      // on its plane, with a top of some area: else the refusal hid lost events.
      SweepOptions capped = o;
      capped.max_height = e.height() + 10.0 * plan_diagonal(f);
      try {
        const Surface s = sweep(f, capped);
        const double tol = roof_tolerance(f, s);
        add(r.problems, what + "refused as rising forever, capped: ", check_valid_mesh(s));
        add(r.problems, what + "refused as rising forever, capped: ", check_faces_on_planes(f, capped, s, tol));
        if (!(cap_area(s) > tol * plan_diagonal(f)))
          r.problems.push_back(what + "refused as rising forever, but capped above its last event its top is empty");
      } catch (const std::exception& capped_error) {
        r.problems.push_back(what + "refused as rising forever (" + e.what() + "), but capped it fails: " +
                             capped_error.what());
      }
    } catch (const SweepError& e) {
      std::string ids;
      for (int id : e.edge_ids()) ids += " " + std::to_string(id);
      r.problems.push_back(what + "sweep failed: " + e.what() + " at height " + std::to_string(e.height()) + ", edges" + ids);
    } catch (const std::exception& e) {
      r.problems.push_back(what + "sweep threw: " + e.what());
    }
    return std::nullopt;
  };
  const std::optional<Surface> roof = sweep_guarded(fp, c.options, "");
  if (!roof) return r;
  const double tol = roof_tolerance(fp, *roof);
  add(r.problems, "", check_valid_mesh(*roof));
  add(r.problems, "", check_faces_on_planes(fp, c.options, *roof, tol));
  if (inward_roof(fp, c.options)) {
    add(r.problems, "", check_inward_roof(fp, c.options, *roof, tol, static_cast<unsigned>(fp.loops[0].points.size())));
    if (const std::optional<double> v = closed_form_volume(fp, c.options)) {
      const double got = surface_volume(*roof);
      // A layer of the position tolerance over the footprint's extent.
      double extent = 0.0;
      for (const auto& p : corners(fp.loops[0])) extent = std::max(extent, glm::length(p - fp.loops[0].points[0]));
      if (std::abs(got - *v) > 1e-9 * *v + tol * extent * extent)
        r.problems.push_back("volume " + std::to_string(got) + ", the integral of the offset areas " + std::to_string(*v));
    }
    if (selection.oracle && cgal_judges(fp, c.options))
      add(r.problems, "CGAL: ", sweep_and_compare_with_cgal(fp, c.options, *roof));
  }
  if (selection.transforms) {
    for (const PlanTransform& t : case_transforms(fp, c.options)) {
      const Footprint moved = transformed(fp, t);
      if (const std::optional<Surface> other = sweep_guarded(moved, c.options, t.name + ": ")) {
        const double moved_tol = std::max(tol, roof_tolerance(moved, *other));
        add(r.problems, t.name + ": ", check_faces_on_planes(moved, c.options, *other, moved_tol));
        add(r.problems, t.name + ": ", compare_transformed(*roof, t, *other, moved_tol));
      }
    }
  }
  return r;
}

}  // namespace procex::testing

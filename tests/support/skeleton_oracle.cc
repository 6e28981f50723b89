#include "tests/support/skeleton_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/sweep/sweep.h"
#include "tests/support/cgal_skeleton.h"
#include "tests/support/point_set.h"
#include "tests/support/roof_properties.h"
#include "tests/support/tangential_skeleton.h"

namespace procex::testing {
namespace {

constexpr std::size_t kShown = 5;

std::string describe(const glm::dvec3& p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

std::string pair_text(std::pair<std::int32_t, std::int32_t> p) {
  return std::to_string(p.first) + "-" + std::to_string(p.second);
}

}  // namespace

Footprint without_straight_vertices(const Footprint& fp) {
  double max_abs = 0.0;
  for (const Loop& loop : fp.loops)
    for (const glm::dvec2& p : loop.points) max_abs = std::max({max_abs, std::abs(p.x), std::abs(p.y)});
  // A point off its exact place by a few units in the last place of the
  // largest coordinate moves the cross product of its edges by this per metre.
  const double rounding = 16.0 * std::numeric_limits<double>::epsilon() * max_abs;
  Footprint out = fp;
  for (Loop& loop : out.loops) {
    Loop kept;
    const std::size_t n = loop.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec2 a = loop.points[(i + n - 1) % n], b = loop.points[i], c = loop.points[(i + 1) % n];
      const glm::dvec2 d1 = b - a, d2 = c - b;
      const double l1 = glm::length(d1), l2 = glm::length(d2), cross = d1.x * d2.y - d1.y * d2.x;
      if (std::abs(cross) < std::max(1e-9 * l1 * l2, rounding * (l1 + l2)) && glm::dot(d1, d2) > 0.0) continue;
      kept.points.push_back(b);
      kept.edges.push_back(loop.edges[i]);
    }
    loop = std::move(kept);
  }
  return out;
}

namespace {

// CGAL's skeleton with exact constructions up to kExactOracleVertices, and
// with inexact ones beyond, or where the exact kernel runs out of its memory
// cap: it keeps every node's whole arithmetic history, and jittered stars of
// 1,000-3,000 vertices, their events micrometres apart, took it past 4 GB
// (the star class, TESTING.md), where the inexact kernel decides the same
// events exactly and rounds only the nodes, far below the comparison's
// tolerance (CgalOracle.TheInexactKernelsNodesAreTheExactOnesWithinTheTolerance).
CgalSkeleton oracle_skeleton(const CgalSkeletonInput& input, std::size_t vertices) {
  if (vertices > kExactOracleVertices) return input.skeleton(CgalConstructions::Inexact, kLargeOracleMemory);
  try {
    return input.skeleton(CgalConstructions::Exact);
  } catch (const CgalOutOfMemory&) {
    return input.skeleton(CgalConstructions::Inexact);
  }
}

}  // namespace

std::vector<std::string> compare_with_cgal(const Footprint& footprint, const Surface& roof) {
  const double tol = roof_tolerance(footprint, roof.tolerance_relative);
  const double rise = 1.0 / std::tan(footprint.loops.at(0).edges.at(0).angle_deg * M_PI / 180.0);
  std::vector<std::string> problems = check_valid_mesh(roof);

  std::size_t vertices = 0;
  for (const Loop& loop : footprint.loops) vertices += loop.points.size();
  CgalSkeleton cgal;
  if (std::optional<CgalSkeleton> closed = tangential_skeleton(footprint)) {
    cgal = std::move(*closed);
  } else {
    try {
      cgal = oracle_skeleton(CgalSkeletonInput(footprint), vertices);
    } catch (const CgalNoSkeleton& e) {
      // Only a generic neighbour that CGAL can skeletonise can judge the roof now.
      problems.push_back(e.what());
      return problems;
    }
  }
  for (glm::dvec3& n : cgal.nodes) n.z *= rise;

  // One roof face per footprint edge.
  std::map<std::int32_t, std::size_t> faces;
  for (const SurfaceFace& f : roof.faces)
    if (f.kind == FaceKind::Side) ++faces[f.source_edge];
  std::size_t wrong_faces = 0;
  for (const auto& [id, n] : cgal.faces_per_edge) {
    const auto it = faces.find(id);
    const std::size_t ours = it == faces.end() ? 0 : it->second;
    if (n != 1 && ++wrong_faces <= kShown)
      problems.push_back("CGAL has " + std::to_string(n) + " faces for edge " + std::to_string(id));
    if (ours != 1 && ++wrong_faces <= kShown)
      problems.push_back("edge " + std::to_string(id) + " has " + std::to_string(ours) + " roof faces, not 1");
  }

  // Which edges' faces meet along a ridge, and how long the longest is.
  // Nodes match within tol at either end, so a ridge's length may differ by
  // up to 2 tol between the roof and CGAL: one side must show a ridge the
  // other has longer than 3 tol, and may show one the other has shorter.
  std::map<std::pair<std::int32_t, std::int32_t>, double> ours_longest;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::int32_t> half;
  for (const SurfaceFace& f : roof.faces) {
    if (f.kind != FaceKind::Side) continue;
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
        const auto other = half.find({b, a});
        if (other != half.end() && other->second != f.source_edge) {
          double& longest = ours_longest[{std::min(other->second, f.source_edge), std::max(other->second, f.source_edge)}];
          longest = std::max(longest, glm::distance(roof.vertices[a], roof.vertices[b]));
        }
        half[{a, b}] = f.source_edge;
      }
  }
  using Pairs = std::set<std::pair<std::int32_t, std::int32_t>>;
  const auto ours_longer_than = [&](double length) {
    Pairs out;
    for (const auto& [p, longest] : ours_longest)
      if (longest > length) out.insert(p);
    return out;
  };
  const auto theirs_longer_than = [&](double length) {
    const auto pairs = ridges_longer_than(cgal, length, rise);
    return Pairs(pairs.begin(), pairs.end());
  };
  const Pairs ridges = ours_longer_than(tol), theirs = theirs_longer_than(tol);
  std::size_t missing_ridges = 0, extra_ridges = 0;
  for (const auto& p : theirs_longer_than(3.0 * tol))
    if (!ridges.count(p) && ++missing_ridges <= kShown)
      problems.push_back("CGAL's faces of edges " + pair_text(p) + " share a bisector, the roof's faces meet in no ridge");
  for (const auto& p : ours_longer_than(3.0 * tol))
    if (!theirs.count(p) && ++extra_ridges <= kShown)
      problems.push_back("the roof's faces of edges " + pair_text(p) + " meet in a ridge, CGAL's share no bisector");

  // Node positions and heights, both ways.
  std::vector<glm::dvec3> ours;
  for (const glm::dvec3& v : roof.vertices)
    if (v.z > tol) ours.push_back(v);
  const PointSet ours_set(roof.vertices), theirs_set(cgal.nodes);
  std::size_t missing = 0, extra = 0;
  for (const glm::dvec3& n : cgal.nodes) {
    if (n.z <= tol || ours_set.nearest(n, tol) <= tol) continue;
    if (++missing <= kShown) problems.push_back("CGAL node " + describe(n) + " has no roof vertex within " + std::to_string(tol));
  }
  for (const glm::dvec3& v : ours) {
    if (theirs_set.nearest(v, tol) <= tol) continue;
    if (++extra <= kShown) problems.push_back("roof vertex " + describe(v) + " has no CGAL node within " + std::to_string(tol));
  }
  if (missing + extra + missing_ridges + extra_ridges + wrong_faces > 0)
    problems.push_back(std::to_string(missing) + " of " + std::to_string(cgal.nodes.size()) + " CGAL nodes and " +
                       std::to_string(extra) + " of " + std::to_string(ours.size()) + " roof vertices unmatched, " +
                       std::to_string(missing_ridges) + " of " + std::to_string(theirs.size()) + " CGAL ridges and " +
                       std::to_string(extra_ridges) + " of " + std::to_string(ridges.size()) +
                       " roof ridges unmatched, " + std::to_string(wrong_faces) + " edges without one face");
  return problems;
}

namespace {

// The footprint with every vertex moved by up to `delta` in x and y.
Footprint perturbed(const Footprint& fp, double delta, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-delta, delta);
  Footprint out = fp;
  for (Loop& loop : out.loops)
    for (glm::dvec2& p : loop.points) p += glm::dvec2(u(rng), u(rng));
  return out;
}

// Where events coincide exactly (grid plans, rotated or not), the roof's
// vertices and ridges are a matter of convention: faces of collinear edges
// are coplanar, so where their seam meets a ridge, and a face that closes to
// nothing at a point, are not seen in the surface. CGAL resolves such a point
// as its exact arithmetic falls, the sweep as its clustering does. There the
// oracle is the limit: the roof must be, within the perturbation, the roof
// of a generic neighbour of the input (every vertex moved by far more than
// the sweep's clustering tolerance) that itself agrees with CGAL in every
// node and ridge, each height difference weighed by how far moving the
// edges' ends moves the planes there (largest_levered_height_difference). Returns the problems of the first neighbour that agrees
// with CGAL but not with the roof, empty when one passes both.
std::vector<std::string> compare_with_generic_neighbours(const Footprint& fp, const Surface& roof) {
  const double delta = 10.0 * roof_tolerance(fp);
  const double rise = 1.0 / std::tan(fp.loops.at(0).edges.at(0).angle_deg * M_PI / 180.0);
  std::vector<std::string> found;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Footprint near = perturbed(fp, delta, seed);
    if (!compare_with_cgal(near, sweep(near)).empty()) continue;  // not generic enough: another one
    const double worst = largest_levered_height_difference(fp, roof, sweep(near), 4000, seed);
    const double allowed = 4.0 * delta * (1.0 + rise);
    if (worst <= allowed) return {};
    if (found.empty())
      found.push_back("the roof is " + std::to_string(worst) + " times the lever in height from that of a neighbour moved by " +
                      std::to_string(delta) + " that agrees with CGAL (allowed " + std::to_string(allowed) + ")");
  }
  if (found.empty()) found.push_back("no neighbour of the input moved by " + std::to_string(delta) + " agrees with CGAL");
  return found;
}

// Compares `roof`, fp's own, with CGAL; see sweep_and_compare_with_cgal.
std::vector<std::string> compare_roof_with_cgal(const Footprint& fp, const Surface& roof) {
  std::vector<std::string> problems = compare_with_cgal(fp, roof);
  if (problems.empty() || !check_valid_mesh(roof).empty()) return problems;
  const std::vector<std::string> limit = compare_with_generic_neighbours(fp, roof);
  if (limit.empty()) return {};
  problems.insert(problems.end(), limit.begin(), limit.end());
  return problems;
}

// What f returns, or the exception it throws as a problem line.
template <class F>
std::vector<std::string> reported(const F& f) {
  try {
    return f();
  } catch (const SweepError& e) {
    std::ostringstream s;
    s << "sweep failed: " << e.what() << " at height " << e.height() << ", edges";
    for (int id : e.edge_ids()) s << " " << id;
    return {s.str()};
  } catch (const std::exception& e) {
    return {std::string("exception: ") + e.what()};
  }
}

}  // namespace

std::vector<std::string> sweep_and_compare_with_cgal(const Footprint& footprint) {
  return reported([&] {
    const Footprint fp = without_straight_vertices(footprint);
    return compare_roof_with_cgal(fp, sweep(fp));
  });
}

std::vector<std::string> sweep_and_compare_with_cgal(const Footprint& footprint, const SweepOptions& options,
                                                     const Surface& roof) {
  const Footprint fp = without_straight_vertices(footprint);
  // The roof handed in is sweep(fp)'s only with the default options, every one
  // of them (a budget decides which scale closes), and where CGAL's plan keeps
  // every vertex.
  bool same_plan = options == SweepOptions{};
  for (std::size_t i = 0; i < fp.loops.size(); ++i)
    same_plan = same_plan && fp.loops[i].points.size() == footprint.loops[i].points.size();
  if (same_plan) return reported([&] { return compare_roof_with_cgal(fp, roof); });
  return reported([&] { return compare_roof_with_cgal(fp, sweep(fp)); });
}

}  // namespace procex::testing

#include "tests/support/cgal_skeleton.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_straight_skeleton_2.h>

namespace procex {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;

struct PolygonWithHoles {
  Polygon outer;
  std::vector<Polygon> holes;
};

bool point_in_loop(const Loop& loop, glm::dvec2 p) {
  bool inside = false;
  const auto& pts = loop.points;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    if ((pts[i].y > p.y) != (pts[j].y > p.y) &&
        p.x < (pts[j].x - pts[i].x) * (p.y - pts[i].y) / (pts[j].y - pts[i].y) + pts[i].x)
      inside = !inside;
  }
  return inside;
}

// Loop `inner` lies inside loop `outer` when most of its vertices do: loops
// may touch at a vertex (OSM courtyards), which a single vertex or a nudged
// edge midpoint can get wrong when features are 1e-7 apart.
bool loop_inside(const Loop& inner, const Loop& outer) {
  std::size_t inside = 0;
  for (const glm::dvec2& p : inner.points) inside += point_in_loop(outer, p) ? 1 : 0;
  return 2 * inside > inner.points.size();
}

Polygon to_cgal(const Loop& loop) {
  Polygon poly;
  for (const glm::dvec2& p : loop.points) poly.push_back(Kernel::Point_2(p.x, p.y));
  return poly;
}

std::vector<PolygonWithHoles> split_by_nesting(const Footprint& fp) {
  const std::size_t n = fp.loops.size();
  std::vector<std::vector<std::size_t>> containers(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && loop_inside(fp.loops[i], fp.loops[j])) containers[i].push_back(j);

  std::vector<PolygonWithHoles> out;
  std::vector<std::size_t> polygon_of(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    if (containers[i].size() % 2 != 0) continue;
    polygon_of[i] = out.size();
    out.push_back({to_cgal(fp.loops[i]), {}});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t depth = containers[i].size();
    if (depth % 2 == 0) continue;
    const auto parent = std::find_if(containers[i].begin(), containers[i].end(),
                                     [&](std::size_t j) { return containers[j].size() + 1 == depth; });
    if (parent == containers[i].end())
      throw std::runtime_error("cgal_skeleton: loop " + std::to_string(i) + " has no enclosing outer loop");
    out[polygon_of[*parent]].holes.push_back(to_cgal(fp.loops[i]));
  }
  return out;
}

}  // namespace

struct CgalSkeletonInput::Impl {
  std::vector<PolygonWithHoles> polygons;

  template <class Visit>
  void for_each_skeleton(Visit&& visit) const {
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      const PolygonWithHoles& p = polygons[i];
      const auto ss = CGAL::create_interior_straight_skeleton_2(p.outer.vertices_begin(), p.outer.vertices_end(),
                                                                p.holes.begin(), p.holes.end(), Kernel());
      if (!ss)
        throw std::runtime_error("CGAL create_interior_straight_skeleton_2 failed on polygon " + std::to_string(i) +
                                 " (" + std::to_string(p.outer.size()) + " outer vertices, " +
                                 std::to_string(p.holes.size()) + " holes)");
      visit(*ss);
    }
  }
};

CgalSkeletonInput::CgalSkeletonInput(const Footprint& footprint)
    : impl_(std::make_unique<Impl>(Impl{split_by_nesting(footprint)})) {}
CgalSkeletonInput::CgalSkeletonInput(CgalSkeletonInput&&) noexcept = default;
CgalSkeletonInput& CgalSkeletonInput::operator=(CgalSkeletonInput&&) noexcept = default;
CgalSkeletonInput::~CgalSkeletonInput() = default;

std::size_t CgalSkeletonInput::polygon_count() const { return impl_->polygons.size(); }

std::size_t CgalSkeletonInput::skeletonise() const {
  std::size_t vertices = 0;
  impl_->for_each_skeleton([&](const auto& ss) { vertices += ss.size_of_vertices(); });
  return vertices;
}

std::vector<glm::dvec3> CgalSkeletonInput::inner_nodes() const {
  std::vector<glm::dvec3> nodes;
  impl_->for_each_skeleton([&](const auto& ss) {
    for (auto v = ss.vertices_begin(); v != ss.vertices_end(); ++v)
      if (v->is_skeleton()) nodes.emplace_back(v->point().x(), v->point().y(), v->time());
  });
  return nodes;
}

}  // namespace procex

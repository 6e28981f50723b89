// CGAL 5.5's interior straight skeleton as an oracle for the sweep: with every
// edge at 45 degrees the sweep's roof vertices are the skeleton's nodes, each
// at the height of its time. CGAL stays inside cgal_skeleton.cc because its
// headers cost many seconds per translation unit.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/footprint.h"

namespace procex {

// A footprint split into the polygons with holes CGAL takes: every loop at
// even nesting depth with the odd-depth loops directly inside it. Loops must
// be simple and must not cross (as the synthetic README and OSM promise).
class CgalSkeletonInput {
 public:
  explicit CgalSkeletonInput(const Footprint& footprint);
  CgalSkeletonInput(CgalSkeletonInput&&) noexcept;
  CgalSkeletonInput& operator=(CgalSkeletonInput&&) noexcept;
  ~CgalSkeletonInput();

  std::size_t polygon_count() const;

  // Runs create_interior_straight_skeleton_2 (Exact_predicates_inexact_
  // constructions_kernel) on every polygon and returns the number of skeleton
  // vertices it built. Throws std::runtime_error naming the polygon if CGAL
  // gives up.
  std::size_t skeletonise() const;

  // The skeleton's inner nodes (not the contour vertices) as (x, y, time).
  std::vector<glm::dvec3> inner_nodes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace procex

// CGAL 5.5's interior straight skeleton as an oracle for the sweep: with every
// edge at one angle the sweep's roof vertices are the skeleton's nodes, each
// at the height of its time, and two edges' roof faces meet along a ridge
// exactly where their skeleton faces share a bisector. CGAL stays inside
// cgal_skeleton.cc because its headers cost many seconds per translation unit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/footprint.h"

namespace procex {

// The longest bisector between the skeleton faces of footprint edges a < b,
// its ends as (x, y, time).
struct CgalRidge {
  std::int32_t a = 0, b = 0;
  glm::dvec3 from{0.0}, to{0.0};
};

// What the oracle compares: skeleton nodes and which edges' faces meet.
struct CgalSkeleton {
  // The inner nodes (not the contour vertices) as (x, y, time).
  std::vector<glm::dvec3> nodes;
  // For every pair of footprint edges (EdgeSpec::id, smaller first, sorted)
  // whose skeleton faces share a bisector, the longest such bisector: which
  // of them count as ridges depends on the comparison's tolerance
  // (ridges_longer_than).
  std::vector<CgalRidge> ridges;
  // Number of skeleton faces per footprint edge id, in id order of
  // CgalSkeletonInput::edge_ids(); a straight skeleton has exactly one.
  std::vector<std::pair<std::int32_t, std::size_t>> faces_per_edge;
};

// CGAL gave no skeleton for the plan: it crashed building one (it runs in a
// child process, see cgal_skeleton.cc), ran past its CPU-time cap, or
// create_interior_straight_skeleton_2 returned none, as CGAL 5.5 does for
// some plans whose events coincide exactly (a polyomino turned by 45 degrees). There is nothing to compare with.
struct CgalNoSkeleton : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The child building the skeleton needed more than its memory cap: no
// skeleton, like any other. A plan of thousands of vertices may need that
// much; CGAL 5.5.1 also ran a 24-vertex polyomino turned by 45 degrees past
// 4 GB (generated grid seed 53252, as it loops on seed 6912's), where the
// plan's generic neighbours take it a few megabytes.
struct CgalOutOfMemory : CgalNoSkeleton {
  using CgalNoSkeleton::CgalNoSkeleton;
};

// How much address space the child building a skeleton may add to what it
// inherits, by default. The exact kernel on a star of 10,000 vertices grew past 20 GB
// (TESTING.md, the size class); the tests share a machine of 23 GB.
constexpr std::size_t kCgalChildMemory = std::size_t{4} << 30;

// How many CPU seconds the child building a skeleton of a plan of `vertices`
// may take, by default: 60 + (vertices / 100)^2, twenty times that under the
// sanitizers. CGAL 5.5.1's builder can loop for ever on a plan whose events
// coincide (CGAL issue 7470; generated grid seed 6912, a polyomino of 42
// vertices turned by 45 degrees, ran for hours with either kernel), where a
// skeleton of those 42 vertices takes it milliseconds; at 1,000 vertices the exact
// kernel took minutes (the size class, TESTING.md), hence the square.
std::size_t cgal_child_seconds(std::size_t vertices);

// Which kernel builds the oracle's skeleton. Exact: CGAL's
// Exact_predicates_exact_constructions_kernel, nodes exact up to the final
// rounding to double. Inexact: Exact_predicates_inexact_constructions_kernel,
// exact decisions but nodes constructed in doubles (the benchmarks' kernel),
// for plans the exact one cannot build in time or memory.
enum class CgalConstructions { Exact, Inexact };

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

  // Runs create_interior_straight_skeleton_2 with CGAL's fast kernel
  // (Exact_predicates_inexact_constructions_kernel, the benchmarks' reference)
  // on every polygon and returns the number of skeleton vertices it built.
  // Throws std::runtime_error naming the polygon if CGAL gives up.
  std::size_t skeletonise() const;

  // The oracle: the skeleton built with the given kernel. Built in a child
  // process of at most `memory` bytes more address space than the caller's
  // and at most `seconds` of CPU time (cgal_child_seconds of the plan's
  // vertices when not given): throws CgalNoSkeleton if CGAL crashes, gives
  // none or runs out of time, CgalOutOfMemory (a CgalNoSkeleton) if it
  // needs more memory.
  CgalSkeleton skeleton(CgalConstructions constructions = CgalConstructions::Exact,
                        std::size_t memory = kCgalChildMemory, std::optional<std::size_t> seconds = std::nullopt) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The pairs of edges (smaller first, sorted) whose faces share a bisector
// longer than `length`, with time scaled by `rise` into height. CGAL splits a
// node where more than three faces meet into several joined by bisectors of
// length zero, which are no ridges.
std::vector<std::pair<std::int32_t, std::int32_t>> ridges_longer_than(const CgalSkeleton& skeleton, double length,
                                                                      double rise = 1.0);

}  // namespace procex

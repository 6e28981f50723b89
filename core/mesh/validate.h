// Property checks on a mesh: what tests assert and what users can ask for.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/geom/tolerances.h"
#include "core/mesh/mesh.h"
#include "core/mesh/surface.h"

namespace procex {

struct ValidationOptions {
  // Distance tolerance; <= 0 means `relative` of the mesh's bounding-box diagonal.
  double tolerance = -1.0;
  double relative = kMeshDistanceRelative;
  bool check_self_intersections = true;
  // Search every pair of triangles for intersections even where a roof's are
  // proven apart over its base (height_field.h): tests compare the two
  // (ValidationReport::proof_contradicted).
  bool search_proven_pairs = false;
};

// What a sweep's roof is held to: relative to the clustering scale it was
// made at (mesh_distance_relative).
ValidationOptions roof_validation(const Surface& roof);

struct ValidationReport {
  bool closed = false;       // no boundary half-edges
  bool manifold = false;     // every edge has two faces, every vertex one fan (parts that
                             // touch along an edge have their own copies of it: round_edge.h)
  bool oriented = false;     // neighbouring faces agree on orientation, volume > 0
  bool planar = false;       // each face within tolerance of its own plane
  bool self_intersection_free = false;
  double volume = 0.0;       // signed; positive for an outward-facing solid
  double max_planarity_error = 0.0;
  double tolerance = 0.0;  // the distance planarity and intersections were checked to
  std::vector<std::string> problems;  // one line each, naming faces / vertices
  // Pairs of triangles the self-intersection search looked at: its work, which
  // tests hold to O(n log n) where a stopwatch could not.
  std::size_t triangle_pairs_tested = 0;
  // Whether the triangles were proven to pass through none of each other
  // (height_field.h), which takes no pairs; but upright ones (walls), whose
  // pairs are searched.
  bool proven_apart = false;
  // Whether the search found two triangles crossing that the proof covered:
  // a fault of the proof (tests search every pair to see it).
  bool proof_contradicted = false;

  bool ok() const {
    return closed && manifold && oriented && planar && self_intersection_free;
  }
};

ValidationReport validate(const Mesh& mesh, const ValidationOptions& options = {});

// The volume a closed mesh encloses; positive when its faces point outwards.
double signed_volume(const Mesh& mesh);

}  // namespace procex

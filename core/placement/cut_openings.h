// Openings cut into walls (issue 15): a placed window or door makes a hole in
// the face it stands on, and the hole is lined by reveal faces that run a
// given depth into the solid and closed by a back face, so the building stays
// a closed 2-manifold and loses exactly width x height x depth per opening.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/anchor.h"
#include "core/mesh/mesh.h"

namespace procex {

// A rectangle on a face: [lo, hi] in `frame`'s (along, up) coordinates about
// its origin, on a face of footprint edge `edge` in the frame's plane.
struct Opening {
  std::int32_t edge = -1;
  Frame frame;
  glm::dvec2 lo{0.0}, hi{0.0};
};

struct CutSpec {
  double depth = 0.2;          // how far the reveals run into the solid, > 0
  std::string tag = "reveal";  // the reveal and back faces' tag
};

struct CutReport {
  std::size_t cut = 0;
  // One line per opening not cut, with the reason: it is not inside one face
  // of its edge with wall left around it, it overlaps an opening cut before,
  // or its recess would reach another face or another recess.
  std::vector<std::string> skipped;
};

// The mesh with the openings cut, in order (an opening is judged against the
// ones cut before it). `tags` gives each face of `mesh` its tag (by face
// index); the result's faces carry theirs in kFaceTagProperty, the recess
// faces spec.tag. Faces keep their kind and source edge; a recess's faces
// take the source edge of the face they are cut into. Throws MeshError if
// OpenMesh refuses a face (it does not for a closed 2-manifold input).
Mesh cut_openings(const Mesh& mesh, const std::vector<std::string>& tags, const std::vector<Opening>& openings,
                  const CutSpec& spec, CutReport& report);

}  // namespace procex

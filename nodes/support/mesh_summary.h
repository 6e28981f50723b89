// A few numbers that characterise a MeshSet: what reports print and what the
// sample regression tests compare (within a tolerance) against stored values.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include <glm/vec3.hpp>

#include "nodes/values.h"

namespace procex {

struct MeshSummary {
  std::size_t meshes = 0, faces = 0;
  std::map<std::string, std::size_t> faces_per_tag;
  glm::dvec3 min{0}, max{0};  // bounding box; zero when there are no vertices
  double volume = 0;          // sum of the meshes' signed volumes
  // Meshes placed on them (windows, chimneys), per placed mesh's name; not
  // in the counts and volume above.
  std::map<std::string, std::size_t> placed;
};

MeshSummary summarize(const MeshSet& set);

}  // namespace procex

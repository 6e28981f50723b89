// The result of placing meshes on a building: the building's own mesh and the
// placed instances kept apart (each a shared mesh and a transform), so a
// window used two hundred times is stored once, and a flattening into one
// mesh for formats without instancing (OBJ, PLY).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/mesh/material.h"
#include "core/mesh/mesh.h"

namespace procex {

// Face property that flatten() adds: the instance a face came from, -1 for
// the building's own faces.
inline constexpr const char* kInstanceProperty = "procex:instance";  // int

// A mesh to place (read_mesh_file in core/io/mesh_read.h reads one).
struct PlaceableMesh {
  std::string name;  // tags the faces that have no tag of their own
  std::shared_ptr<const Mesh> mesh;
  MaterialTable materials = nullptr;  // its faces' materials by tag (its .mtl's, a Material node's)
};

struct Instance {
  std::size_t mesh = 0;           // index into PlacementResult::meshes
  glm::dmat4 transform{1.0};      // the mesh's own coordinates to the world
  std::string tag;                // when not empty, tags every face of this instance
  std::int32_t source_edge = -1;  // the footprint edge it was placed on (EdgeSpec::id), -1 if none
};

// What one building (one PlacementResult) may hold. A legal recipe can ask
// for far more than memory holds (a 300 x 300 window grid on each of six
// walls is 540,000 windows and gigabytes once flattened): past these,
// add_instance refuses with a PlacementError instead of running out.
inline constexpr std::size_t kMaxInstancesPerBuilding = 100000;
inline constexpr std::size_t kMaxPlacedFacesPerBuilding = 5000000;

struct PlacementResult {
  std::shared_ptr<const Mesh> building;  // may be null: instances only
  std::vector<PlaceableMesh> meshes;     // distinct meshes
  std::vector<Instance> instances;
  std::size_t placed_faces = 0;  // faces of all instances' meshes, as flatten() would add them

  // The index of `mesh` in `meshes`, added unless the same shared Mesh is
  // there under the same name with the same materials (one file placed under
  // two names keeps both names). Throws PlacementError if it is null.
  std::size_t add_mesh(const PlaceableMesh& mesh);
  // Adds an instance after check_instance and the per-building budgets above.
  // Returns its index.
  std::size_t add_instance(Instance instance);
};

// Why a transform cannot place a mesh, "" if it can: it is not finite, not
// affine (last row 0 0 0 1), or singular (it would collapse the mesh).
std::string transform_problem(const glm::dmat4& transform);

// Throws PlacementError naming instance `index` if its mesh index is out of
// range or transform_problem finds one.
void check_instance(const PlacementResult& result, std::size_t index);

// det of the transform's 3x3 part: negative for a mirroring placement.
double linear_determinant(const glm::dmat4& transform);

// Everything in one mesh: the building's faces as they are, then each
// instance's vertices transformed and its faces added, in order. An instance
// face's tag is the instance's tag if set, else the face's own tag, else the
// mesh's name; a face tagged by its instance keeps the material of its own
// tag (or name) where its mesh has one (kFaceMaterialProperty); its source edge is the instance's, its kind Side, and
// kInstanceProperty gives the instance. A mirroring transform (negative
// determinant) reverses every face of its instance, so outward faces stay
// outward and a closed 2-manifold part stays one. The placed meshes' own
// corner texture coordinates and normals (normals turned by the transform)
// come along (core/mesh/material.h); their materials, which the mesh does not
// carry, flattened_materials gives. Throws PlacementError (from
// check_instance) or MeshError if OpenMesh refuses a face.
Mesh flatten(const PlacementResult& result);
// The materials of flatten(result)'s faces: the building's (`building`),
// then each placed mesh's that name a tag none before it named (the first
// to name a tag gives it).
MaterialTable flattened_materials(const MaterialTable& building, const PlacementResult& result);

}  // namespace procex

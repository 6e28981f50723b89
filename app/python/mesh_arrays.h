// procex.Mesh: one tagged mesh seen from Python as NumPy arrays. Vertex
// positions, per-face tags, source edges and face kinds are views of the C++
// mesh's own storage (read-only, no copy; the array keeps the mesh alive);
// faces as offsets and indices are laid out once when the mesh is wrapped;
// UVs and normals (core's surface_attributes) are made on first read and
// then seen as views too.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/mesh/uv_frames.h"
#include "nodes/values.h"

namespace procex::python {

struct MeshArrays;

// A placed mesh: which mesh (shared by every instance of it), where.
struct Placement {
  std::shared_ptr<MeshArrays> mesh;
  glm::dmat4 transform{1.0};
  std::string tag;  // when not empty, the tag of every face of this instance
  std::int32_t source_edge = -1;
};

struct MeshArrays {
  std::shared_ptr<const Mesh> mesh;
  std::vector<std::uint32_t> face_tags;  // index into tags, per face
  std::vector<std::string> tags;
  std::string name;      // a placed mesh's name (its file's stem), else empty
  std::string building;
  std::int64_t feature = -1;
  std::vector<std::int32_t> face_offsets;  // n_faces + 1
  std::vector<std::int32_t> face_indices;  // vertex indices, face after face
  std::vector<Placement> placed;
  // UVs and normals as the OBJ writer has them, made on first use (most callers never read them).
  std::optional<SurfaceAttributes> surface;
};

// The part as Python sees it; its placed meshes are wrapped once each, shared by their instances.
std::shared_ptr<MeshArrays> wrap(TaggedMesh part);
// Every part of the set, in order (the vector is consumed).
pybind11::list wrap_all(MeshSet set);

// Registers procex.Mesh and procex.Placement on m.
void bind_mesh(pybind11::module_& m);

}  // namespace procex::python

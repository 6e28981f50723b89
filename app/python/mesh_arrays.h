// procex.Mesh: one tagged mesh seen from Python as NumPy arrays. Vertex
// positions, per-face tags, source edges and face kinds are views of the C++
// mesh's own storage (read-only, no copy; the array keeps the mesh alive);
// faces as offsets and indices are laid out once when the mesh is wrapped;
// UVs and normals (core's surface_attributes) are made on first read and
// then seen as views too.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
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
  MaterialTable materials;  // by tag, as the part or placed mesh carries them
  std::string name;      // a placed mesh's name (its file's stem), else empty
  std::string building;
  std::int64_t feature = -1;
  std::vector<std::int32_t> face_offsets;  // n_faces + 1
  std::vector<std::int32_t> face_indices;  // vertex indices, face after face
  std::vector<Placement> placed;
  // UVs and normals as the OBJ writer has them, made on first use (most callers never read them).
  std::optional<SurfaceAttributes> surface;
};

// Placed meshes already wrapped, by mesh, name and material table, so that the window every
// building of a batch shares is wrapped once (and is one procex.Mesh). Safe
// to use from several threads at once.
class PlaceableCache {
 public:
  std::shared_ptr<MeshArrays> get(const PlaceableMesh& placeable);

 private:
  std::mutex mutex_;
  // The entry holds the mesh and its table alive, so their addresses name no others.
  std::map<std::tuple<const Mesh*, std::string, const Materials*>, std::shared_ptr<MeshArrays>> wrapped_;
};

// The part as Python sees it; its placed meshes are wrapped once each (once
// over every call given the same `placeables`), shared by their instances.
// Makes no Python object, so it runs without the GIL.
std::shared_ptr<MeshArrays> wrap(TaggedMesh part, PlaceableCache& placeables);
using WrappedMeshes = std::vector<std::shared_ptr<MeshArrays>>;
// Every part of the set, in order (the vector is consumed); no GIL needed.
WrappedMeshes wrap_all(MeshSet set, PlaceableCache& placeables);
WrappedMeshes wrap_all(MeshSet set);
// The Python list of them (with the GIL).
pybind11::list to_list(const WrappedMeshes& meshes);

// Registers procex.Mesh and procex.Placement on m.
void bind_mesh(pybind11::module_& m);

}  // namespace procex::python

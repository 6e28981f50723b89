// glTF 2.0 binary (.glb) output through tinygltf: one glTF mesh (and node) per
// building, one primitive per face tag (triangles, flat normals), the tag in the
// primitive's extras and material name, the building id (and the feature's
// position in its source file, for merging shards) in the node's extras.
// Reading back what was written gives the same data, so shards merge into
// the same bytes an unsharded run writes.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace procex {

// A procex mesh as the writer sees it: faces tagged through face_tags -> tags.
struct TaggedMeshView {
  const Mesh* mesh = nullptr;
  std::span<const std::uint32_t> face_tags;  // per face (by index), into tags
  std::span<const std::string> tags;
  std::string building;        // building id ("" if none)
  std::int64_t feature = -1;   // position of the building's feature in its GeoJSON file, -1 if none
};

// The triangles of one tag of one mesh: what a primitive holds.
struct GltfPrimitiveData {
  std::string tag;
  std::vector<float> positions;  // x y z per vertex
  std::vector<float> normals;    // unit, per vertex (faces do not share vertices)
  std::vector<std::uint32_t> indices;
};

struct GltfMeshData {
  std::string building;
  std::int64_t feature = -1;
  std::vector<GltfPrimitiveData> primitives;  // in order of first use of the tag
};

// Display colour (linear RGB) of a face tag: fixed for the usual tags, a grey
// derived from the name otherwise. Shared with other writers (OBJ materials).
std::array<double, 3> tag_colour(const std::string& tag);

// Triangulates every face (convex pieces, fanned); faces with zero area are dropped.
GltfMeshData to_gltf_mesh(const TaggedMeshView& view);
// The same, added to an existing mesh (a building made of several procex
// meshes): faces join the primitive of their tag, made if missing.
void append_to_gltf_mesh(GltfMeshData& mesh, const TaggedMeshView& view);

// Writes a .glb atomically. Throws IoError naming the file on failure.
void write_glb(const std::filesystem::path& path, const std::vector<GltfMeshData>& meshes);
// Reads a .glb written by write_glb. Throws IoError naming the file and what
// is not as write_glb writes it.
std::vector<GltfMeshData> read_glb(const std::filesystem::path& path);

}  // namespace procex

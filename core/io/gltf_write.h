// glTF 2.0 binary (.glb) output, written directly (each building's JSON
// rendered in parallel, the binary chunk streamed from its arrays; tinygltf
// only reads files back), in glTF's frame: metres, +Y up (procex's z), the
// plan not mirrored (core/io/up_axis.h). One glTF mesh (and node) per
// building, one primitive per face tag (triangles, flat normals, texture
// coordinates in metres), the tag in the primitive's extras and material name
// and, per vertex, as the application attribute _TAG (float, the tag's
// position in the asset's extras.tags list, in order of first use);
// a placed mesh's primitives carry its own texture coordinates, normals and
// material (colour and image, the image embedded).
// The node is named by the building id and stands at the building's local
// origin (its translation, in double precision); its extras hold the id, the
// feature's position in its source file (for merging shards), the origin in
// procex's frame (x east, y north, z up), the feature's GeoJSON properties
// and the recipe's exposed values.
// Placed meshes (windows, pillars: core/placement) are instanced: one glTF
// mesh per distinct placed mesh (its name in the mesh's extras as "placed"),
// one child node of its building's node per instance, holding the instance's
// matrix in float32 as glTF readers hold it (a shear, which a glTF matrix
// cannot hold, as two nodes: see core/placement/trs_split.h) and its tag in
// extras.
// Reading back what was written (core/io/glb_read.h) gives the same data
// (the matrices as float32 rounds them), so shards merge into the same bytes
// an unsharded run writes.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/io/io_error.h"
#include "core/mesh/material.h"
#include "core/mesh/mesh.h"

namespace procex {

// A procex mesh as the writer sees it: faces tagged through face_tags -> tags.
struct TaggedMeshView {
  const Mesh* mesh = nullptr;
  std::span<const std::uint32_t> face_tags;  // per face (by index), into tags
  std::span<const std::string> tags;
  std::string building;        // building id ("" if none)
  std::int64_t feature = -1;   // position of the building's feature in its GeoJSON file, -1 if none
  MaterialTable materials = nullptr;  // the faces' materials by tag, carried beside the mesh (null: none)
};

// A primitive's own material (a placed mesh's, from its .mtl, or a tag's from
// the recipe's Material node: core/mesh/material.h): the base colour, times
// the image where there is one (embedded in the .glb, its texture repeating
// every tile_size texture coordinates through KHR_texture_transform), with
// its roughness and metalness.
struct GltfMaterialData {
  std::array<double, 3> colour{1, 1, 1};  // linear RGB
  double roughness = Material::kDefaultRoughness, metallic = 0.0;
  double tile_size = 1.0;
  std::shared_ptr<const std::string> image;  // PNG or JPEG bytes; null if none

  bool operator==(const GltfMaterialData& o) const {
    return colour == o.colour && roughness == o.roughness && metallic == o.metallic && tile_size == o.tile_size &&
           (image == o.image || (image && o.image && *image == *o.image));
  }
};

// The triangles of one tag of one mesh: what a primitive holds.
struct GltfPrimitiveData {
  std::string tag;
  std::vector<float> positions;  // x y z per vertex
  std::vector<float> normals;    // unit, per vertex (faces do not share vertices)
  std::vector<std::uint32_t> indices;
  // Texture coordinates (TEXCOORD_0), u v per vertex or none: metres on the
  // face (core/mesh/uv_frames.h), v negated as glTF's v runs down the image,
  // so a texture stands upright on a wall.
  // A placed mesh's own texture coordinates are kept, v turned to run down
  // (1 - v) as an image's rows do.
  std::vector<float> uvs;
  // The tag's material where its mesh has one (core/mesh/material.h), else
  // none: the tag's colour.
  std::optional<GltfMaterialData> material;

  bool operator==(const GltfPrimitiveData&) const = default;
};

// One placement of a placed mesh.
struct GltfInstanceData {
  std::size_t prototype = 0;   // index into GltfScene::prototypes
  glm::dmat4 transform{1.0};   // the placed mesh's own coordinates to its building's (glTF's frame, from the origin)
  std::string tag;             // the instance's tag ("" if none)
};

struct GltfMeshData {
  std::string building;
  std::int64_t feature = -1;
  // Where the node stands (its translation, glTF's frame, double precision):
  // positions and instance transforms are relative to it, so float32 keeps
  // millimetres at UTM coordinates. Zero for placed meshes.
  std::array<double, 3> origin{0, 0, 0};
  // The node's extras: the feature's GeoJSON properties and the recipe's
  // exposed values, each value as compact JSON text.
  std::map<std::string, std::string> properties, parameters;
  std::vector<GltfPrimitiveData> primitives;  // in order of first use of the tag
  std::vector<GltfInstanceData> instances;    // the meshes placed on this building
};

// A whole file: the buildings, and the placed meshes their instances name
// (for those, `building` holds the placed mesh's name; feature and instances
// are unused). write_glb writes the placed meshes in order of first use,
// equal ones (same name and triangles) once, unused ones not at all.
struct GltfScene {
  std::vector<GltfMeshData> meshes;
  std::vector<GltfMeshData> prototypes;
  // The scene's extras, each value as compact JSON text (procex batch: which
  // shard of which run the file is).
  std::map<std::string, std::string> extras;
};

// Adds part's buildings after into's, and its placed meshes after into's
// (its instances renumbered): how shard files join before they are sorted
// and written again. Placed meshes both hold are written once. The extras
// are into's: what the parts are together is the caller's to say.
void append_scene(GltfScene& into, GltfScene part);

// Display colour (linear RGB) of a face tag: fixed for the usual tags, a grey
// derived from the name otherwise. Shared with other writers (OBJ materials).
std::array<double, 3> tag_colour(const std::string& tag);

// Triangulates every face (convex pieces, fanned); faces with zero area are
// dropped. A tag with a material of the mesh's (core/mesh/material.h) gets
// it, with the image the material was made with (Material::image). Positions and normals turn into glTF's frame here: every
// GltfMeshData is in glTF's frame, so files read back write the same bytes.
// `origin` (procex's frame) becomes GltfMeshData::origin.
GltfMeshData to_gltf_mesh(const TaggedMeshView& view, const glm::dvec3& origin = {0, 0, 0});
// A building's local origin: the centre of its plan bounds rounded to whole
// metres, at height 0 (heights stay absolute).
glm::dvec3 local_origin(const Mesh& mesh);
// The same, added to an existing mesh (a building made of several procex
// meshes): faces join the primitive of their tag, made if missing.
void append_to_gltf_mesh(GltfMeshData& mesh, const TaggedMeshView& view);

// What one .glb can hold: its header gives the file's length in 32 bits.
inline constexpr std::uint64_t kGlbMaxBytes = UINT32_MAX;

// "a .glb holds (4 GiB)", or what a test allows instead.
std::string glb_limit_text(std::uint64_t max_bytes);

// The buildings would make a .glb longer than it can hold (or than the limit
// a test set): thrown apart from other IoErrors so that a caller can say what
// to do instead (procex batch: split the batch into shards).
class GlbTooLarge : public IoError {
 public:
  GlbTooLarge(const std::filesystem::path& path, std::uint64_t bytes, std::uint64_t max_bytes);
};

// Writes a .glb atomically. Throws IoError naming the file on failure, and
// naming the building and instance if an instance's prototype is missing or
// has no triangles, or its transform is not finite, affine and invertible.
void write_glb(const std::filesystem::path& path, const std::vector<GltfMeshData>& meshes);
void write_glb(const std::filesystem::path& path, const GltfScene& scene);
// A .glb written as buildings come, in memory that does not grow with their
// number: the bytes write_glb writes for the scene the parts make together
// (append_scene in the order added; extras the scene's). Each part's
// triangles go to temporary files (SpoolFile) beside the output with its buildings' JSON,
// rendered in parallel (within the caller's TBB arena); what the file's JSON
// needs of the placed meshes, materials and tags, which come first in it but
// are known only at the end, is filled in when finish() puts the file together.
class GlbStreamWriter {
 public:
  // Throws IoError if an extra's name is not UTF-8 or its value not JSON.
  // max_bytes: what the file may hold, kGlbMaxBytes but in tests.
  GlbStreamWriter(std::filesystem::path path, std::map<std::string, std::string> extras,
                  std::uint64_t max_bytes = kGlbMaxBytes);
  GlbStreamWriter(const GlbStreamWriter&) = delete;
  GlbStreamWriter& operator=(const GlbStreamWriter&) = delete;
  ~GlbStreamWriter();
  // Throws IoError as write_glb would for these buildings, or GlbTooLarge
  // when bytes() passes max_bytes.
  void add(std::vector<GltfScene> parts);
  // What the buildings added so far take in the file, at least: their JSON
  // (each number still to be settled counted as one digit) and their arrays;
  // the file's head, placed meshes and images come on top.
  std::uint64_t bytes() const;
  // Writes the file atomically (nothing is written before).
  void finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace procex

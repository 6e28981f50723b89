// What a placed mesh brings with it beyond its shape (paper 3.6's windows and
// doors as artists make them): each face tag's material as its OBJ's .mtl
// gives it, and each face corner's own texture coordinates and normal. The
// writers hand them on (OBJ and MTL, glTF); faces without them (a
// building's) keep the tag colours and the world-scale frames of
// core/mesh/uv_frames.h.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "core/mesh/mesh.h"

namespace procex {

struct Material {
  std::array<double, 3> colour{0.8, 0.8, 0.8};  // linear RGB, each in [0, 1] (MTL Kd, glTF baseColorFactor)
  // glTF's metallic-roughness model, each in [0, 1] (MTL's PBR extension
  // Pr, Pm). The defaults are those procex's tag colours have always had:
  // a matt, non-metal surface.
  double roughness = kDefaultRoughness;
  double metallic = 0.0;
  // A PNG or JPEG image (MTL map_Kd), resolved and confined to the recipe's
  // folder when read; empty if none.
  std::filesystem::path texture;
  // Its bytes as they were read when the material was made: what the .glb
  // embeds and the studio shows, so that an image saved since (mid-batch)
  // never goes out beside meshes keyed and made on the version before. Null
  // if there is no texture.
  std::shared_ptr<const std::string> image;
  // How far one repeat of the texture reaches in texture coordinates: procex's
  // own faces have them in metres, so this is metres per tile; a placed mesh's
  // own coordinates address its image once per 1. The writers divide the
  // coordinates by it (glTF KHR_texture_transform, MTL map_Kd -s), which
  // leaves them in metres in the file.
  double tile_size = 1.0;

  static constexpr double kDefaultRoughness = 0.9;

  bool operator==(const Material& o) const {
    return colour == o.colour && roughness == o.roughness && metallic == o.metallic && texture == o.texture &&
           tile_size == o.tile_size && (image == o.image || (image && o.image && *image == *o.image));
  }
};

// Materials by face tag.
using Materials = std::map<std::string, Material>;

// The materials a mesh is shown with, carried beside it as its face tags are
// (nodes' TaggedMesh, core/placement's PlaceableMesh), not in it: the mesh is
// shared and immutable, so a look kept in it would cost a copy of the whole
// geometry for every change of look. The table is shared too and never
// changed in place: a Material node makes a new one (with_material) and the
// geometry stays where it is. Null: no materials.
using MaterialTable = std::shared_ptr<const Materials>;

// The table's materials; empty if it is null.
const Materials& materials_of(const MaterialTable& table);
// A table with `tag`'s material set to `material`, the others as in `table`.
MaterialTable with_material(const MaterialTable& table, const std::string& tag, const Material& material);
// A table holding `materials`; null if there are none.
MaterialTable material_table(Materials materials);

// Names of the corner properties (a corner is the halfedge that
// points to its vertex in its face, so fh_range walks a face's corners in
// fv_range's order).
inline constexpr const char* kCornerUvProperty = "procex:corner_uv";          // OpenMesh::Vec2d (halfedge)
inline constexpr const char* kCornerNormalProperty = "procex:corner_normal";  // OpenMesh::Vec3d (halfedge)

// A face whose material is not its tag's names it here: a placed mesh's own
// material on a face its placement tagged otherwise (core/placement
// flatten). "" or no property: its tag's.
inline constexpr const char* kFaceMaterialProperty = "procex:material";  // std::string (face)

// Each face's material: `materials` (those carried beside the mesh) at the
// face's kFaceMaterialProperty, else at its tag; null if there is none.
// Looks the property up once, for a walk over the faces. What every writer
// asks for a face's look.
class FaceMaterials {
 public:
  FaceMaterials(const Mesh& mesh, const Materials& materials);
  const Material* of(Mesh::FaceHandle f, const std::string& tag) const;

 private:
  const Mesh& mesh_;
  const Materials& materials_;
  OpenMesh::FPropHandleT<std::string> own_;
};
// The property, added (every face "") if missing.
OpenMesh::FPropHandleT<std::string> add_face_materials(Mesh& mesh);

// The corner properties, invalid if the mesh has none. A face without its
// own texture coordinates (or normals) holds NaN at its corners.
OpenMesh::HPropHandleT<OpenMesh::Vec2d> corner_uv_property(const Mesh& mesh);
OpenMesh::HPropHandleT<OpenMesh::Vec3d> corner_normal_property(const Mesh& mesh);
// Adds them, NaN at every corner (no-op where present).
OpenMesh::HPropHandleT<OpenMesh::Vec2d> add_corner_uvs(Mesh& mesh);
OpenMesh::HPropHandleT<OpenMesh::Vec3d> add_corner_normals(Mesh& mesh);

}  // namespace procex

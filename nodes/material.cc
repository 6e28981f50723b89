// Material: gives the faces of one tag a physically based look (glTF's
// metallic-roughness model) that every output shows: .glb, OBJ's .mtl, the
// studio's preview, Python and Blender.
//
// A node on the mesh link rather than a table on Export: the look then
// travels with the meshes wherever they go (`procex eval -o` and batch write
// graph outputs without an Export node; the studio and the Python module
// read the meshes themselves), and each tag's material is one node that can
// be exposed, grouped and switched like any other.
#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <utility>

#include "core/io/io_error.h"
#include "core/io/texture_image.h"
#include "core/mesh/material.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t tag, colour, roughness, metallic, texture, tile_size;
};
Params par;

// An edited texture is read again.
void hash_texture(const std::vector<Value>& params, const std::filesystem::path& folder, FileVersionMemo* versions,
                  Hasher& h) {
  const std::string& texture = params[par.texture].get<std::string>();
  if (!texture.empty()) hash_file_stamp(folder / texture, versions, h);
}

void declare(NodeDecl& d) {
  d.doc("Gives every face tagged `tag` a material: a base colour (linear RGB, 0 to 1), times the image `texture` "
        "where one is named (a PNG or JPEG, relative to the recipe's folder), with its roughness and metalness "
        "(glTF's metallic-roughness model). procex's texture coordinates are metres on the face, so the texture "
        "repeats every `tile_size` metres on every building alike (a placed mesh's own coordinates repeat every "
        "`tile_size` units). The faces may be a building's (wall, roof, soffit, ...) or a placed mesh's (its "
        "`usemtl` names, else its name); a placed mesh's own material of that name is replaced. Meshes a Mesh "
        "Placement gave a `tag` keep their own materials under it, unless a Material names that tag: then all their "
        "faces take it. .glb files get "
        "the material (pbrMetallicRoughness, the image embedded once, KHR_texture_transform for the tile size), "
        "OBJ's .mtl gets Kd, Pr, Pm and map_Kd -s; the studio's preview and Blender show it. Chain one node per "
        "tag; a later node's material for a tag replaces an earlier one's.")
      .category("Geometry");
  d.input<MeshSet>("mesh");
  par.tag = d.param<std::string>("tag").default_value(std::string("wall")).doc("the face tag that takes the material").index();
  par.colour = d.param<Vec3>("colour").default_value(Vec3{0.8, 0.8, 0.8})
      .doc("base colour, linear red, green, blue from 0 to 1 (multiplies the texture)").index();
  par.roughness = d.param<double>("roughness").default_value(Material::kDefaultRoughness).range(0, 1)
      .doc("0 mirror-smooth, 1 fully rough").index();
  par.metallic = d.param<double>("metallic").default_value(0.0).range(0, 1).doc("0 a dielectric (stone, wood), 1 a metal").index();
  par.texture = d.param<std::string>("texture").default_value(std::string())
      .doc("a PNG or JPEG image, relative to the recipe's folder (empty: colour only)").index();
  par.tile_size = d.param<double>("tile_size").default_value(1.0).range(0.001, 1000).unit("m")
      .doc("how many metres one repeat of the texture covers").index();
  d.output<MeshSet>("mesh").doc("the same meshes, the tag's faces with the material");
  d.hash_extra(hash_texture);
}

// Whether a face of a placed mesh carries `tag` (its own, else the mesh's name).
bool carries_tag(const PlaceableMesh& placed, const std::string& tag) {
  const auto prop = face_tag_property(*placed.mesh);
  for (const auto f : placed.mesh->faces()) {
    const std::string& own = prop.is_valid() ? placed.mesh->property(prop, f) : placed.name;
    if ((own.empty() ? placed.name : own) == tag) return true;
  }
  return false;
}

// A copy of `mesh` whose every face is tagged `tag`, with `material` for it:
// what an instance tagged `tag` shows once a Material names its tag (its
// faces are the tag's, core/placement flatten, and .glb prototypes carry
// their faces' own tags). A placed mesh is small and this is done once per
// mesh, not per instance.
PlaceableMesh all_in_material(const PlaceableMesh& placed, const std::string& tag, const Material& material) {
  auto mesh = std::make_shared<Mesh>(*placed.mesh);
  add_face_properties(*mesh);
  const auto tags = face_tag_property(*mesh);
  for (const auto f : mesh->faces()) mesh->property(tags, f) = tag;
  return {placed.name, std::move(mesh), with_material(nullptr, tag, material)};
}

// Drops the meshes no instance places any more, renumbering the instances.
void drop_unplaced(PlacementResult& placed) {
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> index(placed.meshes.size(), kNone);
  std::vector<PlaceableMesh> kept;
  for (Instance& in : placed.instances) {
    if (index[in.mesh] == kNone) index[in.mesh] = kept.size(), kept.push_back(placed.meshes[in.mesh]);
    in.mesh = index[in.mesh];
  }
  placed.meshes = std::move(kept);
}

void evaluate(EvalContext& ctx) {
  const std::string& tag = ctx.param<std::string>(par.tag);
  if (tag.empty()) return ctx.error("tag: no tag given (the tag of the faces that take the material, e.g. wall or roof)");
  const Vec3& colour = ctx.param<Vec3>(par.colour);
  Material material;
  material.colour = {colour.x, colour.y, colour.z};
  if (!std::all_of(material.colour.begin(), material.colour.end(), [](double c) { return c >= 0.0 && c <= 1.0; }))
    return ctx.error("colour: each of red, green and blue must lie from 0 to 1 (linear RGB)");
  material.roughness = ctx.param<double>(par.roughness);
  material.metallic = ctx.param<double>(par.metallic);
  material.tile_size = ctx.param<double>(par.tile_size);
  if (const std::string& texture = ctx.param<std::string>(par.texture); !texture.empty()) {
    try {
      material.texture = ctx.file(texture);
      material.image = shared_texture_image(material.texture, ctx.file_versions());  // refused here, not by a writer
    } catch (const IoError& e) {
      return ctx.error("texture: " + std::string(e.what()));
    }
  }

  MeshSet out = ctx.input<MeshSet>(0);
  // Each new table made once per old one (parts of one building share theirs), and
  // once per placed mesh, so its instances stay instances of one mesh and look.
  // (Keyed by the old tables themselves, held so no new one takes an old one's address.)
  std::map<MaterialTable, MaterialTable> part_tables;
  std::map<std::pair<std::shared_ptr<const Mesh>, MaterialTable>, MaterialTable> placed_tables;
  std::map<const Mesh*, PlaceableMesh> tagged_copies;  // of meshes placed with the tag
  bool found = false;
  for (TaggedMesh& part : out.parts) {
    ctx.throw_if_cancelled();
    // The geometry stays shared: only the part's small table is new.
    if (std::find(part.tags.begin(), part.tags.end(), tag) != part.tags.end()) {
      auto [it, added] = part_tables.try_emplace(part.materials);
      if (added) it->second = with_material(part.materials, tag, material);
      part.materials = it->second;
      found = true;
    }
    for (PlaceableMesh& placed : part.placed.meshes) {
      auto [it, added] = placed_tables.try_emplace({placed.mesh, placed.materials});
      if (added && carries_tag(placed, tag)) it->second = with_material(placed.materials, tag, material);
      if (it->second) {
        placed.materials = it->second;
        found = true;
      }
    }
    bool retagged = false;
    for (Instance& in : part.placed.instances) {
      if (in.tag != tag) continue;
      const PlaceableMesh placed = part.placed.meshes[in.mesh];
      auto [copy, added] = tagged_copies.try_emplace(placed.mesh.get());
      if (added) copy->second = all_in_material(placed, tag, material);
      in.mesh = part.placed.add_mesh(copy->second);
      retagged = found = true;
    }
    if (retagged) drop_unplaced(part.placed);
  }
  if (!found) ctx.warning("tag: no face is tagged '" + tag + "', so nothing takes the material");
  ctx.set_output(0, std::move(out));
}

}  // namespace
PROCEX_REGISTER_NODE("Material", 1, declare, evaluate);
}  // namespace procex

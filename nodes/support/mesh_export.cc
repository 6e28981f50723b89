#include "nodes/support/mesh_export.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <numeric>
#include <string>

#include <glm/geometric.hpp>

#include "base/atomic_file_set.h"
#include "core/io/cityjson_write.h"
#include "core/io/geopackage_write.h"
#include "core/io/output_crs.h"
#include "core/io/gltf_crs.h"
#include "core/io/io_error.h"
#include "core/io/mesh_write.h"
#include "core/mesh/material.h"
#include "core/mesh/uv_frames.h"
#include "core/placement/placement_gltf.h"

namespace procex {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void append_number(std::string& out, double v) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// OBJ names may not contain whitespace.
std::string obj_name(const std::string& name, const std::string& fallback) {
  std::string out = name.empty() ? fallback : name;
  std::replace_if(out.begin(), out.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  return out;
}

void append_triple(std::string& out, const char* key, const glm::dvec3& p) {
  out += key;
  for (int k = 0; k < 3; ++k) out += ' ', append_number(out, p[k]);
  out += '\n';
}

// The look of faces tagged `tag` with material `own` (FaceMaterials: a
// placed mesh's library, a Material node's), else the tag's colour.
Material look_of(const Material* own, const std::string& tag) {
  if (own) return *own;
  Material m;
  m.colour = tag_colour(tag);
  return m;
}

// The material name `look` is written under: `name`, or, where `materials`
// already holds another look under it (two placed meshes' libraries each with
// a "frame"), the first of name_2, name_3, ... free or holding this look.
std::string material_name(const std::vector<std::pair<std::string, Material>>& materials, const std::string& name,
                          const Material& look) {
  for (int n = 1;; ++n) {
    const std::string candidate = n == 1 ? name : name + "_" + std::to_string(n);
    const auto it = std::find_if(materials.begin(), materials.end(), [&](const auto& m) { return m.first == candidate; });
    if (it == materials.end() || it->second == look) return candidate;
  }
}

// One object per part ("o building_id", as Blender, Maya and Houdini split
// them), a material per face tag (a placed mesh's own colour and texture,
// else the tag's colour), and per face its flat normal (vn) and its corners'
// texture coordinates in metres (vt: core/mesh/uv_frames.h); a placed mesh's
// corners keep their own texture coordinates and normals.
void write_tagged_obj(const std::filesystem::path& path, const MeshSet& set, UpAxis up) {
  std::filesystem::path mtl = path;
  mtl.replace_extension(".mtl");
  std::string obj = "# procex: metres, " + std::string(up == UpAxis::Y ? "+Y up (x east, -z north)" : "+Z up (x east, y north)") +
                    "\nmtllib " + mtl.filename().string() + "\n";
  std::vector<std::pair<std::string, Material>> materials;  // as written: name, look
  std::size_t base = 1, normals = 1, uvs = 1;  // OBJ numbers each kind from 1 across the file
  for (std::size_t i = 0; i < set.parts.size(); ++i) {
    const TaggedMesh& part = set.parts[i];
    const Mesh& mesh = *part.mesh;
    obj += "o " + obj_name(part.building, "mesh_" + std::to_string(i)) + "\n";
    for (const auto v : mesh.vertices()) {
      const Mesh::Point& p = mesh.point(v);
      append_triple(obj, "v", to_file_axes(glm::dvec3(p[0], p[1], p[2]), up));
    }
    const SurfaceAttributes surface = surface_attributes(mesh);
    // Where each face's corners start in surface.corner_uvs (faces are written grouped by tag).
    std::vector<std::size_t> first_corner(mesh.n_faces() + 1, 0);
    for (const auto f : mesh.faces())
      first_corner[static_cast<std::size_t>(f.idx()) + 1] = first_corner[static_cast<std::size_t>(f.idx())] + mesh.valence(f);
    // Faces by tag, and within a tag by look (a placed mesh's own materials
    // under the tag its placement gave it).
    const FaceMaterials own(mesh, materials_of(part.materials));
    std::vector<std::pair<std::uint32_t, const Material*>> groups;  // tag, own material
    std::vector<std::size_t> group_of(mesh.n_faces());
    for (const auto f : mesh.faces()) {
      const auto fi = static_cast<std::size_t>(f.idx());
      const std::pair<std::uint32_t, const Material*> group{part.face_tags[fi], own.of(f, part.tags[part.face_tags[fi]])};
      group_of[fi] = static_cast<std::size_t>(std::find(groups.begin(), groups.end(), group) - groups.begin());
      if (group_of[fi] == groups.size()) groups.push_back(group);
    }
    std::vector<std::size_t> order(groups.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return groups[a].first < groups[b].first; });
    for (const std::size_t g : order) {
      const std::uint32_t t = groups[g].first;
      const Material look = look_of(groups[g].second, part.tags[t]);
      const std::string name = material_name(materials, obj_name(part.tags[t], "untagged"), look);
      bool used = false;
      for (const auto f : mesh.faces()) {
        const auto fi = static_cast<std::size_t>(f.idx());
        if (group_of[fi] != g) continue;
        if (!used) obj += "usemtl " + name + "\n", used = true;
        const bool corner_normals = !surface.corner_normals.empty();
        if (!corner_normals) append_triple(obj, "vn", to_file_axes(surface.face_normals[fi], up));
        for (std::size_t c = first_corner[fi]; c < first_corner[fi + 1]; ++c) {
          if (corner_normals) append_triple(obj, "vn", to_file_axes(surface.corner_normals[c], up));
          obj += "vt ";
          append_number(obj, surface.corner_uvs[c].x);
          obj += ' ';
          append_number(obj, surface.corner_uvs[c].y);
          obj += '\n';
        }
        obj += 'f';
        std::size_t corner = 0;
        for (const auto v : mesh.fv_range(f)) {
          obj += ' ' + std::to_string(base + static_cast<std::size_t>(v.idx())) + '/' + std::to_string(uvs + corner) + '/' +
                 std::to_string(normals + (corner_normals ? corner : 0));
          ++corner;
        }
        obj += '\n';
        uvs += corner;
        normals += corner_normals ? corner : 1;
      }
      if (used && std::none_of(materials.begin(), materials.end(), [&](const auto& m) { return m.first == name; }))
        materials.emplace_back(name, look);
    }
    base += mesh.n_vertices();
  }
  std::string mtl_text = "# procex: one material per face tag\n";
  const std::filesystem::path folder = std::filesystem::weakly_canonical(std::filesystem::absolute(path).parent_path());
  for (const auto& [name, material] : materials) {
    mtl_text += "newmtl " + name + "\nKd";
    for (double c : material.colour) mtl_text += ' ', append_number(mtl_text, c);
    // Roughness and metalness as the PBR extension of MTL has them (Blender reads them).
    mtl_text += "\nPr ";
    append_number(mtl_text, material.roughness);
    mtl_text += "\nPm ";
    append_number(mtl_text, material.metallic);
    mtl_text += "\n";
    // The texture where the recipe's files gave it, relative to the .obj so
    // the pair can move with its folder; -s scales the texture coordinates
    // (metres) to tiles, as Blender's and three.js's readers apply it.
    if (!material.texture.empty()) {
      mtl_text += "map_Kd ";
      if (material.tile_size != 1.0) {
        mtl_text += "-s ";
        append_number(mtl_text, 1.0 / material.tile_size);
        mtl_text += ' ';
        append_number(mtl_text, 1.0 / material.tile_size);
        mtl_text += " 1 ";
      }
      mtl_text += material.texture.lexically_relative(folder).generic_string() + "\n";
    }
  }
  AtomicFileSet files;  // both or neither: a failed .obj leaves no new .mtl beside the old one
  files.add(mtl, mtl_text);
  files.add(path, obj);
  files.commit();
}

std::vector<glm::dvec3> face_points(const Mesh& mesh, Mesh::FaceHandle f) {
  std::vector<glm::dvec3> pts;
  for (const auto v : mesh.fv_range(f)) {
    const Mesh::Point& p = mesh.point(v);
    pts.push_back({p[0], p[1], p[2]});
  }
  return pts;
}

// One GIS building per run of parts with the same building and feature, as
// to_gltf joins them; the parts' own faces only.
std::vector<GisBuilding> to_gis(const MeshSet& set) {
  std::vector<GisBuilding> out;
  for (std::size_t i = 0; i < set.parts.size(); ++i) {
    const TaggedMesh& part = set.parts[i];
    if (i == 0 || set.parts[i - 1].building != part.building || set.parts[i - 1].feature != part.feature) {
      GisBuilding& b = out.emplace_back();
      b.id = part.building.empty() ? "mesh_" + std::to_string(i) : part.building;
      b.properties = part.properties;
    }
    GisBuilding& b = out.back();
    b.shells.push_back(b.faces.size());
    for (const auto f : part.mesh->faces()) {
      std::vector<glm::dvec3> pts = face_points(*part.mesh, f);
      for (std::size_t k = 1; k + 1 < pts.size(); ++k) b.volume += glm::dot(pts[0], glm::cross(pts[k], pts[k + 1])) / 6.0;
      b.faces.push_back(std::move(pts));
      b.face_tags.push_back(face_tag(part, static_cast<std::size_t>(f.idx())));
    }
  }
  return out;
}

}  // namespace

GltfScene to_gltf(const MeshSet& set, std::shared_ptr<GltfPrototypeMemo> prototypes) {
  GltfSceneBuilder builder(std::move(prototypes));
  for (std::size_t i = 0; i < set.parts.size(); ++i) {
    const TaggedMesh& part = set.parts[i];
    const TaggedMeshView view{part.mesh.get(), part.face_tags, part.tags, part.building, part.feature, part.materials};
    const bool same_building = i > 0 && set.parts[i - 1].building == part.building && set.parts[i - 1].feature == part.feature;
    if (same_building) {
      append_to_gltf_mesh(builder.last(), view);
    } else {
      GltfMeshData building = to_gltf_mesh(view, local_origin(*part.mesh));
      building.properties = part.properties;
      building.parameters = part.parameters;
      builder.add(std::move(building));
    }
    builder.place(part.placed);
  }
  return std::move(builder).take();
}

TaggedMesh flattened(const TaggedMesh& part) {
  if (part.placed.instances.empty()) return part;
  PlacementResult all = part.placed;
  all.building = part.mesh;
  auto mesh = std::make_shared<const Mesh>(flatten(all));
  TaggedMesh out = part;
  out.placed = {};
  out.materials = flattened_materials(part.materials, all);
  // The part's own faces come first, as they were; then the instances' faces.
  const std::size_t own = part.mesh->n_faces();
  const auto tags = face_tag_property(*mesh);
  for (std::size_t f = own; f < mesh->n_faces(); ++f) {
    const std::string& tag = mesh->property(tags, Mesh::FaceHandle(static_cast<int>(f)));
    auto it = std::find(out.tags.begin(), out.tags.end(), tag);
    if (it == out.tags.end()) it = out.tags.insert(out.tags.end(), tag);
    out.face_tags.push_back(static_cast<std::uint32_t>(it - out.tags.begin()));
  }
  out.mesh = std::move(mesh);
  return out;
}

bool is_mesh_file(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".obj" || ext == ".ply" || ext == ".glb";
}

bool is_gis_file(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".gpkg" || ext == ".json";
}

std::optional<std::string> output_crs_problem(const std::filesystem::path& path, const std::string& crs) {
  const std::string ext = lower_extension(path);
  if (ext == ".gpkg" || (ext == ".glb" && !crs.empty())) return crs_problem(crs);
  if (ext == ".json") return cityjson_crs_problem(crs);
  return std::nullopt;
}

const std::vector<std::string>& export_extensions() {
  static const std::vector<std::string> extensions = {".glb", ".obj", ".ply", ".gpkg", ".json"};
  return extensions;
}

void write_mesh_set(const std::filesystem::path& path, const MeshSet& set, const ExportOptions& options) {
  const std::string ext = lower_extension(path);
  if (ext == ".glb") {
    GltfScene scene = to_gltf(set);
    set_gltf_crs(scene, options.crs, path);
    return write_glb(path, scene);
  }
  if (ext == ".gpkg") return write_geopackage(path, options.crs, to_gis(set));
  if (ext == ".json") return write_cityjson(path, options.crs, to_gis(set));
  MeshSet flat;
  for (const TaggedMesh& part : set.parts) flat.parts.push_back(flattened(part));
  if (ext == ".obj") return write_tagged_obj(path, flat, options.up);
  if (ext == ".ply") {
    std::vector<NamedMesh> named;
    for (const TaggedMesh& part : flat.parts) named.push_back({part.building, part.mesh.get()});
    return write_ply(path, named, options.up);
  }
  throw IoError("cannot write '" + path.string() + "': unknown mesh format '" + ext + "' (use .obj, .ply, .glb, .gpkg or .city.json)",
                path.string());
}

}  // namespace procex

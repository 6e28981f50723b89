#include "app/studio/editor/preview_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <typeindex>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>

#include "core/geom/convex_partition.h"
#include "core/io/up_axis.h"
#include "core/mesh/material.h"
#include "core/mesh/uv_frames.h"
#include "core/placement/placement.h"

namespace procex::studio {

const TagSummary* PreviewMesh::tag(std::string_view name) const {
  for (const TagSummary& t : tags)
    if (t.name == name) return &t;
  return nullptr;
}

std::vector<const TaggedMesh*> meshes_in(const Value& v) {
  std::vector<const TaggedMesh*> out;
  if (const MeshSet* set = v.empty() || v.type()->cpp_type() != std::type_index(typeid(MeshSet)) ? nullptr : static_cast<const MeshSet*>(v.raw()))
    for (const TaggedMesh& part : set->parts)
      if (part.mesh) out.push_back(&part);
  return out;
}

std::string preview_tag(const TaggedMesh& part, Mesh::FaceHandle f) {
  const auto i = static_cast<std::size_t>(f.idx());
  if (i < part.face_tags.size() && part.face_tags[i] < part.tags.size() && !part.tags[part.face_tags[i]].empty())
    return part.tags[part.face_tags[i]];
  OpenMesh::FPropHandleT<FaceKind> kind;
  if (part.mesh->get_property_handle(kind, kFaceKindProperty)) return face_kind_name(part.mesh->property(kind, f));
  return "face";
}

glm::vec3 tag_color(std::string_view tag) {
  static const std::map<std::string, glm::vec3, std::less<>> fixed = {
      {"wall", {0.86f, 0.74f, 0.52f}},   {"side", {0.86f, 0.74f, 0.52f}},  {"roof", {0.78f, 0.24f, 0.18f}},
      {"cap", {0.25f, 0.55f, 0.80f}},    {"base", {0.45f, 0.45f, 0.45f}},  {"eave", {0.95f, 0.55f, 0.15f}},
      {"soffit", {0.60f, 0.35f, 0.70f}}, {"window", {0.30f, 0.75f, 0.85f}}, {"chimney", {0.55f, 0.30f, 0.25f}},
      {"gable", {0.80f, 0.65f, 0.30f}},  {"dormer", {0.35f, 0.70f, 0.35f}}, {"floor", {0.70f, 0.70f, 0.55f}},
  };
  if (auto it = fixed.find(tag); it != fixed.end()) return it->second;
  // FNV-1a of the name picks a hue; saturation and value stay moderate.
  std::uint32_t h = 2166136261u;
  for (char c : tag) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  const float hue = static_cast<float>(h % 360u) / 60.0f;
  const float s = 0.55f, val = 0.85f;
  const float c = val * s, x = c * (1.0f - std::fabs(std::fmod(hue, 2.0f) - 1.0f)), m = val - c;
  const std::array<glm::vec3, 6> sectors = {glm::vec3{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  return sectors[static_cast<std::size_t>(hue) % 6] + glm::vec3(m);
}

namespace {

// Triangles of one planar polygon, as index triples into `pts`.
std::vector<std::array<std::size_t, 3>> triangulate(const std::vector<glm::dvec3>& pts, const glm::dvec3& normal) {
  std::vector<std::array<std::size_t, 3>> tris;
  if (pts.size() < 3) return tris;
  // Project onto the plane's two axes with the largest extent, keeping orientation.
  const glm::dvec3 a = glm::abs(normal);
  const int drop = a.z >= a.x && a.z >= a.y ? 2 : (a.y >= a.x ? 1 : 0);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = normal[drop] >= 0 ? 1.0 : -1.0;
  std::vector<glm::dvec2> loop;
  loop.reserve(pts.size());
  for (const glm::dvec3& p : pts) loop.emplace_back(p[u], sign * p[v]);
  std::vector<std::vector<std::uint32_t>> pieces;
  if (is_convex(loop)) {
    pieces.emplace_back();
    for (std::uint32_t i = 0; i < loop.size(); ++i) pieces.back().push_back(i);
  } else {
    try {
      pieces = convex_partition({loop});
    } catch (const std::invalid_argument&) {
      pieces.clear();  // a degenerate face: drawn as a fan below, best effort
    }
    if (pieces.empty()) {
      pieces.emplace_back();
      for (std::uint32_t i = 0; i < loop.size(); ++i) pieces.back().push_back(i);
    }
  }
  for (const auto& piece : pieces)
    for (std::size_t k = 1; k + 1 < piece.size(); ++k) tris.push_back({piece[0], piece[k], piece[k + 1]});
  return tris;
}

void push(std::vector<float>& out, const glm::dvec3& p) {
  out.push_back(static_cast<float>(p.x));
  out.push_back(static_cast<float>(p.y));
  out.push_back(static_cast<float>(p.z));
}

void push_vertex(std::vector<float>& out, const glm::dvec3& p, const glm::dvec3& normal, const glm::vec3& color,
                 const glm::dvec2& uv = {0, 0}) {
  push(out, p);
  push(out, normal);
  out.insert(out.end(), {color.r, color.g, color.b, static_cast<float>(uv.x), static_cast<float>(uv.y)});
}

// How a face looks: its colour, and its texture (an index into
// PreviewMesh::textures, -1 for none) repeating every tile_size units of its
// texture coordinates.
struct Look {
  glm::vec3 color{0.0f};
  int texture = -1;
  double tile_size = 1.0;
};

// Vertices by texture (bucket 0: none, bucket t + 1: texture t), joined into
// one array of runs at the end so each texture is one draw.
class Buckets {
 public:
  std::vector<float>& of(int texture) {
    const auto b = static_cast<std::size_t>(texture + 1);
    if (buckets_.size() <= b) buckets_.resize(b + 1);
    return buckets_[b];
  }
  void join(std::vector<float>& vertices, std::vector<PreviewRange>& ranges) {
    for (std::size_t b = 0; b < buckets_.size(); ++b) {
      if (buckets_[b].empty()) continue;
      ranges.push_back({vertices.size() / PreviewMesh::kFloatsPerVertex, buckets_[b].size() / PreviewMesh::kFloatsPerVertex,
                        static_cast<int>(b) - 1});
      vertices.insert(vertices.end(), buckets_[b].begin(), buckets_[b].end());
    }
    buckets_.clear();
  }

 private:
  std::vector<std::vector<float>> buckets_;
};

std::vector<glm::dvec3> face_points(const Mesh& mesh, Mesh::FaceHandle f) {
  std::vector<glm::dvec3> pts;
  for (Mesh::VertexHandle vh : mesh.fv_range(f)) {
    const auto& p = mesh.point(vh);
    pts.emplace_back(p[0], p[1], p[2]);
  }
  return pts;
}

// Newell's normal: robust for any planar polygon, its length is twice the area.
glm::dvec3 newell(const std::vector<glm::dvec3>& pts) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const glm::dvec3& a = pts[i];
    const glm::dvec3& b = pts[(i + 1) % pts.size()];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

glm::dvec3 unit_or_up(const glm::dvec3& n) {
  const double len = glm::length(n);
  return len > 0 ? n / len : glm::dvec3(0, 0, 1);
}

// The smallest axis-aligned box holding the points added.
struct Box {
  glm::dvec3 lo{0.0}, hi{0.0};
  bool empty = true;
  void add(const glm::dvec3& p) {
    lo = empty ? p : glm::min(lo, p);
    hi = empty ? p : glm::max(hi, p);
    empty = false;
  }
  glm::dvec3 centre() const { return 0.5 * (lo + hi); }
};

// Appends the triangles of polygon `pts` (Newell normal `n`) with `look`,
// its corners' texture coordinates at `uvs` (pts.size() of them) when it has
// a texture.
void append_face(Buckets& out, const std::vector<glm::dvec3>& pts, const glm::dvec3& n, const Look& look,
                 const glm::dvec2* uvs) {
  const glm::dvec3 unit = unit_or_up(n);
  const bool textured = look.texture >= 0 && uvs;
  std::vector<float>& into = out.of(textured ? look.texture : -1);
  for (const auto& tri : triangulate(pts, unit))
    for (std::size_t i : tri) push_vertex(into, pts[i], unit, look.color, textured ? uvs[i] / look.tile_size : glm::dvec2(0.0));
}

// Where each face's corners start in SurfaceAttributes::corner_uvs.
std::vector<std::size_t> first_corners(const Mesh& mesh) {
  std::vector<std::size_t> first(mesh.n_faces() + 1, 0);
  for (const auto f : mesh.faces())
    first[static_cast<std::size_t>(f.idx()) + 1] = first[static_cast<std::size_t>(f.idx())] + mesh.valence(f);
  return first;
}

class Builder {
 public:
  // Positions are drawn relative to `origin` (PreviewMesh::origin).
  Builder(PreviewMesh& out, const glm::dvec3& origin) : out_(out) { out_.origin = origin; }

  TagSummary& tag(const std::string& name) {
    TagSummary& t = tags_[name];
    if (t.name.empty()) {
      t.name = name;
      t.color = tag_color(name);
    }
    return t;
  }
  void count_face(TagSummary& t, const glm::dvec3& n) {
    const double area = 0.5 * glm::length(n);
    ++t.faces;
    t.area += area;
    if (n.z > 0) t.area_up += area;
    ++out_.faces;
  }
  void extend(const glm::dvec3& p) {
    bounds_.add(p);
    out_.min = bounds_.lo;
    out_.max = bounds_.hi;
  }

  void add_building(const TaggedMesh& part) {
    const Mesh& mesh = *part.mesh;
    ++out_.meshes;
    const Materials& materials = materials_of(part.materials);
    const MeshUvs uvs(mesh, materials);
    for (Mesh::FaceHandle f : mesh.faces()) {
      std::vector<glm::dvec3> pts = face_points(mesh, f);
      if (pts.size() < 3) continue;
      for (glm::dvec3& p : pts) {
        extend(p);
        p -= out_.origin;
      }
      const glm::dvec3 n = newell(pts);
      TagSummary& t = tag(preview_tag(part, f));
      count_face(t, n);
      append_face(building_, pts, n, look(t, t.name, materials), uvs.of(f));
    }
    for (Mesh::EdgeHandle e : mesh.edges()) {
      const Mesh::HalfedgeHandle h = mesh.halfedge_handle(e, 0);
      for (Mesh::VertexHandle vh : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)}) {
        const auto& p = mesh.point(vh);
        push(out_.edge_points, glm::dvec3(p[0], p[1], p[2]) - out_.origin);
      }
    }
    for (const Instance& in : part.placed.instances)
      if (in.mesh < part.placed.meshes.size() && part.placed.meshes[in.mesh].mesh) add_instance(part.placed.meshes[in.mesh], in);
    for (const ResolvedAnchor& a : part.anchors) out_.anchors.push_back({part.building, a});
  }

  // A building of a .glb: its primitives' triangles, joined into the faces
  // they came from, back in procex's frame; then its placed meshes.
  void add_glb_building(const GltfScene& scene, const GltfMeshData& building) {
    ++out_.meshes;
    const glm::dvec3 origin(building.origin[0], building.origin[1], building.origin[2]);
    for (const GltfPrimitiveData& prim : building.primitives) {
      TagSummary& t = tag(prim.tag.empty() ? "face" : prim.tag);
      const Look l = glb_look(t, prim);
      for_each_glb_face(prim, origin, out_.origin, [&](const std::vector<glm::dvec3>& corners, const glm::dvec3& n, const std::vector<glm::dvec2>& uvs) {
        count_face(t, n);
        append_triangles(building_, corners, n, l, uvs);
        for (const glm::dvec3& p : corners) extend(out_.origin + p);
      }, out_.edge_points);
    }
    // Instance transforms are in glTF's frame, from the building's origin: R^-1 T(origin) M R in procex's.
    const glm::dmat4 r = file_axes_matrix(UpAxis::Y);
    glm::dmat4 at_origin(1.0);
    at_origin[3] = glm::dvec4(origin, 1.0);
    for (const GltfInstanceData& in : building.instances) {
      const glm::dmat4 m = glm::transpose(r) * at_origin * in.transform * r;
      if (in.prototype >= scene.prototypes.size() || !transform_problem(m).empty()) continue;  // the reader refuses these
      place(glb_prototype(scene.prototypes[in.prototype], in.prototype, in.tag), m);
    }
  }

  // After every building: the sizes of the markers follow the scene's.
  void finish() {
    const glm::dvec3 extent = out_.max - out_.min;
    const double size = std::clamp(0.05 * std::max({extent.x, extent.y, extent.z}), 0.3, 1.5);
    for (const PreviewAnchor& a : out_.anchors)
      if (a.anchor.present) add_marker(a.anchor.frame, size);
    for (auto& [name, t] : tags_) out_.tags.push_back(std::move(t));
    building_.join(out_.vertices, out_.ranges);
  }

 private:
  // A placed mesh's faces, in its own coordinates: tag and Newell normal.
  struct Prototype {
    std::size_t group = 0;
    std::vector<std::pair<TagSummary*, glm::dvec3>> faces;
    Box bounds;
    // A face of tag `t`, area vector `n`, through points `pts` (its bounds).
    void add_face(TagSummary& t, const glm::dvec3& n, const std::vector<glm::dvec3>& pts) {
      faces.emplace_back(&t, n);
      for (const glm::dvec3& p : pts) bounds.add(p);
    }
  };

  // Each corner's texture coordinates of a mesh whose materials show a
  // texture (core/mesh/uv_frames.h: metres, or a placed mesh's own), else none.
  struct MeshUvs {
    SurfaceAttributes surface;
    std::vector<std::size_t> first;
    MeshUvs(const Mesh& mesh, const Materials& m) {
      if (std::none_of(m.begin(), m.end(), [](const auto& e) { return !e.second.texture.empty(); })) return;
      surface = surface_attributes(mesh, local_origin(mesh));  // small numbers for float32
      first = first_corners(mesh);
    }
    const glm::dvec2* of(Mesh::FaceHandle f) const {
      return first.empty() ? nullptr : surface.corner_uvs.data() + first[static_cast<std::size_t>(f.idx())];
    }
  };

  // The look of faces shown as tag `t` whose material (if any) is the one
  // `materials` (a mesh's, carried beside it) has for `material_tag`. A tag's
  // summary takes the first material seen for it.
  Look look(TagSummary& t, const std::string& material_tag, const Materials& materials) {
    const auto m = materials.find(material_tag);
    if (m == materials.end()) return {t.color, -1, 1.0};
    const Material& mat = m->second;
    Look l{glm::vec3(mat.colour[0], mat.colour[1], mat.colour[2]), -1, mat.tile_size};
    if (mat.image) l.texture = texture(mat.image, l.color);
    return summarise(t, l);
  }
  Look glb_look(TagSummary& t, const GltfPrimitiveData& prim) {
    if (!prim.material) return {t.color, -1, 1.0};
    const GltfMaterialData& m = *prim.material;
    Look l{glm::vec3(m.colour[0], m.colour[1], m.colour[2]), -1, m.tile_size};
    if (m.image && !prim.uvs.empty()) l.texture = texture(m.image, l.color);
    return summarise(t, l);
  }
  const Look& summarise(TagSummary& t, const Look& l) {
    if (materials_seen_.insert(t.name).second) {
      t.color = l.color;
      t.texture = l.texture;
    }
    return l;
  }
  // The index of an image in PreviewMesh::textures, decoded on first use; -1 if it does not decode.
  int texture(const std::shared_ptr<const std::string>& image, const glm::vec3& tint) {
    const auto [it, fresh] = textures_.try_emplace(image, -1);
    if (fresh) {
      PreviewTexture decoded = decode_texture(*image, tint);
      if (decoded.width > 0) {
        it->second = static_cast<int>(out_.textures.size());
        out_.textures.push_back(std::move(decoded));
      }
    }
    return it->second;
  }

  void add_instance(const PlaceableMesh& placed, const Instance& in) {
    if (!transform_problem(in.transform).empty()) return;  // Mesh Placement refuses these; never drawn
    place(prototype(placed, in.tag), in.transform);
  }

  // One placement of a prototype: its faces counted where they land, its matrices for the instanced draw.
  void place(Prototype& proto, const glm::dmat4& m) {
    const glm::dmat3 linear(m);
    // Faces map by the cofactor matrix: det * inverse transpose (area and orientation).
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    const glm::dmat3 cofactor = glm::determinant(linear) * normal_matrix;
    for (auto& [t, n] : proto.faces) count_face(*t, cofactor * n);
    const Box& b = proto.bounds;
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 corner((c & 1 ? b.hi : b.lo).x, (c & 2 ? b.hi : b.lo).y, (c & 4 ? b.hi : b.lo).z);
      extend(glm::dvec3(m * glm::dvec4(corner, 1.0)));
    }
    glm::dmat4 shown = m;
    shown[3] -= glm::dvec4(out_.origin, 0.0);
    std::vector<float>& out = out_.placed[proto.group].transforms;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) out.push_back(static_cast<float>(shown[c][r]));
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) out.push_back(static_cast<float>(normal_matrix[c][r]));
    ++out_.instances;
  }

  // The triangles of a placed mesh under an instance tag, made on first use.
  Prototype& prototype(const PlaceableMesh& placed, const std::string& instance_tag) {
    auto [it, fresh] = prototypes_.try_emplace({placed.mesh.get(), instance_tag, placed.name, placed.materials.get()});
    Prototype& proto = it->second;
    if (!fresh) return proto;
    proto.group = out_.placed.size();
    out_.placed.emplace_back();
    const Mesh& mesh = *placed.mesh;
    const auto own_tags = face_tag_property(mesh);
    const Materials& materials = materials_of(placed.materials);
    const MeshUvs uvs(mesh, materials);
    Buckets vertices;
    for (Mesh::FaceHandle f : mesh.faces()) {
      const std::vector<glm::dvec3> pts = face_points(mesh, f);
      if (pts.size() < 3) continue;
      // As core's flatten() tags an instance's faces: the instance's tag, the face's own, the mesh's name;
      // the look is the face's own material's, as the .glb shows it.
      const std::string* own = own_tags.is_valid() ? &mesh.property(own_tags, f) : nullptr;
      const std::string& own_tag = own && !own->empty() ? *own : placed.name;
      TagSummary& t = tag(!instance_tag.empty() ? instance_tag : own_tag);
      const glm::dvec3 n = newell(pts);
      proto.add_face(t, n, pts);
      append_face(vertices, pts, n, look(t, own_tag, materials), uvs.of(f));
    }
    PreviewInstances& group = out_.placed[proto.group];
    vertices.join(group.vertices, group.ranges);
    return proto;
  }

  // The triangles of one primitive grouped into the faces they were cut from
  // (the writer gives each face its own vertices, so triangles sharing a
  // vertex are one face), each with its corners' triangles (three points
  // each, procex's frame, relative to `shown_from`), its area vector and its
  // corners' texture coordinates (none if the primitive has none); the faces'
  // outlines (edges of one triangle only) go to `edges`. `origin`: the
  // building's, in the file's frame.
  template <class Fn>
  static void for_each_glb_face(const GltfPrimitiveData& prim, const glm::dvec3& origin, const glm::dvec3& shown_from, Fn&& fn,
                                std::vector<float>& edges) {
    const std::size_t n_vertices = prim.positions.size() / 3;
    std::vector<std::size_t> root(n_vertices);
    std::iota(root.begin(), root.end(), std::size_t{0});
    const auto find = [&](std::size_t v) {
      while (root[v] != v) v = root[v] = root[root[v]];
      return v;
    };
    std::map<std::size_t, std::vector<std::size_t>> faces;  // root vertex -> its triangles' first index
    for (std::size_t i = 0; i + 2 < prim.indices.size(); i += 3) {
      const std::uint32_t a = prim.indices[i], b = prim.indices[i + 1], c = prim.indices[i + 2];
      if (a >= n_vertices || b >= n_vertices || c >= n_vertices) continue;  // the reader refuses these
      root[find(b)] = find(a);
      root[find(c)] = find(a);
    }
    for (std::size_t i = 0; i + 2 < prim.indices.size(); i += 3)
      if (prim.indices[i] < n_vertices && prim.indices[i + 1] < n_vertices && prim.indices[i + 2] < n_vertices) faces[find(prim.indices[i])].push_back(i);
    const auto at = [&](std::uint32_t v) {
      return from_file_axes(origin + glm::dvec3(prim.positions[3 * v], prim.positions[3 * v + 1], prim.positions[3 * v + 2]), UpAxis::Y) -
             shown_from;
    };
    const bool has_uvs = prim.uvs.size() == 2 * n_vertices;
    for (const auto& [face_root, tris] : faces) {
      std::vector<glm::dvec3> corners;
      std::vector<glm::dvec2> uvs;
      glm::dvec3 n(0.0);
      std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
      for (std::size_t i : tris) {
        const std::uint32_t v[3] = {prim.indices[i], prim.indices[i + 1], prim.indices[i + 2]};
        for (int k = 0; k < 3; ++k) {
          corners.push_back(at(v[k]));
          // glTF's v runs down the image, the preview's up: (u, -v) is the same place, a whole tile apart.
          if (has_uvs) uvs.emplace_back(prim.uvs[2 * v[k]], -prim.uvs[2 * v[k] + 1]);
          ++uses[std::minmax(v[k], v[(k + 1) % 3])];
        }
        n += glm::cross(corners[corners.size() - 2] - corners[corners.size() - 3], corners.back() - corners[corners.size() - 3]);
      }
      for (const auto& [edge, count] : uses)
        if (count == 1) {
          push(edges, at(edge.first));
          push(edges, at(edge.second));
        }
      fn(corners, n, uvs);
    }
  }

  // Triangles given as corners, three by three, under one face's normal.
  static void append_triangles(Buckets& out, const std::vector<glm::dvec3>& corners, const glm::dvec3& n, const Look& look,
                               const std::vector<glm::dvec2>& uvs) {
    const glm::dvec3 unit = unit_or_up(n);
    const bool textured = look.texture >= 0 && uvs.size() == corners.size();
    std::vector<float>& into = out.of(textured ? look.texture : -1);
    for (std::size_t i = 0; i < corners.size(); ++i)
      push_vertex(into, corners[i], unit, look.color, textured ? uvs[i] / look.tile_size : glm::dvec2(0.0));
  }

  // A .glb's placed mesh under an instance tag, made on first use.
  Prototype& glb_prototype(const GltfMeshData& placed, std::size_t index, const std::string& instance_tag) {
    auto [it, fresh] = glb_prototypes_.try_emplace({index, instance_tag});
    Prototype& proto = it->second;
    if (!fresh) return proto;
    proto.group = out_.placed.size();
    out_.placed.emplace_back();
    std::vector<float> unused_edges;
    Buckets vertices;
    for (const GltfPrimitiveData& prim : placed.primitives) {
      TagSummary& t = tag(!instance_tag.empty() ? instance_tag : !prim.tag.empty() ? prim.tag : placed.building);
      const Look l = glb_look(t, prim);
      for_each_glb_face(prim, glm::dvec3(0.0), glm::dvec3(0.0), [&](const std::vector<glm::dvec3>& corners, const glm::dvec3& n, const std::vector<glm::dvec2>& uvs) {
        proto.add_face(t, n, corners);
        append_triangles(vertices, corners, n, l, uvs);
      }, unused_edges);
    }
    PreviewInstances& group = out_.placed[proto.group];
    vertices.join(group.vertices, group.ranges);
    return proto;
  }

  void add_marker(const Frame& fr, double size) {
    const glm::dvec3 o = fr.origin - out_.origin + 0.02 * size * fr.normal;  // just off the face
    const glm::dvec3 a = 0.5 * size * fr.along, u = 0.5 * size * fr.up;
    const glm::dvec3 c[4] = {o - a - u, o + a - u, o + a + u, o - a + u};
    for (int i : {0, 1, 2, 0, 2, 3}) push_vertex(out_.marker_triangles, c[i], fr.normal, PreviewMesh::kAnchorColor);
    const std::pair<glm::dvec3, glm::vec3> axes[3] = {{fr.along, {1.0f, 0.2f, 0.2f}}, {fr.up, {0.2f, 1.0f, 0.2f}}, {fr.normal, {0.3f, 0.4f, 1.0f}}};
    for (const auto& [dir, color] : axes) {
      push_vertex(out_.marker_lines, o, fr.normal, color);
      push_vertex(out_.marker_lines, o + 1.5 * size * dir, fr.normal, color);
    }
  }

  PreviewMesh& out_;
  Buckets building_;  // the buildings' triangles, joined into out_.vertices by finish()
  std::map<std::shared_ptr<const std::string>, int> textures_;  // images (by address: shared by the writers' caches) to indices
  std::set<std::string> materials_seen_;  // tags whose summary has a material's colour
  std::map<std::string, TagSummary> tags_;  // std::map: references stay valid as tags are added
  // By mesh, instance tag, name and materials (the parts being previewed hold both).
  std::map<std::tuple<const Mesh*, std::string, std::string, const Materials*>, Prototype> prototypes_;
  std::map<std::pair<std::size_t, std::string>, Prototype> glb_prototypes_;
  Box bounds_;  // out_.min and out_.max
};

// The centre of the buildings' bounds (their placed meshes stand on them).
glm::dvec3 centre_of(const std::vector<const TaggedMesh*>& meshes) {
  Box box;
  for (const TaggedMesh* part : meshes)
    for (Mesh::VertexHandle v : part->mesh->vertices()) {
      const auto& p = part->mesh->point(v);
      box.add(glm::dvec3(p[0], p[1], p[2]));
    }
  return box.centre();
}

glm::dvec3 centre_of(const GltfScene& scene) {
  Box box;
  for (const GltfMeshData& building : scene.meshes)
    for (const GltfPrimitiveData& prim : building.primitives)
      for (std::size_t i = 0; i + 2 < prim.positions.size(); i += 3)
        box.add(from_file_axes(glm::dvec3(building.origin[0] + prim.positions[i], building.origin[1] + prim.positions[i + 1],
                                          building.origin[2] + prim.positions[i + 2]),
                               UpAxis::Y));
  return box.centre();
}

}  // namespace

std::size_t PreviewMesh::absent_anchors() const {
  return static_cast<std::size_t>(std::count_if(anchors.begin(), anchors.end(), [](const PreviewAnchor& a) { return !a.anchor.present; }));
}

PreviewMesh make_preview(const std::vector<const TaggedMesh*>& meshes) {
  PreviewMesh out;
  Builder builder(out, centre_of(meshes));
  for (const TaggedMesh* part : meshes) builder.add_building(*part);
  builder.finish();
  return out;
}

PreviewMesh make_preview(const GltfScene& scene) {
  PreviewMesh out;
  Builder builder(out, centre_of(scene));
  for (const GltfMeshData& building : scene.meshes) builder.add_glb_building(scene, building);
  builder.finish();
  return out;
}

}  // namespace procex::studio

#include "app/studio/editor/preview_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <typeindex>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/geom/convex_partition.h"

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

}  // namespace

PreviewMesh make_preview(const std::vector<const TaggedMesh*>& meshes) {
  PreviewMesh out;
  std::map<std::string, TagSummary> tags;
  bool first = true;
  for (const TaggedMesh* part : meshes) {
    const Mesh* mesh = part->mesh.get();
    ++out.meshes;
    for (Mesh::FaceHandle f : mesh->faces()) {
      std::vector<glm::dvec3> pts;
      for (Mesh::VertexHandle vh : mesh->fv_range(f)) {
        const auto& p = mesh->point(vh);
        pts.emplace_back(p[0], p[1], p[2]);
      }
      if (pts.size() < 3) continue;
      // Newell's normal: robust for any planar polygon, its length is twice the area.
      glm::dvec3 n(0.0);
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const glm::dvec3& a = pts[i];
        const glm::dvec3& b = pts[(i + 1) % pts.size()];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
      }
      const double len = glm::length(n);
      const glm::dvec3 unit = len > 0 ? n / len : glm::dvec3(0, 0, 1);
      const std::string name = preview_tag(*part, f);
      TagSummary& t = tags[name];
      if (t.name.empty()) {
        t.name = name;
        t.color = tag_color(name);
      }
      ++t.faces;
      t.area += 0.5 * len;
      if (unit.z > 0) t.area_up += 0.5 * len;
      for (const auto& tri : triangulate(pts, unit)) {
        for (std::size_t i : tri) {
          push(out.vertices, pts[i]);
          push(out.vertices, unit);
          out.vertices.insert(out.vertices.end(), {t.color.r, t.color.g, t.color.b});
        }
      }
      for (const glm::dvec3& p : pts) {
        out.min = first ? p : glm::min(out.min, p);
        out.max = first ? p : glm::max(out.max, p);
        first = false;
      }
      ++out.faces;
    }
    for (Mesh::EdgeHandle e : mesh->edges()) {
      const Mesh::HalfedgeHandle h = mesh->halfedge_handle(e, 0);
      for (Mesh::VertexHandle vh : {mesh->from_vertex_handle(h), mesh->to_vertex_handle(h)}) {
        const auto& p = mesh->point(vh);
        push(out.edge_points, glm::dvec3(p[0], p[1], p[2]));
      }
    }
  }
  for (auto& [name, t] : tags) out.tags.push_back(std::move(t));
  return out;
}

}  // namespace procex::studio

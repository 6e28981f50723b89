// Registers the building value types with the graph (hash and memory size of
// each: the cache keys bound footprints by content and bounds itself in bytes).
#include "nodes/values.h"

#include <algorithm>

#include "graph/value.h"
#include "nodes/support/level_of_detail.h"

namespace procex {
namespace {

void hash_vec2(const glm::dvec2& p, Hasher& h) { h.f64(p.x).f64(p.y); }

void hash_profile(const Profile& p, Hasher& h) {
  h.str(p.name).u64(p.points.size());
  for (const glm::dvec2& q : p.points) hash_vec2(q, h);
  h.u64(p.tags.size());
  for (const std::string& t : p.tags) h.u64(t.size()).str(t);
}

std::size_t strings_size(const std::vector<std::string>& v) {
  std::size_t n = v.capacity() * sizeof(std::string);
  for (const std::string& s : v) n += s.capacity();
  return n;
}

std::size_t profile_size(const Profile& p) {
  return sizeof(Profile) + p.name.capacity() + p.points.capacity() * sizeof(glm::dvec2) + strings_size(p.tags);
}

void hash_footprint(const Footprint& fp, Hasher& h) {
  h.u64(fp.loops.size());
  for (const Loop& loop : fp.loops) {
    h.u64(loop.points.size());
    for (const glm::dvec2& p : loop.points) hash_vec2(p, h);
    h.u64(loop.edges.size());
    for (const EdgeSpec& e : loop.edges) h.f64(e.angle_deg).i64(e.id).i64(e.profile);
  }
  h.u64(fp.profiles.size());
  for (const Profile& p : fp.profiles) hash_profile(p, h);
}

std::size_t footprint_size(const Footprint& fp) {
  std::size_t n = sizeof(Footprint) + fp.loops.capacity() * sizeof(Loop);
  for (const Loop& loop : fp.loops)
    n += loop.points.capacity() * sizeof(glm::dvec2) + loop.edges.capacity() * sizeof(EdgeSpec);
  for (const Profile& p : fp.profiles) n += profile_size(p);
  return n;
}

void hash_str(const std::string& s, Hasher& h) { h.u64(s.size()).str(s); }

void hash_vec3(const glm::dvec3& p, Hasher& h) { h.f64(p.x).f64(p.y).f64(p.z); }

void hash_anchor_spec(const AnchorSpec& s, Hasher& h) {
  const Anchor& a = s.anchor;
  hash_str(a.name, h);
  h.u64(static_cast<std::uint64_t>(a.plan.mode)).f64(a.plan.value).f64(a.height).i64(a.profile);
  h.u64(a.edges.size());
  for (const std::int32_t e : a.edges) h.i64(e);
  hash_str(s.profile, h);
}

void hash_plan_edit_spec(const PlanEditSpec& s, Hasher& h) {
  hash_anchor_spec(s.at, h);
  h.u64(s.edits.size());
  for (const PlanEdit& e : s.edits) {
    hash_str(e.name, h);
    h.u64(static_cast<std::uint64_t>(e.kind)).u64(e.shape.size());
    for (const glm::dvec2& p : e.shape) h.f64(p.x).f64(p.y);
    h.f64(e.width).f64(e.depth).f64(e.spread).f64(e.offset).u64(e.edges.size());
    for (const EdgeSpec& spec : e.edges) h.f64(spec.angle_deg).i64(spec.id).i64(spec.profile);
    hash_str(e.tag, h);
  }
  h.u64(s.profiles.size());
  for (const Profile& p : s.profiles) hash_profile(p, h);
}

std::size_t plan_edit_spec_size(const PlanEditSpec& s) {
  std::size_t n = sizeof(PlanEditSpec) + s.at.profile.capacity() + s.at.anchor.name.capacity();
  for (const PlanEdit& e : s.edits)
    n += sizeof(PlanEdit) + e.name.capacity() + e.tag.capacity() + e.shape.capacity() * sizeof(glm::dvec2) +
         e.edges.capacity() * sizeof(EdgeSpec);
  for (const Profile& p : s.profiles) n += profile_size(p);
  return n;
}

std::size_t anchor_spec_size(const AnchorSpec& s) {
  return sizeof(AnchorSpec) + s.anchor.name.capacity() + s.anchor.edges.capacity() * sizeof(std::int32_t) +
         s.profile.capacity();
}

void hash_mesh(const Mesh& m, Hasher& h) {
  h.u64(m.n_vertices()).u64(m.n_faces());
  for (const auto v : m.vertices())
    for (int k = 0; k < 3; ++k) h.f64(m.point(v)[k]);
  for (const auto f : m.faces()) {
    h.u64(m.valence(f));
    for (const auto v : m.fv_range(f)) h.u64(static_cast<std::uint64_t>(v.idx()));
  }
}

void hash_anchor(const ResolvedAnchor& a, Hasher& h) {
  hash_str(a.name, h);
  h.u64(a.anchor).i64(a.edge_id).u64(a.present ? 1 : 0).u64(static_cast<std::uint64_t>(a.absence));
  hash_str(a.reason, h);
  for (const glm::dvec3& v : {a.frame.origin, a.frame.along, a.frame.up, a.frame.normal, a.span_from, a.span_to})
    hash_vec3(v, h);
}

void hash_tile(const FacadeTile& t, Hasher& h) {
  hash_str(t.name, h);
  h.i64(t.edge_id).f64(t.width).f64(t.height).i64(t.floor).i64(t.bay);
  for (const glm::dvec3& v : {t.frame.origin, t.frame.along, t.frame.up, t.frame.normal}) hash_vec3(v, h);
}

void hash_materials(const MaterialTable& table, Hasher& h) {
  const Materials& materials = materials_of(table);
  h.u64(materials.size());
  for (const auto& [tag, m] : materials) {
    hash_str(tag, h);
    for (double c : m.colour) h.f64(c);
    h.f64(m.roughness).f64(m.metallic).f64(m.tile_size);
    hash_str(m.texture.string(), h);
  }
}

// Placed meshes by content (their own face tags and materials included): two
// runs that read the same file hash alike.
void hash_placed(const PlacementResult& placed, Hasher& h) {
  h.u64(placed.meshes.size());
  for (const PlaceableMesh& m : placed.meshes) {
    hash_str(m.name, h);
    hash_mesh(*m.mesh, h);
    hash_materials(m.materials, h);
    const auto tags = face_tag_property(*m.mesh);
    if (tags.is_valid())
      for (const auto f : m.mesh->faces()) hash_str(m.mesh->property(tags, f), h);
  }
  h.u64(placed.instances.size());
  for (const Instance& in : placed.instances) {
    h.u64(in.mesh).i64(in.source_edge);
    hash_str(in.tag, h);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) h.f64(in.transform[c][r]);
  }
}

void hash_mesh_set(const MeshSet& set, Hasher& h) {
  h.u64(set.parts.size());
  for (const TaggedMesh& part : set.parts) {
    hash_str(part.building, h);
    h.i64(part.feature).u64(part.tags.size());
    for (const std::string& t : part.tags) hash_str(t, h);
    h.bytes(part.face_tags.data(), part.face_tags.size() * sizeof(std::uint32_t));
    hash_mesh(*part.mesh, h);
    hash_materials(part.materials, h);
    h.u64(part.anchors.size());
    for (const ResolvedAnchor& a : part.anchors) hash_anchor(a, h);
    h.u64(tiles_of(part).size());
    for (const FacadeTile& t : tiles_of(part)) hash_tile(t, h);
    h.u64(part.split_names.size());
    for (const std::string& n : part.split_names) hash_str(n, h);
    hash_placed(part.placed, h);
  }
}

// OpenMesh's own arrays: points, connectivity and the two face properties.
std::size_t mesh_size(const Mesh& m) {
  return sizeof(Mesh) + m.n_vertices() * (sizeof(Mesh::Point) + 16) + m.n_halfedges() * 16 + m.n_edges() * 4 +
         m.n_faces() * (8 + sizeof(int) + 1);
}

// A mesh shared by several sets is charged to each: the cache errs on the safe side.
std::size_t mesh_set_size(const MeshSet& set) {
  std::size_t n = sizeof(MeshSet) + set.parts.capacity() * sizeof(TaggedMesh);
  for (const TaggedMesh& part : set.parts) {
    n += mesh_size(*part.mesh) + part.face_tags.capacity() * sizeof(std::uint32_t) + strings_size(part.tags) +
         part.building.capacity();
    n += part.anchors.capacity() * sizeof(ResolvedAnchor);
    for (const ResolvedAnchor& a : part.anchors) n += a.name.capacity() + a.reason.capacity();
    n += tiles_of(part).capacity() * sizeof(FacadeTile);
    for (const FacadeTile& t : tiles_of(part)) n += t.name.capacity();
    for (const std::string& s : part.split_names) n += sizeof(s) + s.capacity();
    n += part.placed.instances.capacity() * sizeof(Instance) + part.placed.meshes.capacity() * sizeof(PlaceableMesh);
    for (const PlaceableMesh& m : part.placed.meshes) n += mesh_size(*m.mesh);
  }
  return n;
}

MeshSet at_level_of_detail(const MeshSet& set, int level) { return mesh_set_at_level_of_detail(set, level); }

const bool kRegistered = [] {
  ValueTypeRegistry& r = ValueTypeRegistry::global();
  r.add<Footprint>({"footprint", "Closed plan loops (outer CCW, holes CW), each edge with an angle or a profile",
                    hash_footprint, footprint_size});
  r.add<Profile>({"profile", "A polyline (outward offset, height) with a tag per segment", hash_profile, profile_size});
  r.add_list<Profile>();
  r.add<AnchorSpec>({"anchor",
                      "A named point on the footprint's edges (a position along each selected edge and a height) "
                      "that Extrude resolves on the building",
                      hash_anchor_spec, anchor_spec_size});
  r.add<PlanEditSpec>({"plan edit",
                        "Steps inserted into the building's cross-section at an anchor (bay windows, dormers, "
                        "buttresses, recesses), each new edge following its own profile",
                        hash_plan_edit_spec, plan_edit_spec_size});
  r.add<MeshSet>({"mesh",
                  "Closed meshes with a tag per face and a building id per mesh, their resolved anchors and the "
                  "meshes placed on them",
                  hash_mesh_set, mesh_set_size, nullptr, nullptr, at_level_of_detail});
  return true;
}();

}  // namespace

const std::vector<FacadeTile>& tiles_of(const TaggedMesh& part) {
  static const std::vector<FacadeTile> kNone;
  return part.tiles ? *part.tiles : kNone;
}

void face_tags_from_mesh(TaggedMesh& part) {
  const auto tags = face_tag_property(*part.mesh);
  part.face_tags.clear();
  for (const Mesh::FaceHandle f : part.mesh->faces()) {
    const std::string& tag = part.mesh->property(tags, f);
    auto it = std::find(part.tags.begin(), part.tags.end(), tag);
    if (it == part.tags.end()) it = part.tags.insert(part.tags.end(), tag);
    part.face_tags.push_back(static_cast<std::uint32_t>(it - part.tags.begin()));
  }
}

}  // namespace procex

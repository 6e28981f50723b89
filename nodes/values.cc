// Registers the building value types with the graph (hash and memory size of
// each: the cache keys bound footprints by content and bounds itself in bytes).
#include "nodes/values.h"

#include "graph/value.h"

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

void hash_mesh_set(const MeshSet& set, Hasher& h) {
  h.u64(set.parts.size());
  for (const TaggedMesh& part : set.parts) {
    h.u64(part.building.size()).str(part.building).i64(part.feature).u64(part.tags.size());
    for (const std::string& t : part.tags) h.u64(t.size()).str(t);
    h.bytes(part.face_tags.data(), part.face_tags.size() * sizeof(std::uint32_t));
    const Mesh& m = *part.mesh;
    h.u64(m.n_vertices()).u64(m.n_faces());
    for (const auto v : m.vertices())
      for (int k = 0; k < 3; ++k) h.f64(m.point(v)[k]);
    for (const auto f : m.faces()) {
      h.u64(m.valence(f));
      for (const auto v : m.fv_range(f)) h.u64(static_cast<std::uint64_t>(v.idx()));
    }
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
  for (const TaggedMesh& part : set.parts)
    n += mesh_size(*part.mesh) + part.face_tags.capacity() * sizeof(std::uint32_t) + strings_size(part.tags) +
         part.building.capacity();
  return n;
}

const bool kRegistered = [] {
  ValueTypeRegistry& r = ValueTypeRegistry::global();
  r.add<Footprint>({"footprint", "Closed plan loops (outer CCW, holes CW), each edge with an angle or a profile",
                    hash_footprint, footprint_size});
  r.add<Profile>({"profile", "A polyline (outward offset, height) with a tag per segment", hash_profile, profile_size});
  r.add_list<Profile>();
  r.add<MeshSet>({"mesh", "Closed meshes with a tag per face and a building id per mesh", hash_mesh_set, mesh_set_size});
  return true;
}();

}  // namespace
}  // namespace procex

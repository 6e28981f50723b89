#include "nodes/support/extrusion.h"

#include <algorithm>
#include <map>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/mesh/mesh.h"

namespace procex {
namespace {

// Side faces without a profile: vertical ones are walls, the rest roofs.
const char* tag_of_angle(double angle_deg) { return angle_deg == 0.0 ? "wall" : "roof"; }

// Profiles end at their last point; the building ends there too, with a flat
// cap if its roof has not closed below.
void cap_at_profile_tops(const Footprint& fp, SweepOptions& options) {
  std::optional<double> top;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges)
      if (e.profile >= 0) {
        const double y = fp.profiles[static_cast<std::size_t>(e.profile)].points.back().y;
        top = std::max(top.value_or(y), y);
      }
  if (top) options.max_height = std::min(options.max_height.value_or(*top), *top);
}

}  // namespace

Extrusion extrude(const Footprint& footprint, const SweepOptions& options) {
  for (const Profile& p : footprint.profiles) check_profile(p);
  for (const Loop& loop : footprint.loops)
    for (const EdgeSpec& e : loop.edges)
      if (e.profile >= static_cast<int>(footprint.profiles.size()))
        throw InputError("edge id " + std::to_string(e.id) + " names profile " + std::to_string(e.profile) +
                         " but the footprint has " + std::to_string(footprint.profiles.size()));
  PreparedFootprint prepared = prepare_footprint(footprint);
  Extrusion out;
  out.notes = std::move(prepared.notes);
  Footprint fp = std::move(prepared.footprint);
  SweepOptions engine_options = options;
  cap_at_profile_tops(fp, engine_options);

  std::map<std::int32_t, const EdgeSpec*> by_id;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) by_id[e.id] = &e;

  auto mesh = std::make_shared<Mesh>(build_mesh(sweep(fp, engine_options)));
  TaggedMesh& t = out.mesh;
  std::map<std::string, std::uint32_t> tag_index;
  auto index_of = [&](const std::string& tag) {
    auto [it, inserted] = tag_index.try_emplace(tag, static_cast<std::uint32_t>(t.tags.size()));
    if (inserted) t.tags.push_back(tag);
    return it->second;
  };
  const auto kinds = face_kind_property(*mesh);
  const auto edges = source_edge_property(*mesh);
  const auto tags = face_tag_property(*mesh);
  t.face_tags.reserve(mesh->n_faces());
  for (const auto f : mesh->faces()) {
    const FaceKind kind = mesh->property(kinds, f);
    if (kind != FaceKind::Side) {
      t.face_tags.push_back(index_of(face_kind_name(kind)));
      continue;
    }
    // A profile's segment tag, else wall or roof by the edge's angle.
    const std::string& tag = mesh->property(tags, f);
    const auto it = by_id.find(mesh->property(edges, f));
    t.face_tags.push_back(index_of(!tag.empty() ? tag : it == by_id.end() ? "side" : tag_of_angle(it->second->angle_deg)));
  }
  t.mesh = std::move(mesh);
  return out;
}

}  // namespace procex

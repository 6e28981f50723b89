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

// The stand-in for profile support (see extrusion.h): the engine gets plain
// angles and no profiles, so what it does cannot depend on how far its own
// profile support has come.
void engine_input(Footprint& fp, SweepOptions& options, std::vector<std::string>& notes) {
  std::optional<double> top;
  std::vector<bool> used(fp.profiles.size(), false);
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) {
      if (e.profile < 0) continue;
      const Profile& p = fp.profiles[static_cast<std::size_t>(e.profile)];
      used[static_cast<std::size_t>(e.profile)] = true;
      e.angle_deg = p.angle_deg(0);
      e.profile = -1;
      top = std::max(top.value_or(p.points.back().y), p.points.back().y);
    }
  if (!top) return;
  options.max_height = std::min(options.max_height.value_or(*top), *top);
  for (std::size_t i = 0; i < fp.profiles.size(); ++i)
    if (used[i] && fp.profiles[i].segments() > 1)
      notes.push_back("profile '" + fp.profiles[i].name + "': the sweep follows only its first segment for now");
}

std::string side_tag(const EdgeSpec& e, const std::vector<Profile>& profiles) {
  if (e.profile >= 0) {
    const Profile& p = profiles[static_cast<std::size_t>(e.profile)];
    return !p.tags.empty() && !p.tags[0].empty() ? p.tags[0] : tag_of_angle(p.angle_deg(0));
  }
  return tag_of_angle(e.angle_deg);
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
  fp.profiles = footprint.profiles;  // prepare_footprint keeps edge specs but not the profile list
  Footprint engine = fp;
  SweepOptions engine_options = options;
  engine_input(engine, engine_options, out.notes);
  engine.profiles.clear();

  std::map<std::int32_t, const EdgeSpec*> by_id;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) by_id[e.id] = &e;

  auto mesh = std::make_shared<Mesh>(build_mesh(sweep(engine, engine_options)));
  TaggedMesh& t = out.mesh;
  std::map<std::string, std::uint32_t> tag_index;
  auto index_of = [&](const std::string& tag) {
    auto [it, inserted] = tag_index.try_emplace(tag, static_cast<std::uint32_t>(t.tags.size()));
    if (inserted) t.tags.push_back(tag);
    return it->second;
  };
  const auto kinds = face_kind_property(*mesh);
  const auto edges = source_edge_property(*mesh);
  t.face_tags.reserve(mesh->n_faces());
  for (const auto f : mesh->faces()) {
    const FaceKind kind = mesh->property(kinds, f);
    if (kind != FaceKind::Side) {
      t.face_tags.push_back(index_of(face_kind_name(kind)));
      continue;
    }
    const auto it = by_id.find(mesh->property(edges, f));
    t.face_tags.push_back(index_of(it == by_id.end() ? "side" : side_tag(*it->second, fp.profiles)));
  }
  t.mesh = std::move(mesh);
  return out;
}

}  // namespace procex

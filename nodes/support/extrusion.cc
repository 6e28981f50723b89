#include "nodes/support/extrusion.h"

#include <algorithm>
#include <map>
#include <set>

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

std::string quoted_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
  return list;
}

// Edge ids as ranges: "0-7, 9, 12-13".
std::string id_ranges(const std::set<std::int32_t>& ids) {
  std::string out;
  for (auto it = ids.begin(); it != ids.end();) {
    const std::int32_t first = *it;
    std::int32_t last = first;
    while (++it != ids.end() && *it == last + 1) last = *it;
    out += (out.empty() ? "" : ", ") + std::to_string(first) + (last > first ? "-" + std::to_string(last) : "");
  }
  return out;
}

// The anchors as the sweep takes them: profile names become indices into the
// footprint's profiles. An anchor that selects no edge of this footprint (no
// edge uses its profile: a batch draws profiles per building) is dropped with
// a note; naming a profile or an edge the footprint lacks is an error.
std::vector<Anchor> engine_anchors(const Footprint& fp, const std::vector<AnchorSpec>& specs,
                                   std::vector<std::string>& notes) {
  std::set<std::int32_t> ids;
  std::vector<const EdgeSpec*> edges;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) ids.insert(e.id), edges.push_back(&e);
  std::vector<Anchor> out;
  for (const AnchorSpec& spec : specs) {
    Anchor a = spec.anchor;
    const std::string named = "anchor '" + a.name + "'";
    if (!spec.profile.empty()) {
      const auto it = std::find_if(fp.profiles.begin(), fp.profiles.end(),
                                   [&](const Profile& p) { return p.name == spec.profile; });
      if (it == fp.profiles.end()) {
        std::vector<std::string> names;
        for (const Profile& p : fp.profiles) names.push_back(p.name);
        throw InputError(named + ": the footprint has no profile named '" + spec.profile + "' (" +
                         (names.empty() ? std::string("it has no profiles") : "its profiles: " + quoted_list(names)) +
                         ")");
      }
      a.profile = static_cast<int>(it - fp.profiles.begin());
    }
    for (const std::int32_t id : a.edges)
      if (!ids.contains(id))
        throw InputError(named + ": edge id " + std::to_string(id) + " is not an edge of the footprint (its ids: " +
                         id_ranges(ids) + ")");
    const bool selects_any = std::any_of(edges.begin(), edges.end(), [&](const EdgeSpec* e) {
      return (a.profile < 0 || e->profile == a.profile) &&
             (a.edges.empty() || std::find(a.edges.begin(), a.edges.end(), e->id) != a.edges.end());
    });
    if (!selects_any) {
      notes.push_back(named + " is not placed: no " + (a.edges.empty() ? "edge" : "edge it lists") +
                      " uses profile '" + spec.profile + "' on this footprint");
      continue;
    }
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace

Extrusion extrude(const Footprint& footprint, const SweepOptions& options, const std::vector<AnchorSpec>& anchors) {
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
  engine_options.anchors = engine_anchors(fp, anchors, out.notes);

  std::map<std::int32_t, const EdgeSpec*> by_id;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) by_id[e.id] = &e;

  Surface surface = sweep(fp, engine_options);
  auto mesh = std::make_shared<Mesh>(build_mesh(surface));
  TaggedMesh& t = out.mesh;
  for (const ResolvedAnchor& a : surface.anchors)
    if (!a.present) out.notes.push_back("anchor '" + a.name + "' is absent on edge " + std::to_string(a.edge_id) + ": " + a.reason);
  t.anchors = std::move(surface.anchors);
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

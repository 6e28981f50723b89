#include "nodes/support/extrusion.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/mesh/mesh.h"

namespace procex {
namespace {

// Side faces without a profile: vertical ones are walls, the rest roofs.
const char* tag_of_angle(double angle_deg) { return angle_deg == 0.0 ? "wall" : "roof"; }

// Profiles end at their last point; the building ends there too, with a flat
// cap if its roof has not closed below. The profiles of edges a plan edit
// inserts start at its height.
void cap_at_profile_tops(const Footprint& fp, SweepOptions& options) {
  std::optional<double> top;
  auto reach = [&](const EdgeSpec& e, double base) {
    if (e.profile < 0) return;
    const double y = base + fp.profiles[static_cast<std::size_t>(e.profile)].points.back().y;
    top = std::max(top.value_or(y), y);
  };
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) reach(e, 0.0);
  for (const PlanEdit& edit : options.plan_edits)
    for (const EdgeSpec& e : edit.edges) reach(e, edit.at.height);
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

// An anchor as the sweep takes it: its profile name becomes an index into the
// footprint's profiles. Nothing (and why in `unselected`) if it selects no
// edge of this footprint (no edge uses its profile: a batch draws profiles per
// building); naming a profile or an edge the footprint lacks is an error.
std::optional<Anchor> engine_anchor(const Footprint& fp, const AnchorSpec& spec, const std::string& named,
                                    std::string& unselected) {
  std::set<std::int32_t> ids;
  std::vector<const EdgeSpec*> edges;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) ids.insert(e.id), edges.push_back(&e);
  Anchor a = spec.anchor;
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
    unselected = std::string("no ") + (a.edges.empty() ? "edge" : "edge it lists") + " uses profile '" + spec.profile +
                 "' on this footprint";
    return std::nullopt;
  }
  return a;
}

// The anchors as the sweep takes them. One that selects no edge of this
// footprint resolves absent once, with edge id -1 (in `unselected`), so that
// Mesh Placement reports it like any absent anchor.
struct EngineAnchors {
  std::vector<Anchor> anchors;
  std::vector<std::size_t> spec;           // per engine anchor, its index in the specs
  std::vector<ResolvedAnchor> unselected;  // ResolvedAnchor::anchor: the spec's index
};

EngineAnchors engine_anchors(const Footprint& fp, const std::vector<AnchorSpec>& specs) {
  EngineAnchors out;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    std::string why;
    if (auto a = engine_anchor(fp, specs[i], "anchor '" + specs[i].anchor.name + "'", why)) {
      out.anchors.push_back(std::move(*a));
      out.spec.push_back(i);
      continue;
    }
    ResolvedAnchor& r = out.unselected.emplace_back();
    r.name = specs[i].anchor.name;
    r.anchor = i;
    r.absence = Absence::Unselected;
    r.reason = std::move(why);
  }
  return out;
}

// The plan edits as the sweep takes them: placed by their anchors, their
// profiles added to the footprint's, their inserted edges numbered after the
// footprint's edges (collected in `inserted`, for tagging).
std::vector<PlanEdit> engine_plan_edits(Footprint& fp, const std::vector<PlanEditSpec>& specs,
                                        std::vector<EdgeSpec>& inserted, std::vector<std::string>& notes) {
  std::int32_t next_id = 0;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) next_id = std::max(next_id, e.id + 1);
  std::vector<PlanEdit> out;
  for (const PlanEditSpec& spec : specs) {
    const std::string named = "plan edit '" + spec.at.anchor.name + "'";
    std::string why;
    const std::optional<Anchor> at = engine_anchor(fp, spec.at, named, why);
    if (!at) {
      notes.push_back(named + " is not placed: " + why);
      continue;
    }
    const int first_profile = static_cast<int>(fp.profiles.size());
    fp.profiles.insert(fp.profiles.end(), spec.profiles.begin(), spec.profiles.end());
    for (PlanEdit edit : spec.edits) {
      edit.at = *at;
      for (EdgeSpec& e : edit.edges) {
        if (e.profile >= 0) e.profile += first_profile;
        e.id = next_id++;
        inserted.push_back(e);
      }
      out.push_back(std::move(edit));
    }
  }
  return out;
}

}  // namespace

Extrusion extrude(const Footprint& footprint, const SweepOptions& options, const std::vector<AnchorSpec>& anchors,
                  const std::vector<PlanEditSpec>& plan_edits) {
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
  EngineAnchors engine = engine_anchors(fp, anchors);
  engine_options.anchors = std::move(engine.anchors);
  std::vector<EdgeSpec> inserted;
  engine_options.plan_edits = engine_plan_edits(fp, plan_edits, inserted, out.notes);
  cap_at_profile_tops(fp, engine_options);

  std::map<std::int32_t, const EdgeSpec*> by_id;
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) by_id[e.id] = &e;
  for (const EdgeSpec& e : inserted) by_id[e.id] = &e;

  Surface surface = sweep(fp, engine_options);
  auto mesh = std::make_shared<Mesh>(build_mesh(surface));
  out.validation = roof_validation(surface);
  TaggedMesh& t = out.mesh;
  t.anchors = std::move(surface.anchors);
  for (ResolvedAnchor& a : t.anchors) a.anchor = engine.spec[a.anchor];
  for (ResolvedAnchor& a : engine.unselected) t.anchors.push_back(std::move(a));
  for (const ResolvedAnchor& a : t.anchors)
    if (!a.present)
      out.notes.push_back("anchor '" + a.name + "' is absent" +
                          (a.edge_id >= 0 ? " on edge " + std::to_string(a.edge_id) : std::string()) + ": " + a.reason);
  for (const ResolvedAnchor& e : surface.plan_edits)
    if (!e.present) out.notes.push_back("plan edit '" + e.name + "' is not applied on edge " + std::to_string(e.edge_id) + ": " + e.reason);
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

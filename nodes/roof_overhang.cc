// Roof Overhang: each building's roof run past its walls as a slab of its own
// (core/mesh/roof_overhang.h), the building's solid handed on untouched.
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/mesh/roof_overhang.h"
#include "core/mesh/validate.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter and port handles, from the declaration.
struct Handles {
  std::size_t mesh_in, eave, verge, thickness, roof_tags, on_refusal, mesh_out, skipped_out;
};
Handles h;

void declare(NodeDecl& d) {
  d.doc("Runs each building's roof past its walls: the roof's planes carried out `eave` metres (in plan) beyond "
        "walls under a level roof edge and `verge` metres beyond walls under a sloping one (a gable's rake), "
        "`thickness` thick along their normals, with a vertical fascia round the outer edge. The overhang is a "
        "closed solid of its own, added after its building (tags roof, fascia, soffit, and underside where it lies "
        "on the building's roof); the building is handed on as it was. The roof is the faces tagged one of "
        "`roof_tags` and any flat cap, one surface seen from above: gable, hip, mansard, gambrel, over a convex "
        "plan or one with valleys (L, T, U, courtyards). Give the walls flush profiles (Profile Preset `flush_eave`, `gable_end`).")
      .category("Geometry");
  h.mesh_in = d.input<MeshSet>("mesh").doc("buildings (Extrude)").index();
  h.eave = d.param<double>("eave").default_value(0.5).range(0, 20).unit("m").doc("reach past walls under level roof edges").index();
  h.verge = d.param<double>("verge").default_value(0.3).range(0, 20).unit("m").doc("reach past walls under sloping roof edges (gables)").index();
  h.thickness = d.param<double>("thickness").default_value(0.2).range(0.001, 5).unit("m").doc("the slab's thickness, square to the roof").index();
  h.roof_tags = d.param<std::string>("roof_tags").default_value(std::string("roof"))
      .doc("the tags of the roof's faces, separated by commas (a mansard's: `mansard, roof`)").index();
  h.on_refusal = d.param_enum("on_refusal", {"error", "skip"})
      .doc("a roof that cannot be run out: stop with an error naming the building, or hand the building on "
           "without a slab, counted in `skipped` (a batch keeps going; the first reason is a warning)").index();
  h.mesh_out = d.output<MeshSet>("mesh").index();
  h.skipped_out = d.output<std::int64_t>("skipped").doc("buildings handed on without a slab (on_refusal = skip)").index();
}

std::set<std::string> tag_list(const std::string& text) {
  std::set<std::string> tags;
  std::istringstream in(text);
  for (std::string t; std::getline(in, t, ',');) {
    t.erase(0, t.find_first_not_of(" \t"));
    t.erase(t.find_last_not_of(" \t") + 1);
    if (!t.empty()) tags.insert(t);
  }
  return tags;
}

void evaluate(EvalContext& ctx) {
  const RoofOverhang o{ctx.param<double>(h.eave), ctx.param<double>(h.verge), ctx.param<double>(h.thickness)};
  const std::set<std::string> roof_tags = tag_list(ctx.param<std::string>(h.roof_tags));
  const bool skip = ctx.choice(h.on_refusal) == "skip";
  std::int64_t skipped = 0;
  std::string first_reason;
  MeshSet out;
  std::set<std::string> seen;  // every tag there is, for the error when no face has one asked for
  for (const TaggedMesh& part : ctx.input<MeshSet>(h.mesh_in).parts) {
    ctx.throw_if_cancelled();
    out.parts.push_back(part);
    if (!part.mesh) continue;
    const Mesh& mesh = *part.mesh;
    const auto kind = face_kind_property(mesh);
    std::vector<std::vector<glm::dvec3>> roof;
    for (const Mesh::FaceHandle f : mesh.faces()) {
      const auto i = static_cast<std::size_t>(f.idx());
      const std::string tag = i < part.face_tags.size() ? face_tag(part, i) : std::string();
      seen.insert(tag);
      if (!roof_tags.count(tag) && !(kind.is_valid() && mesh.property(kind, f) == FaceKind::Cap)) continue;
      roof.emplace_back();
      for (const auto v : mesh.fv_range(f)) roof.back().push_back({mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2]});
    }
    if (roof.empty()) continue;
    TaggedMesh slab;
    try {
      slab.mesh = std::make_shared<Mesh>(build_mesh(roof_overhang(roof, o)));
      // Checked as Extrude checks its buildings, so a slab that is not a
      // closed solid (its corners cut from planes that barely differ) is
      // refused by name rather than handed on.
      const ValidationReport check = validate(*slab.mesh);
      if (!check.ok()) throw std::runtime_error("the slab made is not a closed solid: " + check.problems.front());
    } catch (const std::exception& e) {  // InputError from the roof, MeshError from OpenMesh
      const std::string reason = (part.building.empty() ? "" : "building " + part.building + ": ") + e.what();
      if (!skip) return ctx.error(reason);
      if (skipped++ == 0) first_reason = reason;
      continue;
    }
    face_tags_from_mesh(slab);
    slab.building = part.building, slab.feature = part.feature;
    slab.properties = part.properties, slab.parameters = part.parameters;
    // Its roof, fascia and soffit look as a Material node before this one said.
    slab.materials = part.materials;
    out.parts.push_back(std::move(slab));
  }
  if (out.parts.size() == ctx.input<MeshSet>(h.mesh_in).parts.size() && !out.parts.empty() && skipped == 0) {
    std::string tags;
    for (const std::string& t : seen) tags += (tags.empty() ? "'" : ", '") + t + "'";
    return ctx.error("no face is tagged " + ctx.param<std::string>(h.roof_tags) + " (the faces' tags: " + tags + ")");
  }
  if (skipped > 0) ctx.warning(std::to_string(skipped) + " building(s) left without an overhang, the first: " + first_reason);
  ctx.set_output(h.mesh_out, std::move(out));
  ctx.set_output(h.skipped_out, skipped);
}

}  // namespace
PROCEX_REGISTER_NODE("Roof Overhang", 1, declare, evaluate);
}  // namespace procex

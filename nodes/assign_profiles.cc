// Assign Profiles: a profile per footprint edge, by rules over edge labels,
// with probabilities, deterministic per building (paper 3.7).
#include <algorithm>
#include <stdexcept>

#include "graph/hash.h"
#include "graph/registry.h"
#include "nodes/support/edge_labels.h"
#include "nodes/support/profile_rules.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t rules, selection, seed, draw, short_below, long_above, street, street_direction;
  std::size_t party_edges_in, street_edges_in;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("Gives each footprint edge a profile. `rules` are tried in order, the first whose labels all match an edge "
        "wins: `street = gable; back long = hip:0.7, mansard:0.3; #4 = 2; * = hip`. Labels: short / medium / long "
        "(edge length), street / side / back (outward normal against the street direction, or the `street_edges` input), outer / inner (hole), "
        "selected (`selection`), party (edges on the `party_edges` input: shared with a neighbouring footprint), #<edge id>, normal:<from>-<to> (compass degrees), * (any). Profiles are named by "
        "name or list position, with optional weights; a random pick depends only on `seed`, the building id and "
        "(with draw = per_edge) the edge, so a building looks the same in every run. Edges no rule matches keep "
        "their angle.")
      .category("Profile");
  d.input<Footprint>("footprint");
  d.input<std::vector<Profile>>("profiles");
  d.input<std::string>("building_id").optional().doc("seeds the random picks (the CLI's batch binds it per feature)");
  par.party_edges_in = d.input<std::vector<std::int64_t>>("party_edges").optional()
      .doc("edge ids shared with a neighbouring footprint: the label `party`, never the street side (a graph input "
           "party_edges is bound per feature by procex batch and eval --footprints)").index();
  par.street_edges_in = d.input<std::vector<std::int64_t>>("street_edges").optional()
      .doc("edge ids facing a street line: when any, the label `street` is theirs alone, and the other edges are side "
           "or back against them (a graph input street_edges is bound per feature by procex batch and eval "
           "--footprints from the file's LineStrings and --streets)").index();
  par.rules = d.param<std::string>("rules").default_value(std::string("* = 0")).doc("see above").index();
  par.selection = d.param<std::vector<std::int64_t>>("selection").default_value(std::vector<std::int64_t>{})
      .doc("edge ids the label `selected` matches").index();
  par.seed = d.param<std::int64_t>("seed").default_value<std::int64_t>(1).doc("random seed").index();
  par.draw = d.param_enum("draw", {"per_building", "per_edge"})
      .doc("per_building: one pick per rule and building (symmetric buildings); per_edge: one per edge").index();
  par.short_below = d.param<double>("short_below").default_value(4.0).range(0, 1000).unit("m").doc("edges shorter than this are short").index();
  par.long_above = d.param<double>("long_above").default_value(12.0).range(0, 1000).unit("m").doc("edges longer than this are long").index();
  par.street = d.param_enum("street", {"longest_edge", "direction"})
      .doc("where the street is: beyond the longest outer edge, or in `street_direction`").index();
  par.street_direction = d.param<double>("street_direction").default_value(-90.0).range(-360, 360).unit("deg")
      .doc("direction from the building to the street, counter-clockwise from +x (-90: south)").index();
  d.output<Footprint>("footprint");
}

// A uniform number in [0, 1) from the seed, the building, the rule and (per_edge) the edge.
double draw(std::int64_t seed, const std::string& building, std::size_t rule, std::int64_t edge) {
  Hasher h(static_cast<std::uint64_t>(seed));
  h.u64(building.size()).str(building).u64(rule).i64(edge);
  return static_cast<double>(h.result().lo >> 11) * 0x1.0p-53;
}

void evaluate(EvalContext& ctx) {
  Footprint fp = ctx.input<Footprint>(0);
  const auto& profiles = ctx.input<std::vector<Profile>>(1);
  const std::string building = ctx.has_input(2) ? ctx.input<std::string>(2) : std::string();
  std::vector<ProfileRule> rules;
  try {
    rules = parse_profile_rules(ctx.param<std::string>(par.rules), profiles);
  } catch (const std::invalid_argument& e) {
    return ctx.error(std::string("rules: ") + e.what());
  }
  const auto& selection = ctx.param<std::vector<std::int64_t>>(par.selection);
  const std::int64_t seed = ctx.param<std::int64_t>(par.seed);
  const bool per_edge = ctx.choice(par.draw) == "per_edge";
  LabelOptions label_options;
  label_options.short_below = ctx.param<double>(par.short_below);
  label_options.long_above = ctx.param<double>(par.long_above);
  if (ctx.choice(par.street) == "direction") label_options.street_deg = ctx.param<double>(par.street_direction);
  if (ctx.has_input(par.party_edges_in))
    for (const std::int64_t id : ctx.input<std::vector<std::int64_t>>(par.party_edges_in))
      label_options.party.push_back(static_cast<std::int32_t>(id));
  if (ctx.has_input(par.street_edges_in))
    for (const std::int64_t id : ctx.input<std::vector<std::int64_t>>(par.street_edges_in))
      label_options.street.push_back(static_cast<std::int32_t>(id));

  fp.profiles = profiles;
  std::size_t unmatched = 0;
  for (const EdgeLabels& e : label_edges(fp, label_options)) {
    const bool selected = std::find(selection.begin(), selection.end(), e.id) != selection.end();
    auto rule = std::find_if(rules.begin(), rules.end(), [&](const ProfileRule& r) {
      return std::all_of(r.labels.begin(), r.labels.end(), [&](const std::string& l) { return label_matches(l, e, selected); });
    });
    if (rule == rules.end()) {
      ++unmatched;
      continue;
    }
    const auto r = static_cast<std::size_t>(rule - rules.begin());
    const double u = draw(seed, building, r, per_edge ? e.id : -1);
    fp.loops[e.loop].edges[e.edge].profile = static_cast<int>(pick_profile(rule->choices, u));
  }
  if (unmatched > 0)
    ctx.warning(std::to_string(unmatched) + " edges match no rule and keep their angle (add a rule '* = ...')");
  ctx.set_output(0, std::move(fp));
}

}  // namespace
PROCEX_REGISTER_NODE("Assign Profiles", 1, declare, evaluate);
}  // namespace procex

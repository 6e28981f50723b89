// Anchor: a named point on footprint edges (paper 3.4, fig. 29) -- a plan
// anchor along each selected edge paired with a height -- that Extrude hands
// to the sweep, which resolves it on the building (core/geom/anchor.h).
#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

enum Param : std::size_t { kName, kMode, kPosition, kHeight, kProfile, kEdges };

void declare(NodeDecl& d) {
  d.doc("A named anchor for Extrude's `anchor_k` inputs: a point on every selected footprint edge (`position` "
        "along it) at a height. Extrude resolves it on each selected edge to a position and a frame (along the "
        "edge, up the face, out of it) where that edge's face still exists at the height, or to absent (a "
        "warning) where the roof has closed over it or where no edge uses `profile`; Mesh Placement places "
        "meshes there by `name`. One anchor thus puts a window on every facade, and it follows the footprint and "
        "the profiles when they change.")
      .category("Geometry");
  d.param<std::string>("name").default_value(std::string("window")).doc("what Mesh Placement calls it");
  d.param_enum("mode", {"fraction", "from_start", "from_end"})
      .doc("position as a fraction of the edge's length at the height, or metres from the edge's start or end");
  d.param<double>("position").default_value(0.5).range(0, 10000)
      .doc("the fraction (0 to 1) or the distance in metres, as `mode` says");
  d.param<double>("height").default_value(1.0).range(0, 10000).unit("m").doc("above the footprint");
  d.param<std::string>("profile").default_value(std::string())
      .doc("only edges using the profile of this name (empty: every edge, whatever its profile)");
  d.param<std::string>("edges").default_value(std::string())
      .doc("only these edge ids, comma-separated, e.g. `0, 2, 5` (empty: every edge)");
  d.output<AnchorSpec>("anchor");
}

std::string trimmed(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// "0, 2,5" -> {0, 2, 5}; throws std::invalid_argument naming the bad item.
std::vector<std::int32_t> parse_edges(const std::string& text) {
  std::vector<std::int32_t> ids;
  if (trimmed(text).empty()) return ids;
  std::size_t start = 0;
  for (int item = 1; start <= text.size(); ++item) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string token = trimmed(text.substr(start, comma - start));
    std::int32_t id = -1;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), id);
    if (token.empty() || ec != std::errc() || end != token.data() + token.size() || id < 0)
      throw std::invalid_argument("edges: item " + std::to_string(item) + " ('" + token +
                                  "') is not an edge id (a whole number from 0); write ids separated by commas, "
                                  "e.g. '0, 2, 5'");
    ids.push_back(id);
    start = comma + 1;
  }
  return ids;
}

void evaluate(EvalContext& ctx) {
  AnchorSpec s;
  s.anchor.name = ctx.param<std::string>(kName);
  if (s.anchor.name.empty()) return ctx.error("name: an anchor needs a name (Mesh Placement finds it by name)");
  constexpr PlanAnchor::Mode kModes[] = {PlanAnchor::Mode::Fraction, PlanAnchor::Mode::FromStart,
                                         PlanAnchor::Mode::FromEnd};
  s.anchor.plan.mode = kModes[ctx.choice_index(kMode)];
  s.anchor.plan.value = ctx.param<double>(kPosition);
  if (s.anchor.plan.mode == PlanAnchor::Mode::Fraction && s.anchor.plan.value > 1.0)
    return ctx.error("position: " + std::to_string(s.anchor.plan.value) +
                     " is not a fraction of the edge (0 to 1); choose mode from_start or from_end for metres");
  s.anchor.height = ctx.param<double>(kHeight);
  s.profile = ctx.param<std::string>(kProfile);
  try {
    s.anchor.edges = parse_edges(ctx.param<std::string>(kEdges));
  } catch (const std::invalid_argument& e) {
    return ctx.error(e.what());
  }
  ctx.set_output(0, std::move(s));
}

}  // namespace
PROCEX_REGISTER_NODE("Anchor", 1, declare, evaluate);
}  // namespace procex

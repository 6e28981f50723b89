// Profile Offset: one step (distance, height) shared by every edge's profile,
// with per-profile and per-edge overrides (paper 3.3, fig. 5). Two nodes in a
// chain make two offsets.
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "core/geom/error.h"
#include "core/geom/profile_offset.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t height, distance, tag, overrides;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("Steps every edge sideways at one height (outward positive: soffits; inward: ledges) and carries each "
        "profile on from the end of the step, so one handle sets where every roof starts. `overrides` gives "
        "profiles or edges their own step: `gable: drop; roof_b: distance=0.8 slope=60; #3 #4: distance=0` -- "
        "rules separated by ';', each a profile name or edge ids (#id) then ':' and settings: distance=<m>, "
        "slope=<degrees from the vertical> (the angle above the offset, replacing the profile's part above), "
        "drop (no step). A later rule wins. Edges without a profile follow their angle.")
      .category("Profile");
  d.input<Footprint>("footprint");
  par.height = d.param<double>("height").default_value(3.0).range(0, 100).unit("m").doc("where the step is, above the footprint").index();
  par.distance = d.param<double>("distance").default_value(0.5).range(-10, 10).unit("m").doc("the step, outward positive").index();
  par.tag = d.param<std::string>("tag").default_value(std::string()).doc("tag of the step's faces (empty: soffit / ledge)").index();
  par.overrides = d.param<std::string>("overrides").default_value(std::string()).doc("see above").index();
  d.output<Footprint>("footprint");
}

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

template <class T>
bool parse(std::string_view s, T& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// One rule, "selector: settings"; throws std::invalid_argument naming what is wrong.
OffsetOverride parse_rule(std::string_view rule) {
  const auto colon = rule.find(':');
  if (colon == std::string_view::npos) throw std::invalid_argument("has no ':' between the edges and the settings");
  OffsetOverride ov;
  const std::string_view selector = trim(rule.substr(0, colon));
  if (selector.empty()) throw std::invalid_argument("names no profile and no edge before ':'");
  if (selector[0] == '#') {
    std::size_t at = 0;
    while (at < selector.size()) {
      const auto end = std::min(selector.find_first_of(" \t,", at), selector.size());
      const std::string_view token = selector.substr(at, end - at);
      std::int32_t id = 0;
      if (!token.empty() && (token[0] != '#' || !parse(token.substr(1), id)))
        throw std::invalid_argument("'" + std::string(token) + "' is not an edge id (write #3)");
      if (!token.empty()) ov.edge_ids.push_back(id);
      at = end + 1;
    }
  } else {
    ov.profile = std::string(selector);
  }
  const std::string_view settings = rule.substr(colon + 1);
  std::size_t at = 0;
  while (at < settings.size()) {
    const auto end = std::min(settings.find_first_of(" \t,", at), settings.size());
    const std::string_view token = settings.substr(at, end - at);
    at = end + 1;
    if (token.empty()) continue;
    if (token == "drop") {
      ov.drop = true;
      continue;
    }
    const auto eq = token.find('=');
    const std::string_view key = token.substr(0, eq);
    double v = 0.0;
    if (eq == std::string_view::npos || (key != "distance" && key != "slope"))
      throw std::invalid_argument("unknown setting '" + std::string(token) + "' (use distance=<m>, slope=<deg> or drop)");
    if (!parse(token.substr(eq + 1), v) || !std::isfinite(v))
      throw std::invalid_argument(std::string(key) + " '" + std::string(token.substr(eq + 1)) + "' is not a number");
    (key == "distance" ? ov.distance : ov.slope_deg) = v;
  }
  return ov;
}

std::vector<OffsetOverride> parse_overrides(std::string_view text) {
  std::vector<OffsetOverride> out;
  std::size_t at = 0, number = 0;
  while (at <= text.size()) {
    const auto end = std::min(text.find_first_of(";\n", at), text.size());
    const std::string_view rule = trim(text.substr(at, end - at));
    at = end + 1;
    if (rule.empty()) continue;
    ++number;
    try {
      out.push_back(parse_rule(rule));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("overrides: rule " + std::to_string(number) + " ('" + std::string(rule) + "') " +
                                  e.what());
    }
  }
  return out;
}

void evaluate(EvalContext& ctx) {
  ProfileOffset offset;
  offset.height = ctx.param<double>(par.height);
  offset.distance = ctx.param<double>(par.distance);
  offset.tag = ctx.param<std::string>(par.tag);
  std::ostringstream name;
  name << "at " << offset.height << " m";
  offset.name = name.str();
  try {
    offset.overrides = parse_overrides(ctx.param<std::string>(par.overrides));
    ctx.set_output(0, apply_profile_offsets(ctx.input<Footprint>(0), {offset}));
  } catch (const std::invalid_argument& e) {
    ctx.error(e.what());
  } catch (const InputError& e) {
    ctx.error(e.what());
  }
}

}  // namespace
PROCEX_REGISTER_NODE("Profile Offset", 1, declare, evaluate);
}  // namespace procex

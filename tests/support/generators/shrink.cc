#include "tests/support/generators/shrink.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <glm/common.hpp>

#include "tests/support/generators/edge_profiles.h"

namespace procex::testing {
namespace {

// Loops longer than this are first tried with every other vertex dropped.
constexpr std::size_t kHalvedAbove = 64;

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    if (static_cast<unsigned char>(ch) >= 0x20) out += ch;
  }
  return out + "\"";
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::string token;
  for (char ch : text + ",") {
    if (std::isdigit(static_cast<unsigned char>(ch)) || ch == '-' || ch == '.' || ch == 'e' || ch == 'E' || ch == '+') {
      token += ch;
    } else if (!token.empty()) {
      out.push_back(std::stod(token));
      token.clear();
    }
  }
  return out;
}

}  // namespace

GeneratedCase shrink(GeneratedCase c, const std::function<bool(const GeneratedCase&)>& fails, std::size_t max_tries) {
  std::size_t tries = 0;
  const auto attempt = [&](const GeneratedCase& candidate) {
    if (tries >= max_tries) return false;
    ++tries;
    if (!fails(candidate)) return false;
    c = candidate;
    return true;
  };
  for (bool progress = true; progress && tries < max_tries;) {
    progress = false;
    for (std::size_t l = c.footprint.loops.size(); l-- > 0 && c.footprint.loops.size() > 1;) {
      GeneratedCase candidate = c;
      candidate.footprint.loops.erase(candidate.footprint.loops.begin() + static_cast<std::ptrdiff_t>(l));
      progress = attempt(candidate) || progress;
    }
    for (std::size_t l = 0; l < c.footprint.loops.size(); ++l) {
      // A loop of thousands of vertices (the size class) would take as many candidates
      // dropped one at a time, each a sweep and a CGAL skeleton of minutes: halve it first.
      if (c.footprint.loops[l].points.size() > kHalvedAbove) {
        GeneratedCase candidate = c;
        Loop& loop = candidate.footprint.loops[l];
        Loop half;
        for (std::size_t i = 0; i < loop.points.size(); i += 2) {
          half.points.push_back(loop.points[i]);
          half.edges.push_back(loop.edges[i]);
        }
        loop = std::move(half);
        if (attempt(candidate)) {
          progress = true;
          continue;
        }
      }
      for (std::size_t i = c.footprint.loops[l].points.size(); i-- > 0 && c.footprint.loops[l].points.size() > 3;) {
        // Dropping vertex i: the edge before it now runs on to vertex i + 1.
        GeneratedCase candidate = c;
        Loop& loop = candidate.footprint.loops[l];
        loop.points.erase(loop.points.begin() + static_cast<std::ptrdiff_t>(i));
        loop.edges.erase(loop.edges.begin() + static_cast<std::ptrdiff_t>(i));
        progress = attempt(candidate) || progress;
      }
    }
  }
  // Round to as few digits below the footprint's size as still fail.
  double extent = 0.0;
  for (const Loop& loop : c.footprint.loops)
    for (const glm::dvec2& p : loop.points)
      extent = std::max({extent, std::abs(p.x - c.footprint.loops[0].points[0].x), std::abs(p.y - c.footprint.loops[0].points[0].y)});
  for (int digits = 0; digits <= 6 && extent > 0.0; ++digits) {
    const double step = std::pow(10.0, std::floor(std::log10(extent)) - digits);
    GeneratedCase candidate = c;
    for (Loop& loop : candidate.footprint.loops)
      for (glm::dvec2& p : loop.points) p = glm::round(p / step) * step;
    if (attempt(candidate)) break;
  }
  GeneratedCase candidate = c;
  for (Loop& loop : candidate.footprint.loops)
    for (EdgeSpec& e : loop.edges) e.angle_deg = std::round(e.angle_deg);
  if (candidate.options.max_height) candidate.options.max_height = std::round(*candidate.options.max_height * 10.0) / 10.0;
  attempt(candidate);
  return c;
}

std::string fixture_geojson(const GeneratedCase& c, const std::string& problem) {
  std::ostringstream s;
  s.precision(17);
  s << "{\"type\": \"FeatureCollection\",\n \"features\": [\n  {\"type\": \"Feature\", \"id\": \"generated\",\n"
    << "   \"properties\": {\n    \"generator\": " << json_string(c.description) << ",\n    \"problem\": "
    << json_string(problem) << ",\n    \"angles\": [";
  std::string profiles;
  for (std::size_t l = 0; l < c.footprint.loops.size(); ++l) {
    s << (l ? ", " : "") << "[";
    const Loop& loop = c.footprint.loops[l];
    for (std::size_t i = 0; i < loop.edges.size(); ++i) {
      s << (i ? ", " : "") << loop.edges[i].angle_deg;
      const int p = loop.edges[i].profile;
      profiles += (profiles.empty() ? "" : " ") + (p >= 0 ? c.profile_presets.at(static_cast<std::size_t>(p)) : std::string("-"));
    }
    s << "]";
  }
  s << "]";
  if (c.options.max_height) s << ",\n    \"max_height\": " << *c.options.max_height;
  if (!c.profile_presets.empty()) s << ",\n    \"profiles\": " << json_string(profiles);
  if (c.preset_plan_edits) s << ",\n    \"plan_edits\": \"presets\"";
  s << "},\n   \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [";
  for (std::size_t l = 0; l < c.footprint.loops.size(); ++l) {
    s << (l ? ",\n     " : "\n     ") << "[";
    const auto& pts = c.footprint.loops[l].points;
    for (std::size_t i = 0; i <= pts.size(); ++i)
      s << (i ? ", " : "") << "[" << pts[i % pts.size()].x << ", " << pts[i % pts.size()].y << "]";
    s << "]";
  }
  s << "]}}\n ]}\n";
  return s.str();
}

GeneratedCase case_from_fixture(const GeoJsonFeature& feature) {
  GeneratedCase c;
  c.description = feature.property_text("generator").value_or(feature.id);
  c.footprint = to_footprint(feature, 45.0);
  const std::vector<double> angles = numbers(feature.property_text("angles").value_or(""));
  std::vector<EdgeSpec*> edges;
  for (Loop& loop : c.footprint.loops)
    for (EdgeSpec& e : loop.edges) edges.push_back(&e);
  if (angles.size() != edges.size())
    throw std::invalid_argument("fixture " + feature.id + ": \"angles\" has " + std::to_string(angles.size()) +
                                " numbers for " + std::to_string(edges.size()) + " edges");
  for (std::size_t i = 0; i < edges.size(); ++i) edges[i]->angle_deg = angles[i];
  c.options.max_height = feature.property_number("max_height");
  // The preset plan edits index the profiles hip, bay, dormer, recess from 0.
  if (feature.property_text("plan_edits") == std::optional<std::string>("presets")) {
    for (const std::string& name : plan_edit_profile_names()) {
      c.footprint.profiles.push_back(profile_preset(name));
      c.profile_presets.push_back(name);
    }
    c.options.plan_edits = preset_plan_edits();
    c.preset_plan_edits = true;
  }
  if (const auto profiles = feature.property_text("profiles")) {
    std::istringstream names(*profiles);
    std::string name;
    for (std::size_t i = 0; names >> name; ++i) {
      if (i >= edges.size()) throw std::invalid_argument("fixture " + feature.id + ": more \"profiles\" than edges");
      if (name == "-") continue;
      auto it = std::find(c.profile_presets.begin(), c.profile_presets.end(), name);
      if (it == c.profile_presets.end()) {
        c.footprint.profiles.push_back(profile_preset(name));
        it = c.profile_presets.insert(c.profile_presets.end(), name);
      }
      edges[i]->profile = static_cast<int>(it - c.profile_presets.begin());
    }
  }
  return c;
}

}  // namespace procex::testing

#include "tests/support/generators/generated_case.h"

#include <cmath>
#include <random>
#include <sstream>

#include "tests/support/generators/edge_profiles.h"
#include "tests/support/generators/grid_plans.h"
#include "tests/support/generators/size_plans.h"

namespace procex::testing {
namespace {

// Roof presets drawn per edge (the rest of profile_preset_names() serve the plan edits).
constexpr std::size_t kRoofPresets = 7;

std::string number(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// The plans classes (a) and (b) share: polyominoes and letters, a quarter of
// them with collinear vertices added.
NamedPlan grid_or_letter_plan(std::mt19937_64& rng, std::size_t max_vertices) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  NamedPlan plan = unit(rng) < 0.45 ? polyomino_plan(rng, max_vertices) : letter_plan(rng);
  return unit(rng) < 0.25 ? with_collinear_vertices(std::move(plan), rng) : plan;
}

GeneratedCase grid_case(std::uint64_t seed, std::mt19937_64& rng) {
  const NamedPlan plan = grid_or_letter_plan(rng, 400);
  const PlanTransform t = generated_transform(seed, rng);
  static constexpr double kAngles[] = {30.0, 45.0, 60.0};
  const double angle = kAngles[std::uniform_int_distribution<int>(0, 2)(rng)];
  GeneratedCase c;
  c.footprint = make_footprint(apply(t, plan.loops), angle);
  c.description = plan.name + ", " + t.name + ", every edge at " + number(angle) + " degrees";
  return c;
}

// A quarter of c's edges vertical, the rest at lo..hi degrees: appended to
// its description. Unless `neighbouring` (capped), no two vertical edges are
// neighbours and the last edge slopes, so that sloped ones close the roof
// over them.
void walls_among_slopes(GeneratedCase& c, double lo, double hi, bool neighbouring, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Loop& loop : c.footprint.loops)
    for (std::size_t i = 0; i < loop.edges.size(); ++i) {
      const bool after_vertical = i > 0 && loop.edges[i - 1].angle_deg == 0.0;
      const bool vertical = unit(rng) < 0.25 && (neighbouring || (!after_vertical && i + 1 < loop.edges.size()));
      loop.edges[i].angle_deg = vertical ? 0.0 : lo + (hi - lo) * unit(rng);
    }
  c.description += "per-edge angles in " + number(lo) + ".." + number(hi) + ", a quarter vertical";
}

// Class (b)'s angles, profiles, caps and plan edits on the footprint of c
// (mode by seed): appended to its description.
void with_angles(GeneratedCase& c, std::uint64_t seed, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto angle_in = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const std::size_t mode = (seed / 10) % 8;
  const bool capped = mode == 1 || mode == 3 || mode == 5 || (mode == 6 && unit(rng) < 0.5);
  const auto each_edge = [&](auto&& assign) {
    for (Loop& loop : c.footprint.loops)
      for (std::size_t i = 0; i < loop.edges.size(); ++i) assign(loop, i);
  };
  switch (mode) {
    case 0:
    case 1: {
      const double a = mode == 0 ? angle_in(5, 80) : angle_in(-60, 80);
      each_edge([&](Loop& loop, std::size_t i) { loop.edges[i].angle_deg = a; });
      c.description += "every edge at " + number(a) + " degrees";
      break;
    }
    case 2:
    case 3:
      each_edge([&](Loop& loop, std::size_t i) { loop.edges[i].angle_deg = mode == 2 ? angle_in(5, 80) : angle_in(-60, 80); });
      c.description += mode == 2 ? "per-edge angles in 5..80" : "per-edge angles in -60..80";
      break;
    case 4:
      walls_among_slopes(c, 5, 80, false, rng);
      break;
    case 5:
      walls_among_slopes(c, -60, 80, true, rng);
      break;
    case 6: {
      const bool one = unit(rng) < 0.5;
      const std::size_t first = std::uniform_int_distribution<std::size_t>(0, kRoofPresets - 1)(rng);
      const std::vector<std::string> names = profile_preset_names();
      for (std::size_t k = 0; k < kRoofPresets; ++k) {
        c.footprint.profiles.push_back(profile_preset(names[k]));
        c.profile_presets.push_back(names[k]);
      }
      each_edge([&](Loop& loop, std::size_t i) {
        loop.edges[i].profile =
            static_cast<int>(one ? first : std::uniform_int_distribution<std::size_t>(0, kRoofPresets - 1)(rng));
      });
      c.description += one ? "every edge with the " + names[first] + " profile" : "per-edge profiles";
      break;
    }
    default:
      for (const std::string& name : plan_edit_profile_names()) {
        c.footprint.profiles.push_back(profile_preset(name));
        c.profile_presets.push_back(name);
      }
      each_edge([&](Loop& loop, std::size_t i) { loop.edges[i].profile = 0; });
      c.options.plan_edits = preset_plan_edits();
      c.preset_plan_edits = true;
      c.description += "hip profile with a bay, a dormer and a recess on every edge";
  }
  if (capped) {
    c.options.max_height = angle_in(0.5, 12.0);
    c.description += ", max_height " + number(*c.options.max_height);
  }
}

GeneratedCase angles_case(std::uint64_t seed, std::mt19937_64& rng) {
  const NamedPlan plan = grid_or_letter_plan(rng, 120);
  const PlanTransform t = generated_transform(seed % 6, rng);  // no scaling or moving: heights stay in metres
  GeneratedCase c;
  c.footprint = make_footprint(apply(t, plan.loops), 45.0);
  c.description = plan.name + ", " + t.name + ", ";
  with_angles(c, seed, rng);
  return c;
}

GeneratedCase size_case(std::uint64_t seed, std::mt19937_64& rng) {
  const std::size_t n = std::uniform_int_distribution<std::size_t>(500, 5000)(rng) * 2;
  NamedPlan plan;
  switch (seed % 3) {
    case 0: plan = star(n, 50.0, std::uniform_real_distribution<double>(20.0, 49.0)(rng)); break;
    case 1: plan = regular_polygon(n, 50.0); break;
    default: plan = random_star_shaped(n, 50.0, rng);
  }
  GeneratedCase c;
  c.footprint = make_footprint(plan.loops, 45.0);
  c.description = plan.name + ", every edge at 45 degrees";
  return c;
}

// Stars of outer radius 100 m and an inner radius of 40 to 95 m whose
// vertices are moved radially by 1 um to 1 cm (drawn evenly in its
// logarithm), every edge at 45 degrees: the spikes collapse within
// micrometres of one height, corners form between nearly opposite edges, and
// the rest closes to a point within about the jitter: as far apart as the
// sweep's clustering scales tell events apart, or not.
GeneratedCase stars_case(std::mt19937_64& rng, std::size_t least, std::size_t most) {
  const std::size_t n = std::uniform_int_distribution<std::size_t>(least / 2, most / 2)(rng) * 2;
  const double inner = std::uniform_real_distribution<double>(40.0, 95.0)(rng);
  const double jitter = std::pow(10.0, std::uniform_real_distribution<double>(-6.0, -2.0)(rng));
  const NamedPlan plan = jittered_star(n, 100.0, inner, jitter, rng);
  GeneratedCase c;
  c.footprint = make_footprint(plan.loops, 45.0);
  c.description = plan.name + ", every edge at 45 degrees";
  return c;
}

// A random simple polygon of n vertices, n drawn evenly in its logarithm
// from `least` to `most`, in a square of 100 m.
NamedPlan random_polygon_plan(std::mt19937_64& rng, double least, double most) {
  const auto n = static_cast<std::size_t>(
      std::exp(std::uniform_real_distribution<double>(std::log(least), std::log(most))(rng)));
  return random_simple_polygon(n, 100.0, rng);
}

// Such a polygon with every edge at 45 degrees.
GeneratedCase random_polygons_case(std::mt19937_64& rng, double least, double most) {
  const NamedPlan plan = random_polygon_plan(rng, least, most);
  GeneratedCase c;
  c.footprint = make_footprint(plan.loops, 45.0);
  c.description = plan.name + ", every edge at 45 degrees";
  return c;
}

// The same polygons (8 to 1,000 vertices) under class (b)'s angles,
// profiles, caps and plan edits.
GeneratedCase random_polygons_angles_case(std::uint64_t seed, std::mt19937_64& rng) {
  const NamedPlan plan = random_polygon_plan(rng, 8, 1000);
  GeneratedCase c;
  c.footprint = make_footprint(plan.loops, 45.0);
  c.description = plan.name + ", ";
  with_angles(c, seed, rng);
  return c;
}

// Walls among slopes under a flat top, where a wall standing between two
// loops meets a roof leaning out across it: such polygons of 8 to 1,500
// vertices under class (b)'s fifth mode, on every case.
GeneratedCase random_polygons_walls_case(std::mt19937_64& rng) {
  const NamedPlan plan = random_polygon_plan(rng, 8, 1500);
  GeneratedCase c;
  c.footprint = make_footprint(plan.loops, 45.0);
  c.description = plan.name + ", ";
  walls_among_slopes(c, -60, 80, true, rng);
  c.options.max_height = 0.5 + 11.5 * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  c.description += ", max_height " + number(*c.options.max_height);
  return c;
}

}  // namespace

const char* class_name(CaseClass c) {
  switch (c) {
    case CaseClass::Grid: return "grid";
    case CaseClass::Angles: return "angles";
    case CaseClass::Size: return "size";
    case CaseClass::Stars: return "stars";
    case CaseClass::LargeStars: return "large_stars";
    case CaseClass::RandomPolygons: return "random_polygons";
    case CaseClass::LargeRandomPolygons: return "large_random_polygons";
    case CaseClass::RandomPolygonsAngles: return "random_polygons_angles";
    case CaseClass::RandomPolygonsWalls: return "random_polygons_walls";
  }
  return "?";
}

GeneratedCase generate_case(CaseClass c, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(c));
  GeneratedCase out;
  switch (c) {
    case CaseClass::Grid: out = grid_case(seed, rng); break;
    case CaseClass::Angles: out = angles_case(seed, rng); break;
    case CaseClass::Size: out = size_case(seed, rng); break;
    case CaseClass::Stars: out = stars_case(rng, 1000, 3000); break;
    case CaseClass::LargeStars: out = stars_case(rng, 3000, 12000); break;
    case CaseClass::RandomPolygons: out = random_polygons_case(rng, 20, 1000); break;
    case CaseClass::LargeRandomPolygons: out = random_polygons_case(rng, 1000, 10000); break;
    case CaseClass::RandomPolygonsAngles: out = random_polygons_angles_case(seed, rng); break;
    case CaseClass::RandomPolygonsWalls: out = random_polygons_walls_case(rng); break;
  }
  out.description = std::string("class ") + class_name(c) + " seed " + std::to_string(seed) + ": " + out.description;
  return out;
}

}  // namespace procex::testing

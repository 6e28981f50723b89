#include "core/geom/profile_offset.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "core/geom/error.h"
#include "core/geom/tolerances.h"

namespace procex {
namespace {

// What one offset does to one edge.
struct EdgeStep {
  double distance = 0.0;
  std::optional<double> slope_deg;
  bool drop = false;
  bool operator<(const EdgeStep& o) const {
    return std::tie(drop, distance, slope_deg) < std::tie(o.drop, o.distance, o.slope_deg);
  }
};

std::string tag_of(const Profile& p, std::size_t segment) { return p.tags.empty() ? std::string() : p.tags[segment]; }

// How far a plane leaning in by `inward` per unit of height must rise to have
// surely closed over a footprint of size `extent` (1 m if it never closes).
double closing_rise(double inward, double extent) { return inward > 0.0 ? extent / inward : 1.0; }

// The profile an edge without one follows: its constant angle, untagged like
// the faces the sweep makes for it, up to where its roof has surely closed.
Profile constant_profile(double angle_deg, double height, double extent) {
  height += closing_rise(std::tan(angle_deg * M_PI / 180.0), extent);
  Profile p = Profile::straight(angle_deg, height, std::string());
  p.name = "angle " + std::to_string(angle_deg);
  return p;
}

// The profile extended above `height` the way the sweep extends it: with its
// last rising segment's slope.
Profile reaching_above(Profile p, double height) {
  if (p.points.back().y > height) return p;
  std::size_t last = p.segments() - 1;
  while (last > 0 && p.points[last + 1].y == p.points[last].y) --last;
  const glm::dvec2 d = p.points[last + 1] - p.points[last];
  if (d.y <= 0.0) throw InputError("profile '" + p.name + "' never rises, so it has no height to step at");
  const double rise = height + 1.0 - p.points.back().y;
  p.points.push_back(p.points.back() + d * (rise / d.y));
  if (!p.tags.empty()) p.tags.push_back(p.tags[last]);
  return p;
}

// `extent`: the footprint's size, how far a roof at an override's slope must
// reach in to have surely closed.
Profile rewrite(const Profile& original, double height, const EdgeStep& step, const std::string& step_tag,
                double extent) {
  const Profile p = reaching_above(original, height);
  Profile out;
  out.name = original.name;
  const bool tagged = !p.tags.empty() || !step_tag.empty();
  auto add = [&](glm::dvec2 point, std::string tag) {
    out.points.push_back(point);
    if (tagged) out.tags.push_back(std::move(tag));
  };
  // Points below the height, then the point at it.
  std::size_t i = 1;
  while (p.points[i].y < height) ++i;
  out.points.push_back(p.points[0]);
  for (std::size_t k = 1; k < i; ++k) add(p.points[k], tag_of(p, k - 1));
  const glm::dvec2 a = p.points[i - 1], b = p.points[i];
  const glm::dvec2 at = b.y == height ? b : a + (b - a) * ((height - a.y) / (b.y - a.y));
  add(at, tag_of(p, i - 1));
  // The segment crossing the height goes on from `at`, the rest after it.
  const std::size_t rest = b.y == height ? i + 1 : i;

  const glm::dvec2 shift{step.distance, 0.0};
  if (step.distance != 0.0) add(at + shift, step_tag);
  if (step.slope_deg) {
    // Up to the profile's top (where Extrude caps the building), or until a
    // roof leaning in at this slope has surely closed.
    const double inward = std::tan(*step.slope_deg * M_PI / 180.0);
    const double rise = std::max(original.points.back().y - height, closing_rise(inward, extent));
    add(at + shift + glm::dvec2{-inward * rise, rise}, tag_of(p, rest - 1));
    return out;
  }
  for (std::size_t k = rest; k < p.points.size(); ++k) add(p.points[k] + shift, tag_of(p, k - 1));
  return out;
}

void check_offset(const ProfileOffset& o) {
  const std::string where = "profile offset '" + o.name + "'";
  if (!std::isfinite(o.height)) throw InputError(where + ": height is not a finite number");
  if (!std::isfinite(o.distance)) throw InputError(where + ": distance is not a finite number");
  if (o.height <= 0.0)
    throw InputError(where + ": height " + std::to_string(o.height) +
                     " must be above 0 (a step at the footprint is a wider footprint)");
}

// Each edge's step under offset `o`, by loop and edge; refuses what selects or changes nothing.
std::vector<std::vector<EdgeStep>> edge_steps(const Footprint& fp, const ProfileOffset& o) {
  std::vector<std::vector<EdgeStep>> steps;
  for (const Loop& loop : fp.loops) steps.emplace_back(loop.edges.size(), EdgeStep{o.distance, {}, false});
  for (std::size_t n = 0; n < o.overrides.size(); ++n) {
    const OffsetOverride& ov = o.overrides[n];
    const std::string where = "profile offset '" + o.name + "', override " + std::to_string(n + 1);
    if (ov.profile.empty() && ov.edge_ids.empty()) throw InputError(where + " names no profile and no edge");
    if (!ov.distance && !ov.slope_deg && !ov.drop) throw InputError(where + " changes nothing (give a distance, a slope or drop)");
    if (ov.distance && !std::isfinite(*ov.distance)) throw InputError(where + ": distance is not a finite number");
    if (ov.slope_deg && !(std::abs(*ov.slope_deg) < 90.0))
      throw InputError(where + ": slope must be an angle from the vertical in (-90, 90) degrees");
    if (!ov.profile.empty() && std::none_of(fp.profiles.begin(), fp.profiles.end(),
                                            [&](const Profile& p) { return p.name == ov.profile; }))
      throw InputError(where + ": the footprint has no profile named '" + ov.profile + "'");
    std::vector<char> found(ov.edge_ids.size(), 0);
    std::size_t selected = 0;
    for (std::size_t li = 0; li < fp.loops.size(); ++li)
      for (std::size_t k = 0; k < fp.loops[li].edges.size(); ++k) {
        const EdgeSpec& e = fp.loops[li].edges[k];
        const auto id = std::find(ov.edge_ids.begin(), ov.edge_ids.end(), e.id);
        const bool by_profile = !ov.profile.empty() && e.profile >= 0 &&
                                fp.profiles[static_cast<std::size_t>(e.profile)].name == ov.profile;
        if (id != ov.edge_ids.end()) found[static_cast<std::size_t>(id - ov.edge_ids.begin())] = 1;
        if (id == ov.edge_ids.end() && !by_profile) continue;
        ++selected;
        EdgeStep& s = steps[li][k];
        if (ov.distance) s.distance = *ov.distance;
        if (ov.slope_deg) s.slope_deg = ov.slope_deg;
        s.drop = s.drop || ov.drop;
      }
    for (std::size_t m = 0; m < found.size(); ++m)
      if (!found[m]) throw InputError(where + ": the footprint has no edge with id " + std::to_string(ov.edge_ids[m]));
    if (selected == 0) throw InputError(where + ": no edge follows profile '" + ov.profile + "'");
  }
  return steps;
}

Footprint apply_one(const Footprint& fp, const ProfileOffset& o) {
  const auto steps = edge_steps(fp, o);
  Footprint out = fp;
  out.profiles.clear();
  // Rewritten profiles by (original, step); the original is a profile index, or the
  // angle (as -1 - index into `angles`) of an edge without one.
  std::map<std::pair<int, EdgeStep>, int> made;
  std::map<Profile const*, int> kept;
  std::vector<double> angles;
  auto keep = [&](const Profile& p) {
    auto [it, fresh] = kept.try_emplace(&p, static_cast<int>(out.profiles.size()));
    if (fresh) out.profiles.push_back(p);
    return it->second;
  };
  for (std::size_t li = 0; li < fp.loops.size(); ++li)
    for (std::size_t k = 0; k < fp.loops[li].edges.size(); ++k) {
      EdgeSpec& e = out.loops[li].edges[k];
      const EdgeStep& s = steps[li][k];
      if (s.drop) {
        if (e.profile >= 0) e.profile = keep(fp.profiles[static_cast<std::size_t>(e.profile)]);
        continue;
      }
      int original = e.profile;
      if (original < 0) {
        auto a = std::find(angles.begin(), angles.end(), e.angle_deg);
        original = -1 - static_cast<int>(a - angles.begin());
        if (a == angles.end()) angles.push_back(e.angle_deg);
      }
      auto [it, fresh] = made.try_emplace({original, s}, static_cast<int>(out.profiles.size()));
      if (fresh) {
        const Profile base = e.profile >= 0 ? fp.profiles[static_cast<std::size_t>(e.profile)]
                                            : constant_profile(e.angle_deg, o.height, length_scale(fp));
        check_profile(base);
        const std::string tag = !o.tag.empty() ? o.tag : s.distance > 0.0 ? "soffit" : "ledge";
        out.profiles.push_back(rewrite(base, o.height, s, tag, length_scale(fp)));
        check_profile(out.profiles.back());
      }
      e.profile = it->second;
    }
  return out;
}

}  // namespace

Footprint apply_profile_offsets(const Footprint& footprint, const std::vector<ProfileOffset>& offsets) {
  std::vector<const ProfileOffset*> order;
  for (const ProfileOffset& o : offsets) {
    check_offset(o);
    order.push_back(&o);
  }
  std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->height < b->height; });
  Footprint fp = footprint;
  for (const ProfileOffset* o : order) fp = apply_one(fp, *o);
  return fp;
}

}  // namespace procex

#include "app/studio/editor/offset_edit.h"

#include <algorithm>

namespace procex::studio {

double profile_offset_at(const std::vector<Vec2>& profile, double height) {
  if (profile.empty()) return 0.0;
  if (height <= profile.front().y) return profile.front().x;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const Vec2 a = profile[i], b = profile[i + 1];
    if (height < std::min(a.y, b.y) || height > std::max(a.y, b.y)) continue;
    if (a.y == b.y) return a.x;
    return a.x + (b.x - a.x) * (height - a.y) / (b.y - a.y);
  }
  return profile.back().x;
}

Vec2 offset_handle(const std::vector<Vec2>& profile, double distance, double height) {
  return {profile_offset_at(profile, height) + distance, height};
}

OffsetParams offset_params(const std::vector<Vec2>& profile, Vec2 to, const Node& profile_offset) {
  const auto clamp_to = [&](std::string_view name, double v) {
    const auto i = profile_offset.decl().param_index(name);
    if (!i) return v;
    const ParamDecl& p = profile_offset.decl().params()[*i];
    if (p.min) v = std::max(v, *p.min);
    if (p.max) v = std::min(v, *p.max);
    return v;
  };
  OffsetParams out;
  out.height = clamp_to("height", to.y);
  out.distance = clamp_to("distance", to.x - profile_offset_at(profile, out.height));
  return out;
}

}  // namespace procex::studio

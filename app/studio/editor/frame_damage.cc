#include "app/studio/editor/frame_damage.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/common.hpp>

namespace procex::studio {

namespace {

Rect empty_rect() { return {glm::vec2(std::numeric_limits<float>::max()), glm::vec2(std::numeric_limits<float>::lowest())}; }
bool is_empty(const Rect& r) { return r.max.x <= r.min.x || r.max.y <= r.min.y; }
Rect join(const Rect& a, const Rect& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }
Rect meet(const Rect& a, const Rect& b) { return {glm::max(a.min, b.min), glm::min(a.max, b.max)}; }
float area(const Rect& r) { return is_empty(r) ? 0.0f : r.size().x * r.size().y; }

// The pixels triangle t of command c covers (its bounds within the clip rectangle).
Rect triangle_rect(const DrawList& l, const DrawCommand& c, std::size_t t) {
  Rect r = empty_rect();
  for (std::size_t k = 0; k < 3; ++k) {
    const DrawVertex& v = l.vertices[c.vertex_offset + l.indices[c.index_offset + t * 3 + k]];
    r = join(r, Rect{{v.x, v.y}, {v.x, v.y}});
  }
  return meet(r, c.clip);
}

Rect command_rect(const DrawList& l, const DrawCommand& c) {
  Rect r = empty_rect();
  for (std::size_t t = 0; t < c.index_count / 3; ++t) r = join(r, triangle_rect(l, c, t));
  return r;
}

Rect list_rect(const DrawList& l) {
  Rect r = empty_rect();
  for (const DrawCommand& c : l.commands) r = join(r, command_rect(l, c));
  return r;
}

bool same_shape(const DrawList& a, const DrawList& b) {
  return a.vertices.size() == b.vertices.size() && a.indices == b.indices && a.commands == b.commands;
}

}  // namespace

void add_damage(std::vector<Rect>& damage, const Rect& r, std::size_t max_rects) {
  if (is_empty(r)) return;
  // Within a rectangle already there: nothing new (a quad's second triangle).
  if (std::any_of(damage.begin(), damage.end(), [&](const Rect& d) { return d.contains(r.min) && d.contains(r.max); })) return;
  damage.push_back(r);
  while (damage.size() > std::max<std::size_t>(max_rects, 1)) {
    std::size_t bi = 0, bj = 1;
    float best = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < damage.size(); ++i)
      for (std::size_t j = i + 1; j < damage.size(); ++j)
        if (const float cost = area(join(damage[i], damage[j])) - area(damage[i]) - area(damage[j]); cost < best) best = cost, bi = i, bj = j;
    damage[bi] = join(damage[bi], damage[bj]);
    damage.erase(damage.begin() + static_cast<std::ptrdiff_t>(bj));
  }
}

std::vector<Rect> FrameDamage::update(std::vector<DrawList> lists, Rect screen, const std::vector<std::uintptr_t>& redrawn_textures) {
  std::vector<Rect> damage;
  if (first_ || !(screen == screen_)) {
    damage.push_back(screen);
  } else {
    std::vector<bool> matched(previous_.size(), false);
    for (const DrawList& now : lists) {
      // The same window's list last frame (the first unmatched one of that name).
      const DrawList* before = nullptr;
      for (std::size_t i = 0; i < previous_.size() && !before; ++i)
        if (!matched[i] && previous_[i].owner == now.owner) matched[i] = true, before = &previous_[i];
      if (!before || !same_shape(now, *before)) {
        add_damage(damage, list_rect(now), kMaxRects);
        if (before) add_damage(damage, list_rect(*before), kMaxRects);
        continue;
      }
      for (const DrawCommand& c : now.commands) {
        if (std::find(redrawn_textures.begin(), redrawn_textures.end(), c.texture) != redrawn_textures.end()) {
          add_damage(damage, command_rect(now, c), kMaxRects);
          continue;
        }
        for (std::size_t t = 0; t < c.index_count / 3; ++t) {
          bool changed = false;
          for (std::size_t k = 0; k < 3 && !changed; ++k) {
            const std::size_t v = c.vertex_offset + now.indices[c.index_offset + t * 3 + k];
            changed = !(now.vertices[v] == before->vertices[v]);
          }
          if (changed) add_damage(damage, join(triangle_rect(now, c, t), triangle_rect(*before, c, t)), kMaxRects);
        }
      }
    }
    for (std::size_t i = 0; i < previous_.size(); ++i)
      if (!matched[i]) add_damage(damage, list_rect(previous_[i]), kMaxRects);  // a window (a popup, a tooltip) went away
  }
  // Whole pixels (every pixel a triangle touches), within the screen.
  for (Rect& r : damage) r = meet(Rect{glm::floor(r.min), glm::ceil(r.max)}, screen);
  std::erase_if(damage, is_empty);
  previous_ = std::move(lists);
  screen_ = screen;
  first_ = false;
  return damage;
}

}  // namespace procex::studio

// frame_damage.h -- which parts of the window changed since the last frame.
//
// Software OpenGL (llvmpipe under Xvfb) spends a frame's time filling
// pixels: the whole 1280x800 window costs ~30 ms there, while the UI build is
// ~4 ms. The studio therefore redraws only the pixels that changed. This
// compares a frame's draw lists (a copy of ImGui's, kept here without ImGui)
// with the previous frame's, triangle by triangle, and returns the screen
// rectangles to redraw: triangles whose vertices moved or changed colour,
// lists whose shape changed, appeared or went, and images whose texture was
// redrawn (the 3D preview).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/studio/editor/canvas_layout.h"

namespace procex::studio {

// One vertex as ImGui draws it (the layout of ImDrawVert).
struct DrawVertex {
  float x, y, u, v;
  std::uint32_t col;
  bool operator==(const DrawVertex&) const = default;
};

struct DrawCommand {
  Rect clip;                   // screen pixels
  std::uintptr_t texture = 0;
  std::uint32_t index_offset = 0, index_count = 0, vertex_offset = 0;
  bool operator==(const DrawCommand&) const = default;
};

// One window's draw list.
struct DrawList {
  std::string owner;  // the window's name: how lists of two frames are matched
  std::vector<DrawVertex> vertices;
  std::vector<std::uint16_t> indices;
  std::vector<DrawCommand> commands;
};

// Adds r to `damage`, merging rectangles (the pair whose union adds the
// least area first) until at most `max_rects` remain.
void add_damage(std::vector<Rect>& damage, const Rect& r, std::size_t max_rects);

class FrameDamage {
 public:
  // The rectangles (screen pixels, whole pixels, at most kMaxRects) that
  // differ from the last frame given; the whole `screen` the first time, and
  // after reset(). `redrawn_textures` are textures whose content changed.
  std::vector<Rect> update(std::vector<DrawList> lists, Rect screen, const std::vector<std::uintptr_t>& redrawn_textures = {});
  // The next update damages everything (the window was resized or exposed).
  void reset() { previous_.clear(), first_ = true; }

  static constexpr std::size_t kMaxRects = 4;

 private:
  std::vector<DrawList> previous_;
  Rect screen_;
  bool first_ = true;
};

}  // namespace procex::studio

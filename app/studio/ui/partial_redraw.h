// partial_redraw.h -- draws ImGui's frame into a window-sized offscreen image
// that persists between frames, redrawing only the rectangles FrameDamage
// finds changed, then copies it to the window's back buffer: all of it, or
// only what the back buffer lacks when its age is known (GLX_EXT_buffer_age).
// A frame that changed nothing is neither drawn nor swapped. On software
// OpenGL this turns a full-window fill per frame into a copy plus the few
// pixels that changed (see BENCHMARKS.md, Studio).
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "app/studio/editor/frame_damage.h"

struct ImDrawData;

namespace procex::studio {

class OffscreenImage;

class PartialRedraw {
 public:
  PartialRedraw();
  ~PartialRedraw();
  PartialRedraw(const PartialRedraw&) = delete;
  PartialRedraw& operator=(const PartialRedraw&) = delete;

  struct Outcome {
    double pixels_redrawn = 0;
    bool presented = false;  // the back buffer holds the frame: swap (otherwise the window already shows it)
  };
  // `width` x `height`: the framebuffer in pixels; `back_buffer_age` as
  // back_buffer_age() says (0: unknown); `redrawn_textures`: textures whose
  // content changed; `present`: fill the back buffer even if nothing changed
  // (a screenshot reads it).
  Outcome render(ImDrawData* draw, int width, int height, int back_buffer_age, const std::vector<std::uintptr_t>& redrawn_textures,
                 bool present);
  // Everything is drawn again next time (the window was exposed).
  void invalidate() { damage_.reset(); }

 private:
  std::unique_ptr<OffscreenImage> image_;
  FrameDamage damage_;
  std::deque<std::vector<Rect>> history_;  // the damage of the last frames presented, newest first
  static constexpr std::size_t kHistory = 4;
};

}  // namespace procex::studio

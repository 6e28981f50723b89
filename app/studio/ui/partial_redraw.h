// partial_redraw.h -- draws ImGui's frame redrawing only the rectangles
// FrameDamage finds changed, into an image that keeps the rest of the window
// from the frames before. Where the window can be shown a rectangle at a time
// (ui/copy_sub_buffer.h) that image is the window's back buffer itself, never
// swapped, and the changed rectangles are all that is copied to the window.
// Elsewhere it is a window-sized offscreen image, copied to the back buffer
// for a swap: all of it, or only what the back buffer lacks when its age is
// known (GLX_EXT_buffer_age). A frame that changed nothing is neither drawn
// nor shown. On software OpenGL this turns a full-window fill per frame into
// the few pixels that changed (see BENCHMARKS.md, Studio).
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
  // `in_back_buffer`: the back buffer keeps its pixels between frames (nothing swaps it).
  explicit PartialRedraw(bool in_back_buffer);
  ~PartialRedraw();
  PartialRedraw(const PartialRedraw&) = delete;
  PartialRedraw& operator=(const PartialRedraw&) = delete;

  struct Outcome {
    double pixels_redrawn = 0;
    bool presented = false;  // the back buffer holds the frame: swap (otherwise the window already shows it)
    std::vector<Rect> copy_to_window;  // in_back_buffer: what to copy to the window (copy_sub_buffer), in place of a swap
  };
  // `width` x `height`: the framebuffer in pixels; `back_buffer_age` as
  // back_buffer_age() says (0: unknown; unused in_back_buffer);
  // `redrawn_textures`: textures whose content changed; `present`: fill the
  // back buffer even if nothing changed (a screenshot reads it; in_back_buffer
  // it always holds the frame).
  Outcome render(ImDrawData* draw, int width, int height, int back_buffer_age, const std::vector<std::uintptr_t>& redrawn_textures,
                 bool present);
  // Everything is drawn again next time (the window was exposed).
  void invalidate() { damage_.reset(); }

 private:
  std::unique_ptr<OffscreenImage> image_;  // null: in the back buffer
  int width_ = 0, height_ = 0;
  FrameDamage damage_;
  std::deque<std::vector<Rect>> history_;  // the damage of the last frames presented, newest first
  static constexpr std::size_t kHistory = 4;
};

}  // namespace procex::studio

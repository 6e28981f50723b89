// copy_sub_buffer.h -- showing a frame by copying only the rectangles that
// changed from the back buffer to the window (GLX_MESA_copy_sub_buffer),
// instead of swapping the whole window.
//
// Under Xvfb with Mesa's software rasteriser, the server offers no
// GLX_EXT_buffer_age, so after a swap the back buffer's content is unknown:
// the studio had to keep the window in an offscreen image and copy all of it
// to the back buffer for every frame that changed anything, then swap all of
// it to the X server (5 of the 6-7 ms of the rasteriser's CPU time of a
// frame that changed 3% of the window, BENCHMARKS.md). The copy leaves the
// back buffer as it was, and it is never swapped, so it keeps the whole
// window from frame to frame: a frame draws the rectangles that changed into
// it and copies those to the window, nothing else.
//
// The back buffer's age (GLX_EXT_buffer_age, ui/back_buffer_age.h) plays no
// part here, rightly: it counts swaps since the back buffer was last shown,
// and this back buffer is never swapped, so it holds exactly what the studio
// drew into it. A server that reports the age would say 0 (undefined) for
// it every frame (Mesa's DRI3 loader gives 0 to a buffer never swapped), and
// heeding that would redraw the whole window each time. What does take its
// pixels is handled apart: a resize gives a new back buffer (PartialRedraw
// sees the size change and redraws all), and an exposed window is drawn and
// copied again in full (PartialRedraw::invalidate).
#pragma once

#include <vector>

#include "app/studio/editor/canvas_layout.h"

namespace procex::studio {

// Whether the current OpenGL context's window can be shown this way.
bool copy_sub_buffer_available();

// Copies each of `rects` (window pixels, rows from the top) from the back
// buffer of the current context's window to the window itself (an implicit
// glFlush first). Only where copy_sub_buffer_available().
void copy_sub_buffer(const std::vector<Rect>& rects, int window_height);

}  // namespace procex::studio

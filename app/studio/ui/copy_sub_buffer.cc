// Kept apart: <GL/glx.h> brings <GL/gl.h>, which the rest of the studio
// replaces with <GL/glcorearb.h>.
#include "app/studio/ui/copy_sub_buffer.h"

#include <GL/glx.h>

#include <cstring>

namespace procex::studio {

namespace {

using CopySubBuffer = void (*)(Display*, GLXDrawable, int, int, int, int);

// The entry point, where the window's screen offers the extension (looked up once: the studio has one window).
CopySubBuffer entry_point() {
  static const CopySubBuffer copy = [] {
    Display* display = glXGetCurrentDisplay();
    if (!display) return CopySubBuffer{nullptr};
    const char* ext = glXQueryExtensionsString(display, DefaultScreen(display));
    if (!ext || !std::strstr(ext, "GLX_MESA_copy_sub_buffer")) return CopySubBuffer{nullptr};
    return reinterpret_cast<CopySubBuffer>(glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCopySubBufferMESA")));
  }();
  return copy;
}

}  // namespace

bool copy_sub_buffer_available() { return entry_point() != nullptr && glXGetCurrentDrawable() != 0; }

void copy_sub_buffer(const std::vector<Rect>& rects, int window_height) {
  const CopySubBuffer copy = entry_point();
  Display* display = glXGetCurrentDisplay();
  const GLXDrawable drawable = glXGetCurrentDrawable();
  for (const Rect& r : rects) {
    // GLX counts rows from the bottom.
    const int x0 = static_cast<int>(r.min.x), x1 = static_cast<int>(r.max.x);
    const int y0 = window_height - static_cast<int>(r.max.y), y1 = window_height - static_cast<int>(r.min.y);
    if (x1 > x0 && y1 > y0) copy(display, drawable, x0, y0, x1 - x0, y1 - y0);
  }
}

}  // namespace procex::studio

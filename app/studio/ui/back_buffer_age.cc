// Kept apart: <GL/glx.h> brings <GL/gl.h>, which the rest of the studio
// replaces with <GL/glcorearb.h>.
#include "app/studio/ui/back_buffer_age.h"

#include <GL/glx.h>
#include <GL/glxext.h>

#include <cstring>

namespace procex::studio {

namespace {

bool has_extension(Display* display, const char* name) {
  const char* ext = glXQueryExtensionsString(display, DefaultScreen(display));
  return ext && std::strstr(ext, name) != nullptr;
}

// Whether swapping copies the back buffer to the window and leaves it as it
// was (GLX_OML_swap_method's copy method, as Mesa's software rasteriser does).
bool swap_copies(Display* display) {
  if (!has_extension(display, "GLX_OML_swap_method")) return false;
  int id = 0;
  if (glXQueryContext(display, glXGetCurrentContext(), GLX_FBCONFIG_ID, &id) != Success) return false;
  const int want[] = {GLX_FBCONFIG_ID, id, None};
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(display, DefaultScreen(display), want, &count);
  int method = 0;
  const bool ok = configs && count > 0 && glXGetFBConfigAttrib(display, configs[0], GLX_SWAP_METHOD_OML, &method) == Success;
  if (configs) XFree(configs);
  return ok && method == GLX_SWAP_COPY_OML;
}

}  // namespace

int back_buffer_age() {
  Display* display = glXGetCurrentDisplay();
  const GLXDrawable drawable = glXGetCurrentDrawable();
  if (!display || !drawable) return 0;
  // Asking a server without the extension would raise an X error: look first, once.
  static const bool has_age = has_extension(display, "GLX_EXT_buffer_age");
  static const bool copies = !has_age && swap_copies(display);
  if (copies) return 1;
  if (!has_age) return 0;
  unsigned int age = 0;
  glXQueryDrawable(display, drawable, GLX_BACK_BUFFER_AGE_EXT, &age);
  return static_cast<int>(age);
}

}  // namespace procex::studio

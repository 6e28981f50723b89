// offscreen_image.h -- a colour image to draw into with OpenGL (a framebuffer
// object with a texture, optionally a depth buffer), kept between frames and
// remade only when its size changes. The 3D preview draws its scene into
// one; the window's partial redraw keeps the whole window in another.
#pragma once

#include <GL/glcorearb.h>

namespace procex::studio {

class OffscreenImage {
 public:
  explicit OffscreenImage(bool with_depth);
  ~OffscreenImage();
  OffscreenImage(const OffscreenImage&) = delete;
  OffscreenImage& operator=(const OffscreenImage&) = delete;

  // True when the image was (re)made at this size: its pixels are undefined.
  bool resize(int width, int height);
  GLuint framebuffer() const { return fbo_; }
  GLuint texture() const { return color_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  bool with_depth_;
  GLuint fbo_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace procex::studio

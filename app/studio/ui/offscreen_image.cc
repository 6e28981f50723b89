#include "app/studio/ui/offscreen_image.h"

namespace procex::studio {

OffscreenImage::OffscreenImage(bool with_depth) : with_depth_(with_depth) {
  glGenFramebuffers(1, &fbo_);
  glGenTextures(1, &color_);
  if (with_depth_) glGenRenderbuffers(1, &depth_);
}

OffscreenImage::~OffscreenImage() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &color_);
  if (with_depth_) glDeleteRenderbuffers(1, &depth_);
}

bool OffscreenImage::resize(int width, int height) {
  if (width == width_ && height == height_) return false;
  width_ = width;
  height_ = height;
  glBindTexture(GL_TEXTURE_2D, color_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
  if (with_depth_) {
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return true;
}

}  // namespace procex::studio

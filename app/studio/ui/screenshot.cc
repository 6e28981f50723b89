#include "app/studio/ui/screenshot.h"

#include <GL/glcorearb.h>
#include <stb_image_write.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace procex::studio {

namespace {

void write_png(int width, int height, const std::vector<unsigned char>& pixels, const std::filesystem::path& file) {
  const auto row = static_cast<std::size_t>(width) * 3;
  // GL's first row is the bottom one; stb_image_write can flip while writing.
  stbi_flip_vertically_on_write(1);
  // Written beside the target and renamed, so a reader never sees half an image.
  const std::filesystem::path tmp = file.string() + ".tmp";
  if (!stbi_write_png(tmp.c_str(), width, height, 3, pixels.data(), static_cast<int>(row)))
    throw std::runtime_error(file.string() + ": cannot write the screenshot");
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) throw std::runtime_error(file.string() + ": cannot write the screenshot: " + ec.message());
}

}  // namespace

void save_back_buffer_png(int width, int height, const std::filesystem::path& file) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * 3 * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  write_png(width, height, pixels, file);
}

void save_texture_png(unsigned texture, int width, int height, const std::filesystem::path& file) {
  if (width <= 0 || height <= 0) throw std::runtime_error(file.string() + ": the preview has not been drawn yet");
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * 3 * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  write_png(width, height, pixels, file);
}

}  // namespace procex::studio

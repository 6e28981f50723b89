#include "app/studio/ui/screenshot.h"

#include <GL/glcorearb.h>
#include <stb_image_write.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace procex::studio {

void save_back_buffer_png(int width, int height, const std::filesystem::path& file) {
  const auto row = static_cast<std::size_t>(width) * 3;
  std::vector<unsigned char> pixels(row * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
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

}  // namespace procex::studio

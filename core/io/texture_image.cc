#include "core/io/texture_image.h"

#include "base/read_file.h"
#include "core/io/io_error.h"

namespace procex {

std::string_view image_mime_type(std::string_view bytes) {
  if (bytes.starts_with(std::string_view("\x89PNG\r\n\x1a\n", 8))) return "image/png";
  if (bytes.starts_with("\xFF\xD8\xFF")) return "image/jpeg";
  return "";
}

std::string read_texture_image(const std::filesystem::path& path) {
  std::string bytes = read_file(path, kMaxTextureBytes);
  if (image_mime_type(bytes).empty())
    throw IoError("texture '" + path.string() + "' is not a PNG or JPEG image (the texture formats glTF carries): "
                  "convert it to .png",
                  path.string());
  return bytes;
}

}  // namespace procex

#include "core/io/texture_image.h"

#include "base/file_read_cache.h"
#include "base/file_version_memo.h"
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

std::shared_ptr<const std::string> shared_texture_image(const std::filesystem::path& path, FileVersionMemo* versions) {
  const FileVersion version = file_version(path, versions);
  if (version.content == 0) return std::make_shared<const std::string>(read_texture_image(path));  // it says why
  static FileReadCache<FileVersion, std::shared_ptr<const std::string>> cache;
  return cache.get(path.string(), version, [&] { return std::make_shared<const std::string>(read_texture_image(path)); });
}

}  // namespace procex

// Texture images a recipe's meshes name (MTL map_Kd): only PNG and JPEG, the
// two formats glTF 2.0 carries and every consumer decodes. The bytes are
// checked by their signature, never decoded here: the consumer decodes them.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "base/file_version_memo.h"

namespace procex {

// Largest texture read (a 8192 x 8192 RGBA PNG is at most about this).
inline constexpr std::size_t kMaxTextureBytes = std::size_t{256} << 20;

// "image/png" or "image/jpeg" by the bytes' signature, "" for anything else.
std::string_view image_mime_type(std::string_view bytes);

// The image's bytes. Throws IoError naming the file if it cannot be read, is
// larger than kMaxTextureBytes or is not a PNG or JPEG image.
std::string read_texture_image(const std::filesystem::path& path);
// The same, read once per version of the file (base/file_version.h) and
// shared: a batch's every building shows the same roof texture, and
// the glTF writer then finds it embedded already by its address. The version
// is `versions`' where a batch keeps them (EvalOptions::file_versions).
// Thread-safe.
std::shared_ptr<const std::string> shared_texture_image(const std::filesystem::path& path,
                                                        FileVersionMemo* versions = nullptr);

}  // namespace procex

// Every file a recipe names (group libraries, footprints, meshes to place,
// Export targets) is resolved here. Recipes are shared, so a name such as
// "../secret.obj", "/etc/passwd" or a symlink out of the folder must not let
// the recipe read a file into its output, echo it in an error or write over
// one: the resolved path, after symlinks, must lie inside the recipe's folder
// or inside a folder the user allowed explicitly (`--allow-path DIR`).
#pragma once

#include <filesystem>
#include <span>
#include <string_view>

#include "base/io_error.h"

namespace procex {

// `name` resolved against `root` (a relative name) or as given (an absolute
// one), symlinks followed as far as the path exists, and checked to lie
// inside root or one of `allowed`. Empty root: the working directory.
// Throws IoError naming `name`, the folder and --allow-path otherwise.
std::filesystem::path confined_path(const std::filesystem::path& root, std::string_view name,
                                    std::span<const std::filesystem::path> allowed = {});

}  // namespace procex

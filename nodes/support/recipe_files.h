// Files that nodes read (GeoJSON footprints) are named relative to the
// recipe's folder. The graph does not tell a node which recipe it belongs to,
// so the program that loads a recipe sets the folder here before evaluating.
#pragma once

#include <filesystem>

namespace procex {

// Set by the CLI (and the studio) after loading a recipe. Thread-safe.
void set_recipe_folder(const std::filesystem::path& folder);

// `file` itself if absolute, else joined to the recipe folder (the working
// directory when none was set).
std::filesystem::path resolve_recipe_path(const std::filesystem::path& file);

}  // namespace procex

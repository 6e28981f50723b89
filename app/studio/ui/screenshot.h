// screenshot.h -- saving the window's back buffer as a PNG.
#pragma once

#include <filesystem>

namespace procex::studio {

// Reads the current GL back buffer (width x height) and writes it as an RGB
// PNG, top row first. Call before swapping buffers. Throws std::runtime_error
// naming the file when it cannot be written.
void save_back_buffer_png(int width, int height, const std::filesystem::path& file);
// The same for a GL texture's level 0 (the preview's image: a recipe's thumbnail).
void save_texture_png(unsigned texture, int width, int height, const std::filesystem::path& file);

}  // namespace procex::studio

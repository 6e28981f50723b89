// Writing a whole file atomically: the bytes go to a temporary file beside the
// target, which is then renamed over it, so readers see the old file or the
// new one, never a half-written one. Shared by core/io (meshes) and graph
// (.pxg files), which must not depend on each other.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>

#include "base/atomic_file_set.h"
#include "base/io_error.h"

namespace procex {

// Throws IoError naming the path and the system's reason on failure; the
// temporary file is removed.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);
// The same for a file made of pieces, written in order without joining them
// first (a .glb's binary chunk straight from each building's arrays).
void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> pieces);
void write_file_atomically(const std::filesystem::path& path, std::span<const FilePiece> pieces);

}  // namespace procex

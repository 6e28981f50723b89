// A command's outputs must not overwrite its inputs or each other: `--report`
// given the footprints' path, or the same path as `-o`, would otherwise
// destroy the input or the mesh after all the work is done.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace procex {

// The first clash between outputs (an .obj's .mtl included) and inputs or
// other outputs, as a message naming both paths; nullopt if there is none.
// Paths are compared after resolving symlinks. Empty paths are skipped.
std::optional<std::string> output_clash(const std::vector<std::filesystem::path>& inputs,
                                        const std::vector<std::filesystem::path>& outputs);

}  // namespace procex

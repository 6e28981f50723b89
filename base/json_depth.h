// Nesting depth of JSON text, checked before a parser sees it: JSON parsers,
// and the code that dumps or walks what they build, recurse once per level,
// so 80,000 nested brackets overflow the stack. Every JSON file procex reads
// (recipes, footprints, shapes, batch reports) is refused beyond the limit.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace procex {

// Far deeper than any recipe, GeoJSON (a MultiPolygon's positions are 7
// levels down) or report needs, far shallower than a stack allows.
inline constexpr std::size_t kMaxJsonDepth = 64;

// The byte offset of the first '[' or '{' (outside strings) that opens a
// level deeper than max_depth; nullopt if there is none.
std::optional<std::size_t> json_too_deep_at(std::string_view text, std::size_t max_depth = kMaxJsonDepth);

}  // namespace procex

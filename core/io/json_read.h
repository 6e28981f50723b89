// Shared by the JSON readers in core/io: loading a file and turning
// nlohmann's parse errors into located IoErrors. Include only from .cc files.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

namespace procex::io_detail {

// The whole file as text; throws IoError if it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

// Parses text; throws IoError naming source, line and column on a syntax error.
nlohmann::json parse_json(std::string_view text, const std::string& source);

// A JSON pointer reference token with '~' and '/' escaped (RFC 6901).
std::string pointer_token(std::string_view key);

// Thrown inside readers for one bad value; the reader adds the file name or
// turns it into a per-item error.
struct ValueProblem {
  std::string pointer;
  std::string message;
};

// The value at pointer as a finite number (ValueProblem otherwise).
double number_at(const nlohmann::json& value, const std::string& pointer);

// The value at pointer as an array (ValueProblem otherwise).
const nlohmann::json& array_at(const nlohmann::json& value, const std::string& pointer);

// Element index of the array at parent_pointer as a finite number; the
// pointer string is only built on failure, since this runs per coordinate.
double number_in(const nlohmann::json& array, const std::string& parent_pointer, std::size_t index);

// Element index of the array at parent_pointer, a position [x, y, ...], as a point.
glm::dvec2 point_in(const nlohmann::json& array, const std::string& parent_pointer, std::size_t index);

}  // namespace procex::io_detail

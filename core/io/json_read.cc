#include "core/io/json_read.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/io/io_error.h"

namespace procex::io_detail {

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open '" + path.string() + "' for reading", path.string());
  std::string text;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size > 0) {
    text.resize(static_cast<std::size_t>(size));
    in.seekg(0, std::ios::beg);
    in.read(text.data(), size);
  }
  if (!in) throw IoError("cannot read '" + path.string() + "'", path.string());
  return text;
}

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Byte offset -> line and column, which is what an editor shows.
    const std::size_t at = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < at; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::ostringstream msg;
    msg << source << ":" << line << ":" << column << ": not valid JSON (" << e.what() << ")";
    throw IoError(msg.str(), source);
  }
}

std::string pointer_token(std::string_view key) {
  std::string out;
  out.reserve(key.size());
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

double number_at(const nlohmann::json& value, const std::string& pointer) {
  if (!value.is_number()) throw ValueProblem{pointer, "expected a number, found " + std::string(value.type_name())};
  const double v = value.get<double>();
  if (!std::isfinite(v)) throw ValueProblem{pointer, "number is not finite"};
  return v;
}

const nlohmann::json& array_at(const nlohmann::json& value, const std::string& pointer) {
  if (!value.is_array()) throw ValueProblem{pointer, "expected an array, found " + std::string(value.type_name())};
  return value;
}

double number_in(const nlohmann::json& array, const std::string& parent_pointer, std::size_t index) {
  const nlohmann::json& v = array[index];
  if (v.is_number()) {
    const double d = v.get<double>();
    if (std::isfinite(d)) return d;
  }
  return number_at(v, parent_pointer + "/" + std::to_string(index));
}

glm::dvec2 point_in(const nlohmann::json& array, const std::string& parent_pointer, std::size_t index) {
  const nlohmann::json& pos = array[index];
  if (!pos.is_array() || pos.size() < 2) {
    const std::string pointer = parent_pointer + "/" + std::to_string(index);
    array_at(pos, pointer);
    throw ValueProblem{pointer, "a position needs at least 2 numbers, found " + std::to_string(pos.size())};
  }
  if (pos[0].is_number() && pos[1].is_number()) {
    const glm::dvec2 p{pos[0].get<double>(), pos[1].get<double>()};
    if (std::isfinite(p.x) && std::isfinite(p.y)) return p;
  }
  const std::string pointer = parent_pointer + "/" + std::to_string(index);
  return {number_in(pos, pointer, 0), number_in(pos, pointer, 1)};
}

}  // namespace procex::io_detail

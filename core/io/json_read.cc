#include "core/io/json_read.h"

#include <algorithm>
#include <cmath>
#include <ios>
#include <memory>
#include <utility>

#include "base/json_depth.h"
#include "base/read_file.h"
#include "core/io/io_error.h"

namespace procex::io_detail {

namespace {

std::string line_column(std::string_view text, std::size_t byte) {
  const std::size_t at = std::min(byte, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// Where the parse stopped: nlohmann's exceptions for a number beyond double
// range (out_of_range.406) carry no position, but its SAX interface hands one,
// with the token, to parse_error. Only run once the parse has failed.
struct ErrorLocator : nlohmann::json_sax<nlohmann::json> {
  std::size_t byte = 0;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::json::exception&) override {
    byte = position >= last_token.size() ? position - last_token.size() : 0;  // the token's first byte
    return false;
  }
};

std::size_t failing_byte(std::string_view text) {
  ErrorLocator locator;
  nlohmann::json::sax_parse(text, &locator);
  return locator.byte;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path) { return read_file(path, kMaxDataFileBytes); }

template <class Json>
Json parse_json(std::string_view text, const std::string& source, typename Json::parser_callback_t callback) {
  if (const auto at = json_too_deep_at(text))
    throw IoError(source + ":" + line_column(text, *at) + ": nesting deeper than " + std::to_string(kMaxJsonDepth) +
                      " levels (no footprint or report needs that many)",
                  source);
  try {
    return Json::parse(text, std::move(callback));
  } catch (const nlohmann::json::parse_error& e) {
    throw IoError(source + ":" + line_column(text, e.byte > 0 ? e.byte - 1 : 0) + ": not valid JSON (" + e.what() + ")",
                  source);
  } catch (const nlohmann::json::out_of_range& e) {  // 406: a number beyond double range
    throw IoError(source + ":" + line_column(text, failing_byte(text)) + ": a number beyond double range (" +
                      std::string(e.what()) + "): numbers must lie within about 1.8e308; fix the value in the file",
                  source);
  }
}

template nlohmann::json parse_json<nlohmann::json>(std::string_view, const std::string&, nlohmann::json::parser_callback_t);
template nlohmann::ordered_json parse_json<nlohmann::ordered_json>(std::string_view, const std::string&,
                                                                   nlohmann::ordered_json::parser_callback_t);

namespace {
struct TooDeep {};
}  // namespace

template <class Json>
Json parse_json_file(const std::filesystem::path& path, typename Json::parser_callback_t callback) {
  const std::unique_ptr<std::istream> in = open_file_stream(path, kMaxDataFileBytes);
  try {
    // The depth checked as the parser goes (level 1 is the root's), as
    // json_too_deep_at checks text: nothing deeper is built or dropped.
    return Json::parse(*in, [&](int depth, typename Json::parse_event_t e, Json& parsed) {
      using event = typename Json::parse_event_t;
      if ((e == event::object_start || e == event::array_start) && static_cast<std::size_t>(depth) + 1 > kMaxJsonDepth)
        throw TooDeep{};
      return !callback || callback(depth, e, parsed);
    });
  } catch (const TooDeep&) {
  } catch (const nlohmann::json::exception&) {
  } catch (const std::ios_base::failure&) {
  }
  parse_json<Json>(read_text_file(path), path.string());  // throws, naming where and why
  throw IoError(path.string() + ": changed while it was read: read it again", path.string());
}

template nlohmann::json parse_json_file<nlohmann::json>(const std::filesystem::path&, nlohmann::json::parser_callback_t);
template nlohmann::ordered_json parse_json_file<nlohmann::ordered_json>(const std::filesystem::path&,
                                                                        nlohmann::ordered_json::parser_callback_t);

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

namespace procex {

nlohmann::ordered_json read_json_file(const std::filesystem::path& path) {
  return io_detail::parse_json<nlohmann::ordered_json>(io_detail::read_text_file(path), path.string());
}

}  // namespace procex

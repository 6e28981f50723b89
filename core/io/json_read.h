// Every JSON file procex reads (footprints, shapes, batch reports) goes
// through here: its size and nesting bounded (base/read_file.h,
// base/json_depth.h), nlohmann's errors (syntax, a number beyond double
// range) turned into IoErrors naming the file, line and column. The
// io_detail helpers are for the readers in core/io. Include only from .cc files.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

namespace procex {

// A JSON document with its members in file order (what merge needs to write
// reports back unchanged). Throws IoError as io_detail::parse_json.
nlohmann::ordered_json read_json_file(const std::filesystem::path& path);

}  // namespace procex

namespace procex::io_detail {

// The whole file as text, at most kMaxDataFileBytes; throws IoError if it
// cannot be read (see read_file).
std::string read_text_file(const std::filesystem::path& path);

// Parses text; throws IoError naming source, and line and column where there
// is one, on a syntax error, nesting deeper than kMaxJsonDepth or a number
// outside double range. `callback` as nlohmann's parse takes it: a value it
// returns false for is left out of the document (a reader that takes each
// element of a long array as it is parsed holds one at a time).
template <class Json = nlohmann::json>
Json parse_json(std::string_view text, const std::string& source, typename Json::parser_callback_t callback = nullptr);
extern template nlohmann::json parse_json<nlohmann::json>(std::string_view, const std::string&,
                                                          nlohmann::json::parser_callback_t);
extern template nlohmann::ordered_json parse_json<nlohmann::ordered_json>(std::string_view, const std::string&,
                                                                          nlohmann::ordered_json::parser_callback_t);

// The same for a whole file (at most kMaxDataFileBytes), read a chunk at a
// time rather than whole: with a callback that drops what it has taken, the
// memory is the document kept, not the file. On a failure the file is read
// whole after all, to name the line and column as parse_json does.
template <class Json = nlohmann::json>
Json parse_json_file(const std::filesystem::path& path, typename Json::parser_callback_t callback);
extern template nlohmann::json parse_json_file<nlohmann::json>(const std::filesystem::path&,
                                                               nlohmann::json::parser_callback_t);
extern template nlohmann::ordered_json parse_json_file<nlohmann::ordered_json>(const std::filesystem::path&,
                                                                               nlohmann::ordered_json::parser_callback_t);

// A callback for parse_json and parse_json_file that takes the elements of
// the array in the document's top-level member `member` one at a time: each
// goes to `take`, with its position, as the parser finishes it, and is left
// out of the document, where the member stays, empty. `restart` is called
// where the array begins, and again where the object repeats the member (the
// last one counts, as in a parsed document).
template <class Json>
typename Json::parser_callback_t elements_of(std::string member, std::function<void()> restart,
                                             std::function<void(const Json&, std::size_t)> take) {
  struct State {
    std::string key;
    bool in = false;
    std::size_t next = 0;
  };
  auto s = std::make_shared<State>();
  return [s, member = std::move(member), restart = std::move(restart), take = std::move(take)](
             int depth, typename Json::parse_event_t e, Json& parsed) {
    using event = typename Json::parse_event_t;
    if (depth == 1 && e == event::key) s->key = parsed.template get<std::string>();
    if (depth == 1 && (e == event::array_start || e == event::object_start)) {
      s->in = e == event::array_start && s->key == member;
      if (s->in) s->next = 0, restart();
    }
    if (depth == 1 && e == event::array_end) s->in = false;
    if (s->in && depth == 2 && (e == event::object_end || e == event::array_end || e == event::value)) {
      take(parsed, s->next++);
      return false;
    }
    return true;
  };
}

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

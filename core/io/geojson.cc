#include "core/io/geojson.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <utility>

#include "core/io/io_error.h"
#include "core/io/json_read.h"

namespace procex {

using nlohmann::json;
using io_detail::array_at;
using io_detail::ValueProblem;

namespace {

// A GeoJSON ring: positions, the last repeating the first (RFC 7946); the
// closing vertex is dropped, an unclosed ring is taken as implicitly closed.
std::vector<glm::dvec2> read_ring(const json& ring, const std::string& pointer) {
  array_at(ring, pointer);
  std::vector<glm::dvec2> points;
  points.reserve(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) points.push_back(io_detail::point_in(ring, pointer, i));
  if (points.size() >= 2 && points.front() == points.back()) points.pop_back();
  return points;
}

std::vector<glm::dvec2> read_line(const json& line, const std::string& pointer) {
  array_at(line, pointer);
  if (line.size() < 2) throw ValueProblem{pointer, "a LineString needs at least two positions"};
  std::vector<glm::dvec2> points;
  points.reserve(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) points.push_back(io_detail::point_in(line, pointer, i));
  return points;
}

void read_polygon(const json& rings, const std::string& pointer, std::size_t polygon, GeoJsonFeature& out) {
  array_at(rings, pointer);
  if (rings.empty()) throw ValueProblem{pointer, "a polygon needs at least one ring"};
  for (std::size_t r = 0; r < rings.size(); ++r) {
    out.loops.push_back(read_ring(rings[r], pointer + "/" + std::to_string(r)));
    out.polygon_of_loop.push_back(polygon);
  }
}

void read_geometry(const json& geometry, const std::string& pointer, GeoJsonFeature& out) {
  if (geometry.is_null()) throw ValueProblem{pointer, "the feature has no geometry"};
  if (!geometry.is_object()) throw ValueProblem{pointer, "geometry must be an object"};
  const auto type = geometry.find("type");
  if (type == geometry.end() || !type->is_string()) throw ValueProblem{pointer + "/type", "geometry has no type"};
  const auto coords = geometry.find("coordinates");
  const std::string cpointer = pointer + "/coordinates";
  if (coords == geometry.end()) throw ValueProblem{cpointer, "geometry has no coordinates"};
  const std::string& t = type->get_ref<const std::string&>();
  if (t == "Polygon") {
    read_polygon(*coords, cpointer, 0, out);
  } else if (t == "MultiPolygon") {
    array_at(*coords, cpointer);
    if (coords->empty()) throw ValueProblem{cpointer, "a MultiPolygon needs at least one polygon"};
    for (std::size_t p = 0; p < coords->size(); ++p) read_polygon((*coords)[p], cpointer + "/" + std::to_string(p), p, out);
  } else if (t == "LineString") {
    out.lines.push_back(read_line(*coords, cpointer));
  } else if (t == "MultiLineString") {
    array_at(*coords, cpointer);
    for (std::size_t l = 0; l < coords->size(); ++l) out.lines.push_back(read_line((*coords)[l], cpointer + "/" + std::to_string(l)));
  } else {
    throw ValueProblem{pointer + "/type",
                       "geometry type '" + t + "' is not a Polygon or MultiPolygon (a footprint) or a LineString (a street)"};
  }
}

void read_angles(const json& value, const std::string& pointer, GeoJsonFeature& out) {
  array_at(value, pointer);
  if (value.size() != out.loops.size())
    throw ValueProblem{pointer, "expected one angle list per ring (" + std::to_string(out.loops.size()) + "), found " +
                                    std::to_string(value.size())};
  out.edge_angles.resize(out.loops.size());
  for (std::size_t r = 0; r < value.size(); ++r) {
    const std::string rpointer = pointer + "/" + std::to_string(r);
    const json& list = array_at(value[r], rpointer);
    if (list.size() != out.loops[r].size())
      throw ValueProblem{rpointer, "ring " + std::to_string(r) + " has " + std::to_string(out.loops[r].size()) +
                                       " edges but " + std::to_string(list.size()) + " angles"};
    out.edge_angles[r].reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) out.edge_angles[r].push_back(io_detail::number_in(list, rpointer, k));
  }
}

// A value as compact JSON text, as dump() gives it, without the serializer's
// cost for the common cases (a property map is built for every feature).
std::string json_text(const json& value) {
  switch (value.type()) {
    case json::value_t::string: {
      const std::string& s = value.get_ref<const std::string&>();
      const bool plain = std::none_of(s.begin(), s.end(), [](char ch) {
        return ch == '"' || ch == '\\' || static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7f;
      });
      if (!plain) return value.dump();
      std::string out;
      out.reserve(s.size() + 2);
      out += '"';
      out += s;
      out += '"';
      return out;
    }
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::null:
      return "null";
    case json::value_t::number_integer:
      return std::to_string(value.get<std::int64_t>());
    case json::value_t::number_unsigned:
      return std::to_string(value.get<std::uint64_t>());
    default:
      return value.dump();
  }
}

std::string feature_id(const json& feature, std::size_t index) {
  auto text_of = [](const json& v) -> std::string {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number()) return v.dump();
    return {};
  };
  if (const auto id = feature.find("id"); id != feature.end()) {
    if (std::string s = text_of(*id); !s.empty()) return s;
  }
  if (const auto props = feature.find("properties"); props != feature.end() && props->is_object()) {
    if (const auto id = props->find("id"); id != props->end()) {
      if (std::string s = text_of(*id); !s.empty()) return s;
    }
  }
  return std::to_string(index);
}

void read_feature(const json& feature, const std::string& pointer, const GeoJsonReadOptions& options,
                  GeoJsonFeature& out) {
  if (!feature.is_object()) throw ValueProblem{pointer, "a feature must be an object"};
  const auto type = feature.find("type");
  if (type == feature.end() || *type != "Feature") throw ValueProblem{pointer + "/type", "type must be \"Feature\""};
  const auto props = feature.find("properties");
  if (props != feature.end() && !props->is_null()) {
    if (!props->is_object()) throw ValueProblem{pointer + "/properties", "properties must be an object or null"};
    for (const auto& [key, value] : props->items()) out.properties.emplace_hint(out.properties.end(), key, json_text(value));
  }
  const auto geometry = feature.find("geometry");
  if (geometry == feature.end()) throw ValueProblem{pointer + "/geometry", "the feature has no geometry"};
  read_geometry(*geometry, pointer + "/geometry", out);
  if (options.angles_property.empty()) return;
  const std::string apointer = pointer + "/properties/" + io_detail::pointer_token(options.angles_property);
  const json* angles = nullptr;
  if (props != feature.end() && props->is_object()) {
    if (const auto it = props->find(options.angles_property); it != props->end()) angles = &*it;
  }
  if (angles) {
    read_angles(*angles, apointer, out);
  } else if (options.require_angles) {
    throw ValueProblem{apointer, "the feature has no '" + options.angles_property + "' property"};
  }
}

}  // namespace

std::optional<std::string> GeoJsonFeature::property_text(const std::string& name) const {
  const auto it = properties.find(name);
  if (it == properties.end()) return std::nullopt;
  if (it->second.empty() || it->second.front() != '"') return it->second;
  return json::parse(it->second).get<std::string>();
}

std::optional<double> GeoJsonFeature::property_number(const std::string& name) const {
  const std::optional<std::string> text = property_text(name);
  if (!text || text->empty()) return std::nullopt;
  std::string_view rest = *text;
  auto skip_spaces = [&rest] {
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  };
  skip_spaces();
  double v = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), v);
  if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
  rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
  skip_spaces();
  constexpr double kFoot = 0.3048;
  if (rest.empty() || rest == "m") return v;
  if (rest == "ft" || rest == "'") return v * kFoot;
  return std::nullopt;
}

void FeatureList::keep_if(const std::function<bool(GeoJsonFeature&)>& keep) {
  std::vector<GeoJsonFeature> kept;
  for (GeoJsonFeature& f : features_)
    if (keep(f)) kept.push_back(std::move(f));
  features_ = std::move(kept);
}

void add_feature(GeoJsonFeature f, GeoJsonCollection& c, FeatureStore& footprints) {
  if (f.lines.empty()) return footprints.add(std::move(f));
  for (auto& line : f.lines) c.lines.push_back(std::move(line));
}

namespace {

// Reads a FeatureCollection from what `parse` parses (a text or a file, with
// the callback given to it). Each element of the top-level "features" array
// is read into the collection as the parser finishes it and then dropped from
// the document, so the document held at once is the collection's members and
// one feature, however many features the file has (a parsed feature takes
// several times its text). Depth 1 is the root's members, 2 the elements of
// its arrays.
GeoJsonCollection read_collection(const std::function<json(json::parser_callback_t)>& parse,
                                  const GeoJsonReadOptions& options, const std::string& source,
                                  FeatureStore* footprints) {
  GeoJsonCollection out;
  FeatureList own(out.features);
  FeatureStore& store = footprints ? *footprints : own;
  auto read_element = [&](const json& feature, std::size_t i) {
    const std::string pointer = "/features/" + std::to_string(i);
    GeoJsonFeature f;
    f.index = i;
    f.id = feature.is_object() ? feature_id(feature, i) : std::to_string(i);
    try {
      read_feature(feature, pointer, options, f);
      add_feature(std::move(f), out, store);
    } catch (const ValueProblem& problem) {
      out.errors.push_back({i, f.id, problem.pointer,
                            source + ": feature " + f.id + " at " + problem.pointer + ": " + problem.message});
    }
  };
  const json doc = parse(io_detail::elements_of<json>(
      "features", [&] { store.clear(), out.errors.clear(), out.lines.clear(); }, read_element));
  if (!doc.is_object()) throw IoError(source + ": the document is not a JSON object", source, "");
  const auto type = doc.find("type");
  if (type == doc.end() || *type != "FeatureCollection")
    throw IoError(source + ": /type must be \"FeatureCollection\"", source, "/type");
  const auto features = doc.find("features");
  if (features == doc.end() || !features->is_array())
    throw IoError(source + ": /features must be an array", source, "/features");
  for (const auto& [name, value] : doc.items()) {
    if (name != "type" && name != "features") out.members.emplace(name, value.dump());
  }
  return out;
}

}  // namespace

GeoJsonCollection parse_geojson(std::string_view text, const GeoJsonReadOptions& options, const std::string& source) {
  return read_collection([&](json::parser_callback_t take) { return io_detail::parse_json(text, source, std::move(take)); },
                         options, source, nullptr);
}

namespace {

// Read a chunk at a time: a million footprints' text is not held whole either.
GeoJsonCollection read_file(const std::filesystem::path& path, const GeoJsonReadOptions& options,
                            FeatureStore* footprints) {
  return read_collection([&](json::parser_callback_t take) { return io_detail::parse_json_file(path, std::move(take)); },
                         options, path.string(), footprints);
}

}  // namespace

GeoJsonCollection read_geojson_file(const std::filesystem::path& path, const GeoJsonReadOptions& options) {
  return read_file(path, options, nullptr);
}

GeoJsonCollection read_geojson_file(const std::filesystem::path& path, const GeoJsonReadOptions& options,
                                    FeatureStore& footprints) {
  return read_file(path, options, &footprints);
}

Footprint to_footprint(const GeoJsonFeature& feature, double default_angle_deg) {
  Footprint fp = make_footprint(feature.loops, default_angle_deg);
  if (!feature.edge_angles.empty()) {
    for (std::size_t r = 0; r < fp.loops.size(); ++r)
      for (std::size_t k = 0; k < fp.loops[r].edges.size(); ++k) fp.loops[r].edges[k].angle_deg = feature.edge_angles[r][k];
  }
  return fp;
}

}  // namespace procex

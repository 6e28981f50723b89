// Reading building footprints from a GeoJSON FeatureCollection (RFC 7946) of
// Polygon and MultiPolygon features. One bad feature never stops the others:
// it is reported with its index, id and the JSON pointer of the bad value.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/footprint.h"

namespace procex {

struct GeoJsonReadOptions {
  // Name of a feature property holding per-edge angles in degrees: one list
  // per ring in GeoJSON ring order, one number per edge, edge k running from
  // vertex k to vertex k + 1. Empty: no angles are read.
  std::string angles_property;
  // A feature without the angles property is an error (true) or simply has
  // no edge_angles (false) so the caller can fall back to one angle.
  bool require_angles = true;
};

struct GeoJsonFeature {
  std::size_t index = 0;  // position in the "features" array
  // The feature's "id" member (a string, or a number written as text); else
  // properties.id; else the index as text.
  std::string id;
  // Every ring of every polygon, in GeoJSON order, the repeated closing vertex
  // dropped. Orientation is kept as given (RFC 7946: outer CCW, holes CW).
  std::vector<std::vector<glm::dvec2>> loops;
  // polygon_of_loop[i] = which polygon of a MultiPolygon loop i belongs to (0 for a Polygon).
  std::vector<std::size_t> polygon_of_loop;
  // Every member of "properties", its value as compact JSON text
  // (strings keep their quotes: "\"yes\"", numbers as written: "12.5").
  std::map<std::string, std::string> properties;
  // Per-edge angles (degrees) when GeoJsonReadOptions::angles_property is set
  // and present: edge_angles[i].size() == loops[i].size().
  std::vector<std::vector<double>> edge_angles;
  // A LineString's or MultiLineString's lines instead of loops: a street, not a
  // footprint (the readers put it in GeoJsonCollection::lines).
  std::vector<std::vector<glm::dvec2>> lines;

  // A property's value as plain text: a JSON string unquoted and unescaped,
  // any other value as its JSON text; nullopt if absent.
  std::optional<std::string> property_text(const std::string& name) const;
  // A property's value as a number: a JSON number, or a string holding one
  // and nothing else but a unit of length: "12", "12 m", "40 ft", "40'"
  // (feet become metres). nullopt if absent or anything else ("3,5", "0x3",
  // "3 storeys"): a value is never taken from the front of a string.
  std::optional<double> property_number(const std::string& name) const;
};

struct GeoJsonFeatureError {
  std::size_t index = 0;  // position in the "features" array
  std::string id;         // as GeoJsonFeature::id, when it could be read
  std::string pointer;    // JSON pointer of the offending value, e.g. /features/3/geometry/coordinates/0/2
  std::string message;    // what is wrong, naming the pointer
};

struct GeoJsonCollection {
  std::vector<GeoJsonFeature> features;  // the features that were read, in file order
  std::vector<GeoJsonFeatureError> errors;  // the features that were not, in file order
  // The LineString and MultiLineString features' lines (streets: core/geom/street_edges.h).
  std::vector<std::vector<glm::dvec2>> lines;
  // Top-level members other than "type" and "features" (e.g. "name", "stats"),
  // each as compact JSON text.
  std::map<std::string, std::string> members;
  // The CRS the loops' coordinates are in (EPSG code, WKT or PROJ string), set
  // by read_footprints (core/io/footprint_read.h); empty when none is known.
  std::string crs;
};

// Where a reader puts the footprints it reads, in file order: a collection's
// `features` (FeatureList), or a batch's spool on disk (core/io/feature_spool.h),
// since a million footprints held as GeoJsonFeature take 600 MB.
class FeatureStore {
 public:
  virtual ~FeatureStore() = default;
  virtual void add(GeoJsonFeature f) = 0;
  // A repeated "features" member: the last counts, so what came before goes.
  virtual void clear() = 0;
  // Gives each feature, in order, to `keep`, which may change it (a
  // projection); drops those it returns false for.
  virtual void keep_if(const std::function<bool(GeoJsonFeature&)>& keep) = 0;
};

// The footprints in memory, in a vector (GeoJsonCollection::features).
class FeatureList final : public FeatureStore {
 public:
  explicit FeatureList(std::vector<GeoJsonFeature>& features) : features_(features) {}
  void add(GeoJsonFeature f) override { features_.push_back(std::move(f)); }
  void clear() override { features_.clear(); }
  void keep_if(const std::function<bool(GeoJsonFeature&)>& keep) override;

 private:
  std::vector<GeoJsonFeature>& features_;
};

// Adds a feature just read: a street's lines to c.lines, a footprint to `footprints`.
void add_feature(GeoJsonFeature f, GeoJsonCollection& c, FeatureStore& footprints);

// Throws IoError if the file cannot be read, is not JSON or is not a
// FeatureCollection; per-feature problems go to GeoJsonCollection::errors.
GeoJsonCollection read_geojson_file(const std::filesystem::path& path, const GeoJsonReadOptions& options = {});
// The same with the footprints put in `footprints`, not the collection's features.
GeoJsonCollection read_geojson_file(const std::filesystem::path& path, const GeoJsonReadOptions& options,
                                    FeatureStore& footprints);
// The same on text already in memory; source names it in messages.
GeoJsonCollection parse_geojson(std::string_view text, const GeoJsonReadOptions& options = {},
                                const std::string& source = "<memory>");

// The feature as a footprint: loops as given, edge ids numbered 0, 1, 2, ...
// across the loops in GeoJSON ring order, each edge at its edge_angles value
// if present, else at default_angle_deg. Run prepare_footprint() on the
// result to check it and fix orientation.
Footprint to_footprint(const GeoJsonFeature& feature, double default_angle_deg);

}  // namespace procex

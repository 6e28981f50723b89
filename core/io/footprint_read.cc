#include "core/io/footprint_read.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include <cpl_error.h>
#include <gdal_priv.h>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "core/io/gdal_support.h"
#include "core/io/io_error.h"
#include "core/io/output_crs.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The only drivers an untrusted file may open: no VRT (it names other files
// and URLs), nothing that reaches the network.
constexpr const char* kDrivers[] = {"GeoJSON", "ESRI Shapefile", "GPKG", "FlatGeobuf", "OSM", nullptr};
constexpr const char* kFormats = "GeoJSON, Shapefile, GeoPackage, FlatGeobuf or OSM";

// A file with no CRS whose footprints are all smaller than this, taken as
// metres, is longitude/latitude (see footprint_read.h).
constexpr double kLargestLonLatFootprint = 0.05;

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw IoError(path.string() + ": " + why, path.string());
}

struct CloseDataset {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};

// The 2008 GeoJSON "crs" member ({"type": "name", "properties": {"name": CRS}}),
// which GDAL writes for projected data; empty if absent.
std::string crs_member(const GeoJsonCollection& c, const fs::path& path) {
  const auto it = c.members.find("crs");
  if (it == c.members.end()) return "";
  const json crs = json::parse(it->second, nullptr, false);
  const json::json_pointer name("/properties/name");
  if (!crs.is_object() || crs.value("type", "") != "name" || !crs.contains(name) || !crs[name].is_string())
    refuse(path, "the \"crs\" member is not {\"type\": \"name\", \"properties\": {\"name\": CRS}}: give the file's CRS "
                 "with --crs");
  return crs[name].get<std::string>();
}

// A field's value as compact JSON text, as GeoJsonFeature::properties holds it.
std::string field_json(const OGRFeature& f, int i) {
  const OGRFieldDefn* d = f.GetFieldDefnRef(i);
  switch (d->GetType()) {
    case OFTInteger:
      if (d->GetSubType() == OFSTBoolean) return f.GetFieldAsInteger(i) ? "true" : "false";
      return json(f.GetFieldAsInteger(i)).dump();
    case OFTInteger64: return json(f.GetFieldAsInteger64(i)).dump();
    case OFTReal: {
      const double v = f.GetFieldAsDouble(i);
      return std::isfinite(v) ? json(v).dump() : "null";
    }
    default: return json(std::string(f.GetFieldAsString(i))).dump();
  }
}

// OSM tags the driver does not give a column ("height", "building:levels",
// "roof:shape") come in other_tags as an hstore: "k"=>"v","k2"=>"v2". Each
// becomes a string property; an ill-formed rest is left in other_tags only.
void add_other_tags(const std::string& text, std::map<std::string, std::string>& properties) {
  std::size_t i = 0;
  auto quoted = [&](std::string& out) {
    if (i >= text.size() || text[i] != '"') return false;
    for (++i; i < text.size() && text[i] != '"'; ++i) {
      if (text[i] == '\\' && i + 1 < text.size()) ++i;
      out += text[i];
    }
    return i++ < text.size();
  };
  while (i < text.size()) {
    std::string key, value;
    if (!quoted(key) || text.compare(i, 2, "=>") != 0) return;
    i += 2;
    if (!quoted(value)) return;
    properties.try_emplace(key, json(value).dump());
    if (i < text.size() && text[i++] != ',') return;
  }
}

// A Shapefile's .dbf holds field names of at most 10 characters, so GDAL
// writes "building:levels" as "building_l" (':' becomes '_', the rest is cut):
// the OSM Simple 3D Buildings keys a massing recipe reads whose names are cut
// get their names back, so they set from a Shapefile what they set from any
// other format. Only these: a cut name is ambiguous in general (building_m
// could be building:material; it is taken as building:min_level, the one with
// a bearing on the geometry). Names of 10 characters or fewer ("height",
// "roof_shape", "min_height") need none: binding reads ':' as '_'.
constexpr std::pair<std::string_view, const char*> kShapefileCutNames[] = {
    {"building_l", "building:levels"}, {"building_m", "building:min_level"}, {"roof_heigh", "roof:height"},
    {"roof_level", "roof:levels"},     {"roof_direc", "roof:direction"},     {"roof_orien", "roof:orientation"},
};

std::string property_name(const char* field, bool shapefile) {
  if (shapefile)
    for (const auto& [cut, name] : kShapefileCutNames)
      if (cut == field) return name;
  return field;
}

// The feature's id: its "id" column (as GeoJSON's properties.id), OSM's way
// or relation id, else its position.
std::string feature_id(const OGRFeature& f, std::size_t index) {
  for (const auto& [column, prefix] : {std::pair{"id", ""}, {"osm_way_id", "w"}, {"osm_id", "r"}})
    if (const int i = f.GetFieldIndex(column); i >= 0 && f.IsFieldSetAndNotNull(i))
      return prefix + std::string(f.GetFieldAsString(i));
  return std::to_string(index);
}

// Why a feature cannot be read.
struct FeatureProblem {
  std::string why;
};

void add_polygon(const OGRPolygon& polygon, std::size_t which, GeoJsonFeature& out) {
  if (polygon.IsEmpty()) throw FeatureProblem{"a polygon has no rings"};
  auto add = [&](const OGRLinearRing* ring) {
    std::vector<glm::dvec2> points;
    for (int i = 0; i < ring->getNumPoints(); ++i) {
      points.emplace_back(ring->getX(i), ring->getY(i));
      if (!std::isfinite(points.back().x) || !std::isfinite(points.back().y))
        throw FeatureProblem{"a coordinate is not a finite number"};
    }
    if (points.size() >= 2 && points.front() == points.back()) points.pop_back();
    out.loops.push_back(std::move(points));
    out.polygon_of_loop.push_back(which);
  };
  add(polygon.getExteriorRing());
  for (int i = 0; i < polygon.getNumInteriorRings(); ++i) add(polygon.getInteriorRing(i));
}

void add_line(const OGRLineString& line, GeoJsonFeature& out) {
  if (line.getNumPoints() < 2) throw FeatureProblem{"a LineString needs at least two points"};
  std::vector<glm::dvec2>& points = out.lines.emplace_back();
  for (int i = 0; i < line.getNumPoints(); ++i) {
    points.emplace_back(line.getX(i), line.getY(i));
    if (!std::isfinite(points.back().x) || !std::isfinite(points.back().y))
      throw FeatureProblem{"a coordinate is not a finite number"};
  }
}

void read_geometry(const OGRGeometry* g, GeoJsonFeature& out) {
  if (!g) throw FeatureProblem{"the feature has no geometry"};
  std::unique_ptr<OGRGeometry> linear;
  if (g->hasCurveGeometry()) linear.reset(g->getLinearGeometry()), g = linear.get();
  switch (wkbFlatten(g->getGeometryType())) {
    case wkbPolygon: return add_polygon(*g->toPolygon(), 0, out);
    case wkbMultiPolygon: {
      const OGRMultiPolygon& m = *g->toMultiPolygon();
      if (m.IsEmpty()) throw FeatureProblem{"a MultiPolygon needs at least one polygon"};
      for (int i = 0; i < m.getNumGeometries(); ++i) add_polygon(*m.getGeometryRef(i), static_cast<std::size_t>(i), out);
      return;
    }
    case wkbLineString: return add_line(*g->toLineString(), out);
    case wkbMultiLineString:
      for (const OGRLineString* line : *g->toMultiLineString()) add_line(*line, out);
      return;
    default:
      throw FeatureProblem{std::string("geometry type '") + OGRGeometryTypeToName(g->getGeometryType()) +
                           "' is not a Polygon or MultiPolygon (a footprint) or a LineString (a street)"};
  }
}

// The footprints of a file GDAL reads; crs is the layer's when empty.
GeoJsonCollection read_with_gdal(const fs::path& path, const std::string& layer_asked, std::string& crs,
                                 FeatureStore& footprints) {
  const std::string name = path.string();
  if (name.rfind("/vsi", 0) == 0 || name.find("://") != std::string::npos)
    refuse(path, "not a local file: footprints are read only from files on disk");
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) refuse(path, "cannot open the file (missing, or not a regular file)");
  register_gdal_drivers();
  const QuietGdal quiet;
  std::unique_ptr<GDALDataset, CloseDataset> dataset(
      GDALDataset::Open(name.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, kDrivers, nullptr, nullptr));
  if (!dataset) refuse(path, std::string("not a ") + kFormats + " file GDAL can read (" + gdal_reason() + ")");
  const bool osm = std::string(dataset->GetDriverName()) == "OSM";
  const bool shapefile = std::string(dataset->GetDriverName()) == "ESRI Shapefile";
  OGRLayer* layer = !layer_asked.empty()     ? dataset->GetLayerByName(layer_asked.c_str())
                    : osm                      ? dataset->GetLayerByName("multipolygons")
                    : dataset->GetLayerCount() ? dataset->GetLayer(0)
                                               : nullptr;
  if (!layer && !layer_asked.empty()) {
    std::string names;
    for (int i = 0; i < dataset->GetLayerCount(); ++i)
      names += std::string(i ? ", '" : "'") + dataset->GetLayer(i)->GetName() + "'";
    refuse(path, "has no layer '" + layer_asked + "': its layers are " + (names.empty() ? "none" : names) +
                     " (choose one with --layer)");
  }
  if (!layer) refuse(path, "holds no layer of polygons");
  if (osm && layer->SetAttributeFilter("building IS NOT NULL") != OGRERR_NONE)
    refuse(path, "cannot select the buildings: " + gdal_reason());
  if (crs.empty())
    if (const OGRSpatialReference* srs = layer->GetSpatialRef())
      if (const auto wkt = wkt2(*srs)) crs = *wkt;

  GeoJsonCollection out;
  const std::string layer_name = layer->GetName();
  for (std::size_t index = 0;; ++index) {
    CPLErrorReset();
    OGRFeatureUniquePtr f;
    if (osm) {  // the OSM driver reads all its layers at once, in file order
      OGRLayer* from = nullptr;
      do f.reset(dataset->GetNextFeature(&from, nullptr, nullptr, nullptr));
      while (f && from != layer);
    } else {
      f.reset(layer->GetNextFeature());
    }
    const bool gdal_failed = CPLGetLastErrorType() >= CE_Failure;
    if (!f) {
      if (gdal_failed) refuse(path, "GDAL stopped reading after feature " + std::to_string(index) + ": " + gdal_reason());
      break;
    }
    GeoJsonFeature feature;
    feature.index = index;
    feature.id = feature_id(*f, index);
    const std::string where = "layer '" + layer_name + "' (FID " + std::to_string(f->GetFID()) + ")";
    try {
      if (gdal_failed) throw FeatureProblem{"GDAL: " + gdal_reason()};
      for (int i = 0; i < f->GetFieldCount(); ++i)
        if (f->IsFieldSetAndNotNull(i)) {
          feature.properties[property_name(f->GetFieldDefnRef(i)->GetNameRef(), shapefile)] = field_json(*f, i);
          if (osm && std::string(f->GetFieldDefnRef(i)->GetNameRef()) == "other_tags")
            add_other_tags(f->GetFieldAsString(i), feature.properties);
        }
      read_geometry(f->GetGeometryRef(), feature);
      add_feature(std::move(feature), out, footprints);
    } catch (const FeatureProblem& p) {
      out.errors.push_back({index, feature.id, "", where + ": " + p.why});
    }
  }
  return out;
}

struct Box {
  glm::dvec2 low{std::numeric_limits<double>::infinity()}, high{-std::numeric_limits<double>::infinity()};
  void add(glm::dvec2 p) { low = glm::min(low, p), high = glm::max(high, p); }
  bool empty() const { return low.x > high.x; }
  bool lon_lat() const { return low.x >= -180 && high.x <= 180 && low.y >= -90 && high.y <= 90; }
};

Box box_of(const GeoJsonFeature& f) {
  Box b;
  for (const auto& loop : f.loops)
    for (const glm::dvec2& p : loop) b.add(p);
  return b;
}

// What settling the frame needs of the footprints, noted as they pass into
// the store: the footprints themselves may be on disk by then.
class BoundsNoted final : public FeatureStore {
 public:
  explicit BoundsNoted(FeatureStore& to) : to_(to) {}
  void add(GeoJsonFeature f) override {
    if (const Box b = box_of(f); !b.empty()) {
      all.add(b.low), all.add(b.high);
      all_lon_lat = all_lon_lat && b.lon_lat();
      largest = std::max({largest, b.high.x - b.low.x, b.high.y - b.low.y});
    }
    to_.add(std::move(f));
  }
  void clear() override {
    all = {}, all_lon_lat = true, largest = 0;
    to_.clear();
  }
  void keep_if(const std::function<bool(GeoJsonFeature&)>& keep) override { to_.keep_if(keep); }

  Box all;                  // of every footprint
  bool all_lon_lat = true;  // every footprint's box within longitude/latitude's range
  double largest = 0;       // the largest extent of a footprint's box

 private:
  FeatureStore& to_;
};

// The rule for a file that declares no CRS (footprint_read.h).
void refuse_unmarked_lon_lat(const BoundsNoted& bounds, const fs::path& path) {
  if (!bounds.all_lon_lat) return;
  if (const double largest = bounds.largest; largest > 0 && largest < kLargestLonLatFootprint)
    refuse(path, "declares no CRS and every coordinate is a longitude/latitude, with footprints under 5 cm across as "
                 "metres: it is longitude/latitude (what RFC 7946 GeoJSON means). Give --crs EPSG:4326 (or the file's "
                 "geographic CRS) to have it projected, or --crs of its metric system if it really is in metres");
}

// A transverse Mercator on `from`'s datum centred on `centre` (in from's own coordinates).
std::string local_frame(const OGRSpatialReference& from, glm::dvec2 centre, const fs::path& path) {
  OGRSpatialReference geographic;
  geographic.CopyGeogCSFrom(&from);
  geographic.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (!from.IsGeographic()) {
    std::unique_ptr<OGRCoordinateTransformation> to_geographic(OGRCreateCoordinateTransformation(&from, &geographic));
    if (!to_geographic || !to_geographic->Transform(1, &centre.x, &centre.y))
      refuse(path, "PROJ cannot find the longitude/latitude of the data's centre: " + gdal_reason());
  }
  auto rounded = [](double degrees) { return std::round(degrees * 1e6) / 1e6; };  // a stable name, ~0.1 m
  OGRSpatialReference frame;
  frame.CopyGeogCSFrom(&from);
  frame.SetProjCS("procex local transverse Mercator");
  frame.SetTM(rounded(centre.y), rounded(centre.x), 1.0, 0.0, 0.0);
  frame.SetLinearUnits(SRS_UL_METER, 1.0);
  const auto wkt = wkt2(frame);
  if (!wkt) refuse(path, "PROJ cannot write the local frame: " + gdal_reason());
  return *wkt;
}

// Projects c from `source` to the frame its buildings are made in (footprint_read.h).
void settle_frame(GeoJsonCollection& c, BoundsNoted& footprints, const std::string& source, const std::string& target,
                  const fs::path& path) {
  if (source.empty()) {
    refuse_unmarked_lon_lat(footprints, path);
    if (!target.empty()) refuse(path, "declares no CRS to project from to --target-crs: give its CRS with --crs");
    return;
  }
  const QuietGdal quiet;
  OGRSpatialReference from;
  if (const auto problem = read_crs(source, from)) refuse(path, *problem + ": give the file's CRS with --crs");
  if (target.empty() && !from.IsGeographic() && from.GetLinearUnits() == 1.0) {
    c.crs = source;
    return;
  }
  Box all = footprints.all;
  for (const auto& line : c.lines)
    for (const glm::dvec2& p : line) all.add(p);
  if (all.empty()) {
    c.crs = target.empty() ? source : target;
    return;
  }
  if (from.IsGeographic() && !all.lon_lat())
    refuse(path, "its CRS '" + source + "' is geographic but its coordinates are not longitudes/latitudes (x from " +
                     std::to_string(all.low.x) + " to " + std::to_string(all.high.x) + ", y from " +
                     std::to_string(all.low.y) + " to " + std::to_string(all.high.y) +
                     "): if it is in metres, give --crs of its metric system");
  if (!target.empty())
    if (const auto problem = crs_problem(target)) refuse(path, "--target-crs: " + *problem);
  const std::string frame = target.empty() ? local_frame(from, (all.low + all.high) * 0.5, path) : target;
  OGRSpatialReference to;
  if (const auto problem = read_crs(frame, to)) refuse(path, *problem);
  std::unique_ptr<OGRCoordinateTransformation> project(OGRCreateCoordinateTransformation(&from, &to));
  if (!project) refuse(path, "PROJ cannot take its CRS '" + source + "' to '" + frame + "': " + gdal_reason());

  footprints.keep_if([&](GeoJsonFeature& f) {
    bool ok = true;
    for (auto& loop : f.loops)
      for (glm::dvec2& p : loop) ok = ok && project->Transform(1, &p.x, &p.y) && std::isfinite(p.x) && std::isfinite(p.y);
    if (!ok) c.errors.push_back({f.index, f.id, "", "PROJ cannot project it from '" + source + "' (" + gdal_reason() + ")"});
    return ok;
  });
  // A street PROJ cannot project is left out: it only labels the edges near it.
  std::erase_if(c.lines, [&](std::vector<glm::dvec2>& line) {
    bool ok = true;
    for (glm::dvec2& p : line) ok = ok && project->Transform(1, &p.x, &p.y) && std::isfinite(p.x) && std::isfinite(p.y);
    return !ok;
  });
  std::sort(c.errors.begin(), c.errors.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  c.crs = frame;
}

std::string lower_extension(const fs::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return e;
}

}  // namespace

GeoJsonCollection read_footprints(const fs::path& path, const FootprintReadOptions& options) {
  std::vector<GeoJsonFeature> features;
  FeatureList list(features);
  GeoJsonCollection c = read_footprints(path, options, list);
  c.features = std::move(features);
  return c;
}

GeoJsonCollection read_footprints(const fs::path& path, const FootprintReadOptions& options, FeatureStore& footprints) {
  std::string source = options.crs;
  BoundsNoted noted(footprints);
  GeoJsonCollection c;
  if (const std::string e = lower_extension(path); e == ".geojson" || e == ".json") {
    if (!options.layer.empty())
      refuse(path, "a GeoJSON file holds one layer, so --layer '" + options.layer + "' names nothing: leave it out");
    c = read_geojson_file(path, options.geojson, noted);
    if (source.empty()) source = crs_member(c, path);
  } else {
    c = read_with_gdal(path, options.layer, source, noted);
  }
  settle_frame(c, noted, source, options.target_crs, path);
  if (!options.streets.empty()) {
    FootprintReadOptions streets;
    streets.crs = options.crs, streets.target_crs = c.crs, streets.layer = options.streets_layer;
    GeoJsonCollection more = read_footprints(options.streets, streets);
    c.lines.insert(c.lines.end(), std::make_move_iterator(more.lines.begin()), std::make_move_iterator(more.lines.end()));
  }
  return c;
}

std::vector<fs::path> footprint_files(const fs::path& path) {
  std::vector<fs::path> files = {path};
  if (lower_extension(path) != ".shp") return files;
  for (const char* sidecar : {".dbf", ".shx", ".prj", ".cpg", ".DBF", ".SHX", ".PRJ", ".CPG"})
    files.push_back(fs::path(path).replace_extension(sidecar));
  return files;
}

}  // namespace procex

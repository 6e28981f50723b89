#include "core/io/geopackage_write.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <limits>
#include <memory>
#include <set>
#include <string_view>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <nlohmann/json.hpp>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "base/atomic_write.h"
#include "core/io/gdal_support.h"
#include "core/io/io_error.h"

namespace procex {
namespace {

using json = nlohmann::json;

// gpkg_contents.last_change: a fixed date keeps the bytes a function of the buildings.
class FixedDate {
 public:
  FixedDate() { CPLSetThreadLocalConfigOption("OGR_CURRENT_DATE", "2000-01-01T00:00:00.000Z"); }
  ~FixedDate() { CPLSetThreadLocalConfigOption("OGR_CURRENT_DATE", nullptr); }
  FixedDate(const FixedDate&) = delete;
  FixedDate& operator=(const FixedDate&) = delete;
};

enum class ColumnType { Real, Boolean, String };

struct Column {
  std::string property, name;
  ColumnType type = ColumnType::Real;
};

// Each property's column: its type from every value the buildings give it.
std::vector<Column> property_columns(const std::vector<GisBuilding>& buildings, std::set<std::string>& used) {
  std::map<std::string, std::set<json::value_t>> kinds;
  for (const GisBuilding& b : buildings)
    for (const auto& [name, text] : b.properties) {
      const json v = json::parse(text, nullptr, false);
      auto& k = kinds[name];
      if (!v.is_null()) k.insert(v.is_number() ? json::value_t::number_float : v.type());
    }
  std::vector<Column> out;
  for (const auto& [name, types] : kinds) {
    Column& c = out.emplace_back();
    c.property = name;
    c.type = types.empty() || types == std::set{json::value_t::number_float} ? ColumnType::Real
             : types == std::set{json::value_t::boolean}                     ? ColumnType::Boolean
                                                                              : ColumnType::String;
    auto lower = [](std::string s) {
      std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
      return s;
    };
    c.name = name;
    for (int n = 2; !used.insert(lower(c.name)).second; ++n) c.name = name + "_" + std::to_string(n);
  }
  return out;
}

OGRPolygon polygon_of(const std::vector<glm::dvec3>& face) {
  OGRLinearRing ring;
  for (const glm::dvec3& p : face) ring.addPoint(p.x, p.y, p.z);
  ring.closeRings();
  OGRPolygon polygon;
  polygon.addRing(&ring);  // copies
  return polygon;
}

class Writer {
 public:
  Writer(const std::filesystem::path& path, const std::string& memory) : path_(path), memory_(memory) {
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
    if (!driver) fail("GDAL has no GeoPackage driver");
    dataset_.reset(driver->Create(memory_.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!dataset_) fail("GDAL could not make a GeoPackage: " + gdal_reason());
  }
  ~Writer() {
    dataset_.reset();
    VSIUnlink(memory_.c_str());
  }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  [[noreturn]] void fail(const std::string& why) const {
    throw IoError("cannot write '" + path_.string() + "': " + why, path_.string());
  }
  void check(bool ok, const std::string& what) const {
    if (!ok) fail(what + ": " + gdal_reason());
  }

  OGRLayer* layer(const char* name, OGRSpatialReference& srs, OGRwkbGeometryType type) {
    const char* options[] = {"FID=fid", "GEOMETRY_NAME=geom", nullptr};
    OGRLayer* l = dataset_->CreateLayer(name, &srs, type, const_cast<char**>(options));
    check(l != nullptr, std::string("layer ") + name);
    return l;
  }

  // The whole file, read from GDAL's memory once it is closed.
  std::string finish() {
    check(dataset_->CommitTransaction() == OGRERR_NONE, "committing the layers");
    dataset_.reset();
    vsi_l_offset size = 0;
    GByte* bytes = VSIGetMemFileBuffer(memory_.c_str(), &size, FALSE);
    if (!bytes) fail("GDAL lost the GeoPackage it made: " + gdal_reason());
    return std::string(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size));
  }

  GDALDataset& dataset() { return *dataset_; }

 private:
  struct Close {
    void operator()(GDALDataset* d) const { GDALClose(d); }
  };
  std::filesystem::path path_;
  std::string memory_;
  std::unique_ptr<GDALDataset, Close> dataset_;
};

void add_field(Writer& w, OGRLayer* layer, const std::string& name, OGRFieldType type,
               OGRFieldSubType subtype = OFSTNone) {
  OGRFieldDefn field(name.c_str(), type);
  field.SetSubType(subtype);
  w.check(layer->CreateField(&field) == OGRERR_NONE, "column " + name);
}

void set_property(OGRFeature& f, const Column& c, const std::string& text) {
  const json v = json::parse(text, nullptr, false);
  if (v.is_null() || v.is_discarded()) return f.SetFieldNull(f.GetFieldIndex(c.name.c_str()));
  switch (c.type) {
    case ColumnType::Real: return f.SetField(c.name.c_str(), v.get<double>());
    case ColumnType::Boolean: return f.SetField(c.name.c_str(), v.get<bool>() ? 1 : 0);
    case ColumnType::String: return f.SetField(c.name.c_str(), v.is_string() ? v.get<std::string>().c_str() : text.c_str());
  }
}

}  // namespace

void write_geopackage(const std::filesystem::path& path, const std::string& crs, const std::vector<GisBuilding>& buildings) {
  register_gdal_drivers();
  const QuietGdal quiet;
  const FixedDate date;
  OGRSpatialReference srs;
  const std::optional<std::string> problem = read_metric_crs(crs, srs);
  auto refuse = [&](const std::string& why) { throw IoError("cannot write '" + path.string() + "': " + why, path.string()); };
  if (problem) refuse(*problem);

  static std::atomic<std::uint64_t> serial{0};
  Writer w(path, "/vsimem/procex_" + std::to_string(++serial) + ".gpkg");
  OGRLayer* shells = w.layer("buildings", srs, wkbMultiPolygon25D);
  std::set<std::string> used = {"fid", "geom", "building_id", "procex_ground", "procex_height", "procex_volume"};
  const std::vector<Column> columns = property_columns(buildings, used);
  add_field(w, shells, "building_id", OFTString);
  for (const Column& c : columns)
    add_field(w, shells, c.name, c.type == ColumnType::String ? OFTString : c.type == ColumnType::Real ? OFTReal : OFTInteger,
              c.type == ColumnType::Boolean ? OFSTBoolean : OFSTNone);
  for (const char* measure : {"procex_ground", "procex_height", "procex_volume"}) add_field(w, shells, measure, OFTReal);
  OGRLayer* surfaces = w.layer("surfaces", srs, wkbPolygon25D);
  add_field(w, surfaces, "building_id", OFTString);
  add_field(w, surfaces, "tag", OFTString);

  // One transaction for both layers: GeoPackage writes are slow one by one.
  w.check(w.dataset().StartTransaction() == OGRERR_NONE, "starting a transaction");
  for (const GisBuilding& b : buildings) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    OGRMultiPolygon shell;
    for (std::size_t i = 0; i < b.faces.size(); ++i) {
      for (const glm::dvec3& p : b.faces[i]) low = std::min(low, p.z), high = std::max(high, p.z);
      OGRPolygon polygon = polygon_of(b.faces[i]);
      OGRFeature surface(surfaces->GetLayerDefn());
      surface.SetField("building_id", b.id.c_str());
      surface.SetField("tag", b.face_tags[i].c_str());
      surface.SetGeometry(&polygon);
      w.check(surfaces->CreateFeature(&surface) == OGRERR_NONE, "a surface of building " + b.id);
      shell.addGeometry(&polygon);
    }
    OGRFeature f(shells->GetLayerDefn());
    f.SetField("building_id", b.id.c_str());
    for (const Column& c : columns)
      if (const auto it = b.properties.find(c.property); it != b.properties.end()) set_property(f, c, it->second);
    if (low <= high) f.SetField("procex_ground", low), f.SetField("procex_height", high - low);
    f.SetField("procex_volume", b.volume);
    f.SetGeometry(&shell);
    w.check(shells->CreateFeature(&f) == OGRERR_NONE, "building " + b.id);
  }
  write_file_atomically(path, w.finish());
}

}  // namespace procex

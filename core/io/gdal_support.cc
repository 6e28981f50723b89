#include "core/io/gdal_support.h"

#include <mutex>

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>

namespace procex {

QuietGdal::QuietGdal() {
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
}

QuietGdal::~QuietGdal() { CPLPopErrorHandler(); }

std::string gdal_reason() {
  const std::string m = CPLGetLastErrorMsg();
  return m.empty() ? "GDAL gave no reason" : m;
}

void register_gdal_drivers() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

std::optional<std::string> read_crs(const std::string& crs, OGRSpatialReference& srs) {
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (srs.SetFromUserInput(crs.c_str(), OGRSpatialReference::SET_FROM_USER_INPUT_LIMITATIONS) != OGRERR_NONE)
    return "PROJ does not know the CRS '" + crs + "' (" + gdal_reason() + ")";
  return std::nullopt;
}

std::optional<std::string> read_metric_crs(const std::string& crs, OGRSpatialReference& srs) {
  if (crs.empty())
    return "no coordinate reference system: give the footprints' CRS with --crs (e.g. EPSG:32632, a WKT or a "
           "PROJ string; projected, in metres)";
  if (auto problem = read_crs(crs, srs)) return problem;
  if (srs.IsGeographic())
    return "the CRS '" + crs + "' is geographic (longitude/latitude in degrees); procex builds in metres: " +
           "give a projected CRS in metres (procex projects longitude/latitude footprints itself)";
  if (const double metres = srs.GetLinearUnits(); metres != 1.0)
    return "the CRS '" + crs + "' measures in units of " + std::to_string(metres) +
           " m; procex writes metres: give a CRS in metres";
  return std::nullopt;
}

std::optional<std::string> wkt2(const OGRSpatialReference& srs) {
  char* wkt = nullptr;
  const char* options[] = {"FORMAT=WKT2_2019", nullptr};
  std::optional<std::string> out;
  if (srs.exportToWkt(&wkt, options) == OGRERR_NONE && wkt) out = wkt;
  CPLFree(wkt);
  return out;
}

}  // namespace procex

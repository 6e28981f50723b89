#include "core/io/gdal_support.h"

#include <mutex>

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

}  // namespace procex

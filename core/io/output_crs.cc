#include "core/io/output_crs.h"

#include <string_view>

#include "core/io/gdal_support.h"

namespace procex {

std::optional<std::string> crs_problem(const std::string& crs) {
  const QuietGdal quiet;
  OGRSpatialReference srs;
  return read_metric_crs(crs, srs);
}

OutputCrsText output_crs_wkt2(const std::string& crs) {
  const QuietGdal quiet;
  OGRSpatialReference srs;
  if (auto problem = read_metric_crs(crs, srs)) return {"", std::move(problem)};
  if (auto text = wkt2(srs)) return {std::move(*text), std::nullopt};
  return {"", "PROJ cannot write the CRS '" + crs + "' as WKT2 (" + gdal_reason() + ")"};
}

std::optional<std::string> crs_epsg_code(const std::string& crs) {
  const QuietGdal quiet;
  OGRSpatialReference srs;
  if (read_crs(crs, srs)) return std::nullopt;
  const char* authority = srs.GetAuthorityName(nullptr);
  if (!(authority && std::string_view(authority) == "EPSG") && srs.AutoIdentifyEPSG() != OGRERR_NONE) return std::nullopt;
  const char* code = srs.GetAuthorityCode(nullptr);
  if (!code) return std::nullopt;
  return std::string(code);
}

}  // namespace procex

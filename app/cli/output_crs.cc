#include "app/cli/output_crs.h"

#include "core/io/geopackage_write.h"

namespace procex {

std::optional<std::string> settle_output_crs(const std::filesystem::path& output, const GeoJsonCollection* footprints,
                                             ExportOptions& options) {
  if (footprints) options.crs = footprints->crs;
  if (!is_gis_file(output)) return std::nullopt;
  return crs_problem(options.crs);
}

}  // namespace procex

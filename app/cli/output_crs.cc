#include "app/cli/output_crs.h"

namespace procex {

std::optional<std::string> settle_output_crs(const std::filesystem::path& output, const GeoJsonCollection* footprints,
                                             ExportOptions& options) {
  if (footprints) options.crs = footprints->crs;
  return output_crs_problem(output, options.crs);
}

}  // namespace procex

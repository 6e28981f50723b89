#include "app/cli/output_crs.h"

#include <nlohmann/json.hpp>

#include "core/io/geopackage_write.h"

namespace procex {

std::optional<std::string> settle_output_crs(const std::filesystem::path& output, const GeoJsonCollection* footprints,
                                             ExportOptions& options) {
  if (options.crs.empty() && footprints)
    if (const auto it = footprints->members.find("crs"); it != footprints->members.end()) {
      const nlohmann::json crs = nlohmann::json::parse(it->second, nullptr, false);
      const nlohmann::json::json_pointer name("/properties/name");
      if (!crs.is_object() || crs.value("type", "") != "name" || !crs.contains(name) || !crs[name].is_string())
        return is_gis_file(output) ? std::optional<std::string>("the footprints' \"crs\" member is not {\"type\": \"name\", "
                                                                "\"properties\": {\"name\": CRS}}: give --crs")
                                   : std::nullopt;
      options.crs = crs[name].get<std::string>();
    }
  if (!is_gis_file(output)) return std::nullopt;
  return crs_problem(options.crs);
}

}  // namespace procex

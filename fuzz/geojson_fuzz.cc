// Fuzzes the GeoJSON footprint reader: any input must either read (bad
// features listed, not thrown) or throw IoError, and every feature read must
// become a footprint and answer its property queries.
#include <cstdint>
#include <string_view>

#include "core/io/geojson.h"
#include "core/io/io_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const procex::GeoJsonCollection c = procex::parse_geojson(text, {"angles", false}, "fuzz.geojson");
    for (const procex::GeoJsonFeature& f : c.features) {
      (void)procex::to_footprint(f, 45.0);
      for (const auto& [name, value] : f.properties) {
        (void)f.property_text(name);
        (void)f.property_number(name);
      }
    }
  } catch (const procex::IoError&) {
  }
  return 0;
}

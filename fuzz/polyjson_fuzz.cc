// Fuzzes the .json shape reader: any input must either give shapes or throw
// IoError, and a shape read must become a footprint or an InputError.
#include <cstdint>
#include <string_view>

#include "core/geom/error.h"
#include "core/io/io_error.h"
#include "core/io/polyjson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    for (const procex::PolyShape& shape : procex::parse_polyjson(text, "fuzz.json")) {
      try {
        (void)procex::to_footprint(shape, 45.0);
      } catch (const procex::InputError&) {
      }
    }
  } catch (const procex::IoError&) {
  }
  return 0;
}

// The sample block (samples/footprints/sample_block.geojson) the GIS tests
// share: its path, and its own metric frame as its "projection" member states
// it (a transverse Mercator around Monaco's cathedral).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/app/command_test.h"

namespace procex::test {

inline const std::filesystem::path kRepository = std::filesystem::path(PROCEX_SAMPLES).parent_path();
inline const std::filesystem::path kSampleBlock = kRepository / "samples" / "footprints" / "sample_block.geojson";

inline std::string sample_block_crs() {
  return nlohmann::json::parse(read_text(kSampleBlock))["projection"]["proj"].get<std::string>();
}

}  // namespace procex::test

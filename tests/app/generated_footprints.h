// Footprint files for tests that need many buildings: a FeatureCollection of
// n small rectangles, one per 40 m cell, each with an id and a property, as
// bench/batch_footprints.py writes them.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace procex::test {

inline void write_footprints(const std::filesystem::path& file, std::size_t n) {
  std::ofstream out(file);
  out << "{\"type\": \"FeatureCollection\", \"features\": [\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double x = 40.0 * static_cast<double>(i % 1000), y = 40.0 * static_cast<double>(i / 1000);
    char ring[256];
    std::snprintf(ring, sizeof ring, "[[%.1f,%.1f],[%.1f,%.1f],[%.1f,%.1f],[%.1f,%.1f],[%.1f,%.1f]]", x, y, x + 12, y,
                  x + 12, y + 9, x, y + 9, x, y);
    out << (i ? "," : "") << "{\"type\":\"Feature\",\"id\":\"b" << i
        << "\",\"properties\":{\"building:levels\":3},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[" << ring
        << "]}}\n";
  }
  out << "]}\n";
}

}  // namespace procex::test

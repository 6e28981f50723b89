// The real and synthetic data the tests and benchmarks read, kept in the
// repository's data/ (PROCEX_DATA, defined by CMake), so a clone anywhere
// tests itself. The corpus is a fixed list: a missing file fails to read
// instead of quietly shrinking the suite.
#pragma once

#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace procex {

inline std::filesystem::path synthetic_file(const std::string& name) {
  return std::filesystem::path(PROCEX_DATA) / "synthetic" / (name + ".json");
}

inline std::filesystem::path footprint_file(const std::string& name) {
  return std::filesystem::path(PROCEX_DATA) / "footprints" / (name + ".geojson");
}

// The OpenStreetMap corpus of data/footprints/ (see its README), in one order.
inline std::vector<std::filesystem::path> footprint_corpus_files() {
  return {footprint_file("corpus_baltimore_2015"), footprint_file("corpus_manhattan_2015"),
          footprint_file("corpus_monaco")};
}

// A corpus file's stem as a test name (GoogleTest takes letters, digits and '_').
inline std::string corpus_test_name(const std::filesystem::path& file) {
  std::string name = file.stem().string();
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

}  // namespace procex

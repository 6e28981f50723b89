// Where the shared real and synthetic data live: PROCEX_SHARED, which CMake
// defines for the test suites and the benchmarks (-DPROCEX_SHARED_DIR=...).
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace procex {

inline std::filesystem::path synthetic_file(const std::string& name) {
  return std::filesystem::path(PROCEX_SHARED) / "data" / "synthetic" / (name + ".json");
}

// Every *.geojson of data/footprints/, sorted, so runs visit them in one order.
inline std::vector<std::filesystem::path> footprint_corpus_files() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path dir = std::filesystem::path(PROCEX_SHARED) / "data" / "footprints";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".geojson") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// A corpus file's stem as a test name (GoogleTest takes letters, digits and '_').
inline std::string corpus_test_name(const std::filesystem::path& file) {
  std::string name = file.stem().string();
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

}  // namespace procex

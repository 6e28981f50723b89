// procex_roof_hashes: a fingerprint of every sweep a soak makes, to the bit,
// so that a soak's counts can be carried across an engine change that leaves
// them all the same (TESTING.md, "Carrying a soak across an engine change").
// Soaks of the large classes take hours of CGAL; this takes the sweeps alone.
//
//   procex_roof_hashes [CLASS FIRST-LAST | FILE]...
//
// CLASS FIRST-LAST: each case of a generated class (grid, large_stars, ...)
// with its seed in the range, both ends in: its prepared plan's sweep and the
// sweeps check_case makes besides (its transforms, and CGAL's plan).
// FILE: each feature of a GeoJSON file swept at 45 degrees, or of a
// generated_*.geojson fixture with its own angles, profiles and options.
//
// One line a sweep: what was swept, the hash of its vertices and faces (or of
// its error: type, message and height), and its vertex count and retries.
// Run at two commits; `diff` of the outputs lists every sweep that changed.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/sweep/sweep.h"
#include "tests/support/generators/check_case.h"
#include "tests/support/generators/run_generated.h"
#include "tests/support/generators/shrink.h"

namespace procex::testing {
namespace {

// FNV-1a, 64 bits, over the bytes of what is mixed in.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void mix(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void mix(const T& value) {
    mix(&value, sizeof value);
  }
};

void print_sweep(const std::string& what, const Footprint& fp, const SweepOptions& options) {
  Hash hash;
  std::string summary;
  try {
    const Surface s = sweep(fp, options);
    for (const glm::dvec3& v : s.vertices) hash.mix(v);
    for (const SurfaceFace& f : s.faces) {
      hash.mix(f.kind);
      hash.mix(f.source_edge);
      hash.mix(f.tag.data(), f.tag.size());
      for (const auto& loop : f.loops) {
        hash.mix(loop.size());
        hash.mix(loop.data(), loop.size() * sizeof loop[0]);
      }
    }
    summary = std::to_string(s.vertices.size()) + " vertices, " + std::to_string(s.retries) + " retries";
  } catch (const SweepError& e) {
    const double height = e.height();
    hash.mix(height);
    hash.mix(e.what(), std::strlen(e.what()));
    summary = std::string("error: ") + e.what();
  } catch (const std::exception& e) {
    hash.mix(e.what(), std::strlen(e.what()));
    summary = std::string("error: ") + e.what();
  }
  std::printf("%s %016llx %s\n", what.c_str(), static_cast<unsigned long long>(hash.h), summary.c_str());
}

void print_case(const std::string& name, const Footprint& footprint, const SweepOptions& options) {
  Footprint prepared;
  try {
    prepared = prepare_footprint(footprint).footprint;
  } catch (const std::exception& e) {
    std::printf("%s refused: %s\n", name.c_str(), e.what());
    return;
  }
  print_sweep(name, prepared, options);
  for (const auto& [plan, fp] : checked_plans(prepared, options)) print_sweep(name + ", " + plan, fp, options);
}

bool class_named(const std::string& name, CaseClass& out) {
  for (int k = 0; k <= static_cast<int>(CaseClass::RandomPolygonsWalls); ++k)
    if (name == class_name(static_cast<CaseClass>(k))) {
      out = static_cast<CaseClass>(k);
      return true;
    }
  return false;
}

void print_file(const std::string& path) {
  const GeoJsonCollection read = read_geojson_file(path);
  const bool fixture = path.find("generated_") != std::string::npos;
  for (const GeoJsonFeature& f : read.features) {
    const std::string name = path + " " + f.id;
    if (fixture) {
      const GeneratedCase c = case_from_fixture(f);
      print_case(name, c.footprint, c.options);
    } else {
      print_case(name, to_footprint(f, 45.0), {});
    }
  }
}

int run(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s [CLASS FIRST-LAST | FILE]...\n", argv[0]);
    return 2;
  }
  for (int a = 1; a < argc; ++a) {
    CaseClass cls;
    if (class_named(argv[a], cls)) {
      if (a + 1 == argc) throw std::invalid_argument(std::string(argv[a]) + ": give its seeds, e.g. 0-99");
      const auto [first, end] = seed_range(argv[++a], class_name(cls));
      for (std::size_t seed = first; seed < end; ++seed) {
        const GeneratedCase c = generate_case(cls, seed);
        print_case(std::string(class_name(cls)) + " " + std::to_string(seed), c.footprint, c.options);
      }
    } else {
      print_file(argv[a]);
    }
  }
  return 0;
}

}  // namespace
}  // namespace procex::testing

int main(int argc, char** argv) {
  try {
    return procex::testing::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "procex_roof_hashes: %s\n", e.what());
    return 1;
  }
}

// procex's sweep against CGAL 5.5's create_interior_straight_skeleton_2 on the
// same inputs, in one run: regular n-gons, the 24-loop image contours, a
// 200-vertex rectilinear footprint, the 6000-footprint city and the whole
// OpenStreetMap corpus. Every edge at 45 degrees (CGAL: unweighted), which is
// the one case where both compute the same thing. Single-threaded.
//
// Inputs are read and checked (prepare_footprint) before timing; a run times
// only sweep() for procex and only the skeleton construction for CGAL.
// Peak memory: the process's peak resident set (getrusage) over one engine's
// runs on one case, reset before each measurement through
// /proc/self/clear_refs, so each figure is that engine's own peak.
//
//   procex_sweep_bench [--runs N] [--budget SECONDS] [--no-cgal] [CASE...]
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "bench/process_usage.h"
#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/io/polyjson.h"
#include "core/sweep/sweep.h"
#include "tests/support/cgal_skeleton.h"
#include "tests/support/data_files.h"

namespace procex {
namespace {

struct Case {
  std::string name;
  std::vector<Footprint> footprints;
  std::vector<std::string> ids;  // for naming failures
  std::size_t vertices = 0;
  std::size_t refused = 0;  // inputs prepare_footprint refused (not timed by either engine)
};

void add_footprint(Case& c, const Footprint& raw, std::string id) {
  try {
    c.footprints.push_back(prepare_footprint(raw).footprint);
    c.ids.push_back(std::move(id));
    for (const Loop& l : raw.loops) c.vertices += l.points.size();
  } catch (const InputError&) {
    ++c.refused;
  }
}

Case synthetic_case(const std::string& name) {
  Case c{name, {}, {}, 0, 0};
  const std::vector<PolyShape> shapes = read_polyjson_file(synthetic_file(name));
  for (std::size_t i = 0; i < shapes.size(); ++i) add_footprint(c, to_footprint(shapes[i], 45.0), std::to_string(i));
  return c;
}

Case osm_case() {
  Case c{"osm_corpus", {}, {}, 0, 0};
  for (const auto& file : footprint_corpus_files())
    for (const GeoJsonFeature& f : read_geojson_file(file).features) add_footprint(c, to_footprint(f, 45.0), f.id);
  return c;
}

struct Measurement {
  std::vector<double> ms;  // one per run
  double peak_mb = 0.0;
  double base_mb = 0.0;  // resident before the first run
  std::size_t failures = 0;
  std::vector<std::string> failed_ids;

  double median() const {
    std::vector<double> s = ms;
    std::sort(s.begin(), s.end());
    return s.empty() ? 0.0 : (s[(s.size() - 1) / 2] + s[s.size() / 2]) / 2.0;
  }
};

double resident_mb() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Hands freed heap pages back first: otherwise they stay resident and every
// later measurement would start at the previous one's peak.
void reset_peak() {
  ::malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
}

struct RunLimits {
  int runs = 5;
  double budget_s = 30.0;  // stop after this much time once 3 runs are in
};

// run_one(i) processes footprint i and returns false if the engine failed on it.
Measurement measure(const Case& c, const RunLimits& limits, const std::function<bool(std::size_t)>& run_one) {
  Measurement m;
  reset_peak();
  m.base_mb = resident_mb();
  double spent_s = 0.0;
  for (int r = 0; r < limits.runs; ++r) {
    if (r >= 3 && spent_s > limits.budget_s) break;
    std::size_t failures = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < c.footprints.size(); ++i)
      if (!run_one(i)) {
        ++failures;
        if (r == 0 && m.failed_ids.size() < 10) m.failed_ids.push_back(c.ids[i]);
      }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    m.ms.push_back(ms);
    m.failures = failures;
    spent_s += ms / 1000.0;
  }
  m.peak_mb = bench::peak_rss_mb();
  return m;
}

Measurement measure_procex(const Case& c, const RunLimits& limits) {
  std::size_t sink = 0;
  Measurement m = measure(c, limits, [&](std::size_t i) {
    try {
      sink += sweep(c.footprints[i]).vertices.size();
      return true;
    } catch (const SweepError&) {
      return false;
    }
  });
  if (sink == 0) std::fprintf(stderr, "procex built nothing on %s\n", c.name.c_str());
  return m;
}

Measurement measure_cgal(const Case& c, const RunLimits& limits) {
  std::vector<CgalSkeletonInput> inputs;
  inputs.reserve(c.footprints.size());
  for (const Footprint& fp : c.footprints) inputs.emplace_back(fp);
  std::size_t sink = 0;
  Measurement m = measure(c, limits, [&](std::size_t i) {
    try {
      sink += inputs[i].skeletonise();
      return true;
    } catch (const std::runtime_error&) {
      return false;
    }
  });
  if (sink == 0) std::fprintf(stderr, "CGAL built nothing on %s\n", c.name.c_str());
  return m;
}

// "peak (+growth over what was resident before the first run)".
std::string memory(const Measurement& m) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f (+%.1f)", m.peak_mb, std::max(0.0, m.peak_mb - m.base_mb));
  return buf;
}

void print_failures(const char* engine, const Case& c, const Measurement& m) {
  if (m.failures == 0) return;
  std::fprintf(stderr, "%s failed on %zu of %zu footprints of %s:", engine, m.failures, c.footprints.size(),
               c.name.c_str());
  for (const std::string& id : m.failed_ids) std::fprintf(stderr, " %s", id.c_str());
  std::fprintf(stderr, "%s\n", m.failures > m.failed_ids.size() ? " ..." : "");
}

int run(int argc, char** argv) {
  RunLimits limits;
  bool with_cgal = true;
  std::vector<std::string> wanted;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) limits.runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--budget" && i + 1 < argc) limits.budget_s = std::atof(argv[++i]);
    else if (a == "--no-cgal") with_cgal = false;
    else if (a.rfind("--", 0) == 0) {
      std::fprintf(stderr, "usage: %s [--runs N] [--budget SECONDS] [--no-cgal] [CASE...]\n", argv[0]);
      return 2;
    } else wanted.push_back(a);
  }
  const std::vector<std::string> all = {"a_circle_0064", "a_circle_0256", "a_circle_1024", "a_circle_4096",
                                        "b_image_contours", "c_ortho_0200", "d_city_6000", "osm_corpus"};
  for (const std::string& w : wanted)
    if (std::find(all.begin(), all.end(), w) == all.end()) {
      std::fprintf(stderr, "unknown case %s\n", w.c_str());
      return 2;
    }

  std::printf("| case | footprints | vertices | procex ms (median) | CGAL 5.5 ms (median) | CGAL / procex | "
              "procex peak MB (+growth) | CGAL peak MB (+growth) | runs (procex, CGAL) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (const std::string& name : all) {
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), name) == wanted.end()) continue;
    const Case c = name == "osm_corpus" ? osm_case() : synthetic_case(name);
    if (c.refused > 0) std::fprintf(stderr, "%s: %zu inputs refused by prepare_footprint, not timed\n", name.c_str(), c.refused);
    const Measurement p = measure_procex(c, limits);
    print_failures("procex", c, p);
    std::printf("| %s | %zu | %zu | %.2f | ", name.c_str(), c.footprints.size(), c.vertices, p.median());
    if (with_cgal) {
      const Measurement g = measure_cgal(c, limits);
      print_failures("CGAL", c, g);
      std::printf("%.2f | %.1fx | %s | %s | %zu, %zu |\n", g.median(), g.median() / p.median(), memory(p).c_str(),
                  memory(g).c_str(), p.ms.size(), g.ms.size());
    } else {
      std::printf("- | - | %s | - | %zu, - |\n", memory(p).c_str(), p.ms.size());
    }
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace procex

int main(int argc, char** argv) { return procex::run(argc, argv); }

// Profiles in the sweep (issue 3's benchmark, figures in BENCHMARKS.md,
// "Profiles"): the fig. 25 analogue (24 nested loops, 552 vertices, three
// profiles with eaves stepping out) and every OpenStreetMap footprint of
// ../shared/data/footprints under a four-segment house profile (wall, soffit,
// fascia, roof). Footprints are read and prepared before timing; one thread.
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/sweep/sweep.h"
#include "tests/support/shared_data.h"

namespace procex {
namespace {

Footprint figure25_analogue() {
  auto ring = [](glm::dvec2 centre, double r, bool clockwise) {
    std::vector<glm::dvec2> pts;
    for (int i = 0; i < 23; ++i) {
      const double a = 2 * M_PI * i / 23 * (clockwise ? -1 : 1);
      pts.push_back(centre + r * (1.0 + 0.04 * std::sin(5.0 * a)) * glm::dvec2{std::cos(a), std::sin(a)});
    }
    return pts;
  };
  std::vector<std::vector<glm::dvec2>> loops;
  for (int b = 0; b < 6; ++b) {
    const glm::dvec2 c{100.0 * (b % 3), 100.0 * (b / 3)};
    loops.push_back(ring(c, 40, false));
    loops.push_back(ring(c + glm::dvec2{-12, 0}, 20, true));
    loops.push_back(ring(c + glm::dvec2{-12, 0}, 8, false));
    loops.push_back(ring(c + glm::dvec2{22, 14}, 6, true));
  }
  Footprint fp = make_footprint(loops, 45.0);
  fp.profiles = {{"soffit", {{0, 0}, {0, 3}, {0.5, 3}, {-10, 13.5}}, {"wall", "soffit", "roof"}},
                 {"mansard", {{0, 0}, {0, 3}, {0.3, 3}, {-1, 6}, {-4, 7}}, {"wall", "soffit", "mansard", "roof"}},
                 {"deep eave", {{0, 0}, {0, 3}, {0.8, 3}, {-6, 9}}, {"wall", "soffit", "roof"}}};
  int k = 0;
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.profile = k++ % 3;
  return fp;
}

void BM_Figure25Analogue(benchmark::State& state) {
  const Footprint fp = figure25_analogue();
  for (auto _ : state) benchmark::DoNotOptimize(sweep(fp));
}
BENCHMARK(BM_Figure25Analogue)->Unit(benchmark::kMillisecond);

std::vector<Footprint> corpus_with_house_profile() {
  const Profile house{"house", {{0, 0}, {0, 3}, {0.4, 3}, {0.4, 3.2}, {-4.6, 8.2}}, {"wall", "soffit", "fascia", "roof"}};
  std::vector<Footprint> out;
  for (const auto& file : footprint_corpus_files())
    for (const GeoJsonFeature& f : read_geojson_file(file).features) {
      try {
        Footprint fp = prepare_footprint(to_footprint(f, 45.0)).footprint;
        fp.profiles = {house};
        for (Loop& loop : fp.loops)
          for (EdgeSpec& e : loop.edges) e.profile = 0;
        out.push_back(std::move(fp));
      } catch (const InputError&) {
        // the two OSM-flagged self-intersecting rings
      }
    }
  return out;
}

void BM_OsmCorpusHouseProfile(benchmark::State& state) {
  static const std::vector<Footprint> corpus = corpus_with_house_profile();
  std::size_t failed = 0;
  for (auto _ : state) {
    failed = 0;
    for (const Footprint& fp : corpus) {
      try {
        benchmark::DoNotOptimize(sweep(fp));
      } catch (const SweepError&) {
        ++failed;
      }
    }
  }
  state.counters["footprints"] = static_cast<double>(corpus.size());
  state.counters["failed"] = static_cast<double>(failed);
  state.counters["us_per_footprint"] = benchmark::Counter(
      static_cast<double>(corpus.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_OsmCorpusHouseProfile)->Unit(benchmark::kSecond)->Iterations(3);

}  // namespace
}  // namespace procex

BENCHMARK_MAIN();

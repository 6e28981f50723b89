// Profiles in the sweep (issue 3's benchmark, figures in BENCHMARKS.md,
// "Profiles"): the fig. 25 analogue (24 nested loops, 552 vertices, three
// profiles with eaves stepping out) and every OpenStreetMap footprint of
// ../shared/data/footprints under a four-segment house profile (wall, soffit,
// fascia, roof). Footprints are read and prepared before timing; one thread.
#include <vector>

#include <benchmark/benchmark.h>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/sweep/sweep.h"
#include "tests/support/figure25.h"
#include "tests/support/shared_data.h"

namespace procex {
namespace {

void BM_Figure25Analogue(benchmark::State& state) {
  const Footprint fp = testing::figure25_analogue();
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

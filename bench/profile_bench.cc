// Profiles in the sweep (issue 3's benchmark, figures in BENCHMARKS.md,
// "Profiles"): the fig. 25 analogue (24 nested loops, 552 vertices, three
// profiles with eaves stepping out) and every OpenStreetMap footprint of
// data/footprints under a four-segment house profile (wall, soffit,
// fascia, roof). Footprints are read and prepared before timing; one thread.
// A natural step on one edge (a bay out of the wall at 1 m, under a hip roof)
// changes a few corners of a big cross-section: the corpus with a bay on each
// footprint's longest edge, and a 4096-vertex star (2048 reflex corners).
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include <benchmark/benchmark.h>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/sweep/sweep.h"
#include "tests/support/figure25.h"
#include "tests/support/data_files.h"

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

const std::vector<Profile> kHipAndBay{{"hip", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}},
                                      {"bay", {{0, 0}, {0, 1.5}, {-2, 3.5}}, {"bay wall", "bay roof"}}};

struct WithBay {
  Footprint footprint;
  SweepOptions options;
};

// The footprint under a hip roof, with a bay grown at 1 m out of the middle
// of its outer loop's longest edge.
WithBay with_one_bay(Footprint fp) {
  fp.profiles = kHipAndBay;
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.profile = 0;
  const Loop& outer = fp.loops.front();
  const std::size_t n = outer.points.size();
  auto length = [&](std::size_t j) { return glm::length(outer.points[(j + 1) % n] - outer.points[j]); };
  std::size_t longest = 0;
  for (std::size_t j = 1; j < n; ++j)
    if (length(j) > length(longest)) longest = j;
  PlanEdit bay;
  bay.name = "bay";
  bay.at = {"bay", {PlanAnchor::Mode::Fraction, 0.5}, 1.0, 0, {outer.edges[longest].id}};
  bay.kind = PlanEdit::Kind::Natural;
  bay.width = 1.5;
  bay.depth = 0.6;
  bay.edges.assign(3, EdgeSpec{0.0, 1000000, 1});
  WithBay out{std::move(fp), {}};
  out.options.plan_edits = {bay};
  return out;
}

// Sweeps every case per iteration; counts the bays grown.
void sweep_with_bays(benchmark::State& state, const std::vector<WithBay>& cases) {
  std::size_t failed = 0, bays = 0;
  for (auto _ : state) {
    failed = bays = 0;
    for (const WithBay& c : cases) {
      try {
        const Surface s = sweep(c.footprint, c.options);
        for (const ResolvedAnchor& r : s.plan_edits) bays += r.present;
      } catch (const SweepError&) {
        ++failed;
      }
    }
  }
  state.counters["footprints"] = static_cast<double>(cases.size());
  state.counters["bays"] = static_cast<double>(bays);
  state.counters["failed"] = static_cast<double>(failed);
}

void BM_OsmCorpusOneBay(benchmark::State& state) {
  static const std::vector<WithBay> cases = [] {
    std::vector<WithBay> out;
    for (const Footprint& fp : corpus_with_house_profile()) out.push_back(with_one_bay(fp));
    return out;
  }();
  sweep_with_bays(state, cases);
}
BENCHMARK(BM_OsmCorpusOneBay)->Unit(benchmark::kSecond)->Iterations(3);

// 4096 vertices alternating between radii near 100 m and near 90 m (jittered:
// a symmetric star makes every collision happen at once).
void BM_Star4096OneBay(benchmark::State& state) {
  static const std::vector<WithBay> cases = [] {
    Loop star;
    constexpr int kPoints = 4096;
    std::mt19937 random(1);
    std::uniform_real_distribution<double> jitter(-2.0, 2.0);
    for (int i = 0; i < kPoints; ++i) {
      const double a = 2.0 * M_PI * i / kPoints, r = (i % 2 == 0 ? 100.0 : 90.0) + jitter(random);
      star.points.emplace_back(r * std::cos(a), r * std::sin(a));
      star.edges.push_back(EdgeSpec{45.0, i, 0});
    }
    Footprint fp;
    fp.loops = {star};
    return std::vector<WithBay>{with_one_bay(std::move(fp))};
  }();
  sweep_with_bays(state, cases);
}
BENCHMARK(BM_Star4096OneBay)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace procex

BENCHMARK_MAIN();

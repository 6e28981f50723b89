// Mixed horizontal steps over the OpenStreetMap corpus: at one height each
// edge of a footprint, drawn independently (seeded by the footprint's index),
// steps out (a soffit), steps in (a ledge) or does not step at all, then every
// edge carries on as a roof. This is what a profile offset with edges dropped
// out of it (or given their own distance) asks of the engine (paper 3.3,
// fig. 5): neighbours stepping different ways at one height, where the
// flattened nested sweep of horizontal_event.cc must not fold a face onto
// itself. Every output must validate, and every face lie on a plane of its
// edge's profile (or be a jog across its line: tests/support/roof_properties.h).
//
// Three mixes: out or none, in or none (what dropping edges out of one offset
// makes), and all three, where a neighbour stepping out and the next stepping
// in fold a soffit over a ledge until the flattened faces are overlaid.
#include <cstdint>
#include <iostream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "tests/support/roof_properties.h"
#include "tests/support/sanitizers.h"
#include "tests/support/validation_text.h"
#include "tests/support/data_files.h"

namespace procex {
namespace {

// Under the sanitizers every kSanitizedStride-th footprint runs (the check is
// per footprint, so a subset still covers every kind of mix).
constexpr std::size_t kSanitizedStride = 6;

// Walls to 3 m, then out by 0.6 m, in by 0.5 m or no step, then a roof
// rising 1:1. The roofs above stay parallel to the step, so a step changes
// only where each roof starts.
std::vector<Profile> step_profiles() {
  return {
      {"out", {{0, 0}, {0, 3}, {0.6, 3}, {-4.4, 8}}, {"wall", "soffit", "roof"}},
      {"in", {{0, 0}, {0, 3}, {-0.5, 3}, {-5.5, 8}}, {"wall", "ledge", "roof"}},
      {"none", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}},
  };
}

// Empty when the footprint sweeps to a valid mesh (or OSM flags it invalid
// and prepare_footprint refuses it), else what went wrong.
enum class Mix { OutOrNone, InOrNone, All };

std::string sweep_mixed(const GeoJsonFeature& f, Mix mix) {
  PreparedFootprint prepared;
  try {
    prepared = prepare_footprint(to_footprint(f, 45.0));
  } catch (const InputError& e) {
    return f.property_text("valid") == "false" ? std::string() : std::string("refused: ") + e.what();
  }
  Footprint& fp = prepared.footprint;
  fp.profiles = step_profiles();
  // mt19937's raw output is fully specified by the standard: the same mix on every platform.
  std::mt19937 rng(static_cast<std::uint32_t>(f.index) * 2246822519u + 5u);
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) {
      e.profile = static_cast<int>(rng() % 3u);
      if ((mix == Mix::OutOrNone && e.profile == 1) || (mix == Mix::InOrNone && e.profile == 0)) e.profile = 2;
    }
  try {
    const Surface roof = sweep(fp);
    const ValidationReport v = validate(build_mesh(roof));
    if (!v.ok()) return describe(v);
    std::string off;
    for (const std::string& line : testing::check_faces_on_planes(fp, {}, roof, testing::roof_tolerance(fp)))
      off += (off.empty() ? "" : "; ") + line;
    return off;
  } catch (const SweepError& e) {
    return std::string("SweepError: ") + e.what();
  } catch (const MeshError& e) {
    return std::string("MeshError: ") + e.what();
  }
}

void sweep_corpus(const std::filesystem::path& file, Mix mix) {
  const GeoJsonCollection corpus = read_geojson_file(file);
  ASSERT_TRUE(corpus.errors.empty()) << corpus.errors.front().message;
  ASSERT_GT(corpus.features.size(), 1000u);
  std::size_t run = 0, failed = 0;
  for (const GeoJsonFeature& f : corpus.features) {
    if (kSanitized && f.index % kSanitizedStride != 0) continue;
    ++run;
    const std::string problem = sweep_mixed(f, mix);
    if (problem.empty()) continue;
    ++failed;
    ADD_FAILURE() << f.id << " (feature " << f.index << "): " << problem;
  }
  std::cout << file.filename().string() << ": " << run << " footprints with mixed steps, " << failed << " failed\n";
}

class SweepMixedSteps : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(SweepMixedSteps, OutOrNone) { sweep_corpus(GetParam(), Mix::OutOrNone); }
TEST_P(SweepMixedSteps, InOrNone) { sweep_corpus(GetParam(), Mix::InOrNone); }
TEST_P(SweepMixedSteps, OutInOrNone) { sweep_corpus(GetParam(), Mix::All); }

INSTANTIATE_TEST_SUITE_P(Osm, SweepMixedSteps, ::testing::ValuesIn(footprint_corpus_files()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace procex

// Plan edits on every real footprint of data/footprints/: under a hip
// roof, a natural bay grows out of the middle of every edge at 1 m, a dormer
// out of every eave at 3 m and a forced recess is cut into every wall at the
// footprint. Edits that do not fit an edge are absent (with a reason); every
// mesh must validate (closed, 2-manifold, oriented, planar, no
// self-intersection): natural steps are grown by a nested sweep and stay
// simple where they run into each other or into the walls round them.
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "core/io/geojson.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "tests/support/sanitizers.h"
#include "tests/support/data_files.h"

namespace procex {
namespace {

// Under the sanitizers every kSanitizedStride-th footprint is swept.
constexpr std::size_t kSanitizedStride = 16;

const std::vector<Profile> kProfiles{
    {"hip", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}},
    {"bay", {{0, 0}, {0, 1.5}, {-2, 3.5}}, {"bay wall", "bay roof"}},
    {"dormer", {{0, 0}, {0, 1.2}, {-3, 4.2}}, {"dormer wall", "dormer roof"}},
    {"recess", {{0, 0}, {0, 2.2}, {-3, 5.2}}, {"recess wall", "recess roof"}},
};

PlanEdit natural(const std::string& name, double height, double width, double depth, int profile) {
  PlanEdit e;
  e.name = name;
  e.at = {name, {PlanAnchor::Mode::Fraction, 0.5}, height, 0, {}};
  e.kind = PlanEdit::Kind::Natural;
  e.width = width;
  e.depth = depth;
  e.edges.assign(3, EdgeSpec{0.0, 1000000, profile});
  return e;
}

std::vector<PlanEdit> edits() {
  PlanEdit recess;
  recess.name = "recess";
  recess.at = {"recess", {PlanAnchor::Mode::FromStart, 1.0}, 0.0, 0, {}};
  recess.shape = {{0, 0}, {0, -0.5}, {0.8, -0.5}, {0.8, 0}};
  recess.edges.assign(3, EdgeSpec{0.0, 2000000, 3});
  return {natural("bay", 1.0, 1.5, 0.6, 1), natural("dormer", 3.0, 1.2, 0.3, 2), recess};
}

class PlanEditCorpus : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(PlanEditCorpus, EveryFootprintValidates) {
  const GeoJsonCollection corpus = read_geojson_file(GetParam());
  ASSERT_TRUE(corpus.errors.empty());
  std::size_t ok = 0, applied = 0, absent = 0, refused = 0;
  auto failed = [&](const GeoJsonFeature& f, const std::string& why) {
    ADD_FAILURE() << f.id << " (feature " << f.index << "): " << why;
  };
  for (const GeoJsonFeature& f : corpus.features) {
    if (kSanitized && f.index % kSanitizedStride != 0) continue;
    PreparedFootprint prepared;
    try {
      prepared = prepare_footprint(to_footprint(f, 45.0));
    } catch (const InputError&) {
      ++refused;  // OSM's own invalid rings: the corpus test checks these
      continue;
    }
    Footprint& fp = prepared.footprint;
    fp.profiles = kProfiles;
    for (Loop& loop : fp.loops)
      for (EdgeSpec& e : loop.edges) e.profile = 0;
    SweepOptions options;
    options.plan_edits = edits();
    try {
      const Surface s = sweep(fp, options);
      for (const ResolvedAnchor& r : s.plan_edits) (r.present ? applied : absent) += 1;
      const ValidationReport v = validate(build_mesh(s));
      if (v.ok()) {
        ++ok;
        continue;
      }
      failed(f, "does not validate: " + (v.problems.empty() ? std::string() : v.problems.front()));
    } catch (const std::exception& e) {
      failed(f, e.what());
    }
  }
  std::cout << GetParam().filename().string() << ": " << ok << " ok, " << refused << " refused; edits applied "
            << applied << ", absent " << absent << "\n";
  // Most footprints have edges long enough for several of the edits.
  EXPECT_GT(applied, 2 * ok);
}

INSTANTIATE_TEST_SUITE_P(Osm, PlanEditCorpus, ::testing::ValuesIn(footprint_corpus_files()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace procex

// procex batch sets its footprints aside on disk (core/io/feature_spool.h):
// what comes back is what the reader gives in memory, projected and labelled
// alike; the unreadable ones are refused in the same words; and the batch's
// peak memory does not grow with the number of footprints as it did when
// every one was held as read.
#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli/feature_binding.h"
#include "app/cli/recipe_session.h"
#include "core/io/feature_spool.h"
#include "tests/app/child_peak_memory.h"
#include "tests/app/command_test.h"
#include "tests/app/generated_footprints.h"
#include "tests/app/sample_block.h"
#include "tests/support/sanitizers.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = PROCEX_SAMPLES;
const fs::path kData = PROCEX_TEST_DATA;

class BatchFootprintSpool : public test::CommandTest {
 protected:
  // The footprints as open_footprints gives them in memory and as it spools them.
  void expect_spooled_as_in_memory(const fs::path& recipe_file, const fs::path& footprints,
                                   const FootprintReadOptions& read) {
    const std::optional<Graph> recipe = load_recipe(recipe_file, {}, err_);
    ASSERT_TRUE(recipe) << err_.str();
    const std::optional<GeoJsonCollection> memory = open_footprints(*recipe, recipe_file, footprints, read, "batch", err_);
    ASSERT_TRUE(memory) << err_.str();
    FeatureSpool spool(dir_.string());
    const std::optional<GeoJsonCollection> spooled =
        open_footprints(*recipe, recipe_file, footprints, read, "batch", err_, &spool);
    ASSERT_TRUE(spooled) << err_.str();
    EXPECT_TRUE(spooled->features.empty());
    EXPECT_EQ(spooled->crs, memory->crs);
    EXPECT_EQ(spooled->lines, memory->lines);
    EXPECT_EQ(spooled->members, memory->members);
    ASSERT_EQ(spooled->errors.size(), memory->errors.size());
    for (std::size_t i = 0; i < memory->errors.size(); ++i) {
      EXPECT_EQ(spooled->errors[i].index, memory->errors[i].index);
      EXPECT_EQ(spooled->errors[i].message, memory->errors[i].message);
    }
    ASSERT_EQ(spool.size(), memory->features.size());
    for (std::size_t i = 0; i < spool.size(); ++i) {
      const GeoJsonFeature& want = memory->features[i];
      const GeoJsonFeature got = spool.at(i);
      SCOPED_TRACE(want.id);
      EXPECT_EQ(got.index, want.index);
      EXPECT_EQ(got.id, want.id);
      EXPECT_EQ(got.loops, want.loops);  // exactly: the same projection, once
      EXPECT_EQ(got.polygon_of_loop, want.polygon_of_loop);
      EXPECT_EQ(got.properties, want.properties);  // party_edges and street_edges included
      EXPECT_EQ(got.edge_angles, want.edge_angles);
    }
  }
};

TEST_F(BatchFootprintSpool, PartyAndStreetEdgesAsInMemory) {
  FootprintReadOptions read;
  read.streets = kSamples / "footprints" / "terrace_east_street.geojson";
  expect_spooled_as_in_memory(kSamples / "city.pxg", kSamples / "footprints" / "terrace.geojson", read);
  expect_spooled_as_in_memory(kSamples / "city.pxg", test::kSampleBlock, {});
}

// A projection rewrites every spooled footprint (FeatureSpool::keep_if).
TEST_F(BatchFootprintSpool, ProjectedAsInMemory) {
  FootprintReadOptions read;
  read.crs = "EPSG:32632", read.target_crs = "EPSG:3857";
  expect_spooled_as_in_memory(kSamples / "city.pxg", test::kSampleBlock, read);
  expect_spooled_as_in_memory(kSamples / "city.pxg", fs::path(PROCEX_DATA) / "footprints" / "corpus_monaco.geojson", {});
}

TEST_F(BatchFootprintSpool, UnreadableFeaturesRefusedAsInMemory) {
  expect_spooled_as_in_memory(kSamples / "city.pxg", kData / "geojson_bad_features.geojson", {});
}

// Peak RSS in KiB of `procex batch` over `footprints`, a thousandth of them
// built (--shard 0/1000): every footprint read, labelled and set aside.
long batch_peak_kib(const fs::path& footprints, const fs::path& output) {
  return test::procex_peak_kib({"batch", (kSamples / "city.pxg").string(), "--footprints", footprints.string(), "-o",
                                output.string(), "--shard", "0/1000", "--jobs", "1", "--no-progress"});
}

// 250,000 footprints held as read took about 550 bytes each (the records,
// their property maps with the party edges, their rings): some 120 MB more
// than 25,000. Spooled, what stays per footprint is its place in the spool
// and the batch's source record (under 100 bytes), and the tiles' boxes
// while labelling.
TEST_F(BatchFootprintSpool, PeakMemoryDoesNotFollowTheFootprints) {
  if (kSanitized) GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine are not the program's";
  const fs::path few = dir_ / "few.geojson", many = dir_ / "many.geojson";
  test::write_footprints(few, 25000);
  test::write_footprints(many, 250000);
  const long few_kib = batch_peak_kib(few, dir_ / "few.glb");
  const long many_kib = batch_peak_kib(many, dir_ / "many.glb");
  const double growth_mb = static_cast<double>(many_kib - few_kib) / 1024;
  EXPECT_LT(growth_mb, 40) << "peak " << few_kib / 1024 << " MB at 25,000 footprints, " << many_kib / 1024
                           << " MB at 250,000";
  // The spool went with the batch: nothing is left beside the outputs.
  std::vector<std::string> left;
  for (const fs::directory_entry& e : fs::directory_iterator(dir_)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"few.geojson", "few.glb", "many.geojson", "many.glb"}));
}

}  // namespace
}  // namespace procex

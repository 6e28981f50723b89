// feature_sources: a batch's footprints, readable (in the spool) and not (an
// error), come out by their index in the file, each pointing at its own
// record, and a shard takes the indices i with i % shards == shard.
#include "core/io/feature_sources.h"

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace procex {
namespace {

std::string id_of(std::size_t index) {
  std::string id = "f";  // not "f" + ...: GCC 12's -Wrestrict false positive
  id += std::to_string(index);
  return id;
}

// Readable footprints at indices 0, 2, 3, 6 (spooled in that order) and
// unreadable ones at 5 and 1 (errors in the order a reader met them).
class FeatureSources : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const std::size_t index : {0, 2, 3, 6}) {
      GeoJsonFeature f;
      f.index = index, f.id = id_of(index);
      f.loops = {{{0, 0}, {1, 0}, {1, 1}}};
      f.polygon_of_loop = {0};
      spool_.add(f);
    }
    errors_ = {{5, "e5", "/features/5", "bad 5"}, {1, "e1", "/features/1", "bad 1"}};
  }
  FeatureSpool spool_{std::filesystem::temp_directory_path().string()};
  std::vector<GeoJsonFeatureError> errors_;
};

std::vector<std::size_t> indices(const std::vector<FeatureSource>& sources) {
  std::vector<std::size_t> out;
  for (const FeatureSource& s : sources) out.push_back(s.index);
  return out;
}

TEST_F(FeatureSources, AllOfThemInInputOrderEachPointingAtItsRecord) {
  const std::vector<FeatureSource> sources = feature_sources(spool_, errors_);
  EXPECT_EQ(indices(sources), (std::vector<std::size_t>{0, 1, 2, 3, 5, 6}));
  for (const FeatureSource& s : sources) {
    if (s.error) {
      EXPECT_EQ(s.error->index, s.index);
      EXPECT_GE(s.error, errors_.data());
      EXPECT_LT(s.error, errors_.data() + errors_.size());
    } else {
      EXPECT_EQ(spool_.index(s.spooled), s.index);
      EXPECT_EQ(spool_.at(s.spooled).id, id_of(s.index));
    }
  }
}

TEST_F(FeatureSources, AShardTakesTheIndicesItIsDealt) {
  EXPECT_EQ(indices(feature_sources(spool_, errors_, 0, 2)), (std::vector<std::size_t>{0, 2, 6}));
  EXPECT_EQ(indices(feature_sources(spool_, errors_, 1, 2)), (std::vector<std::size_t>{1, 3, 5}));
  EXPECT_EQ(indices(feature_sources(spool_, errors_, 2, 3)), (std::vector<std::size_t>{2, 5}));
}

TEST_F(FeatureSources, NoneGivenNoneTaken) {
  const FeatureSpool empty(std::filesystem::temp_directory_path().string());
  EXPECT_TRUE(feature_sources(empty, {}).empty());
}

}  // namespace
}  // namespace procex

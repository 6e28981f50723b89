// A batch into one .glb that the file cannot hold (glTF's 4 GiB; here a
// smaller limit set through BatchCommandOptions::glb_max_bytes, the one the
// writer enforces) is refused before its buildings are made, judged from a
// sample of them made ahead (app/cli/glb_size_estimate.h); one the sample
// lets through and that does not fit after all is refused by the writer when
// it passes the limit. Either way nothing is written and the message says how
// to split the batch.
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli/batch_command.h"
#include "app/cli/glb_size_estimate.h"
#include "app/cli/recipe_session.h"
#include "tests/app/command_test.h"
#include "tests/app/generated_footprints.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = PROCEX_SAMPLES;

class BatchGlbLimit : public test::CommandTest {
 protected:
  BatchCommandOptions options(std::size_t buildings, const std::string& output) {
    const fs::path footprints = dir_ / ("footprints" + std::to_string(buildings) + ".geojson");
    if (!fs::exists(footprints)) test::write_footprints(footprints, buildings);
    BatchCommandOptions o;
    o.recipe = kSamples / "city.pxg";
    o.footprints = footprints;
    o.output = dir_ / output;
    o.report = dir_ / (output + ".json");
    o.jobs = 2;
    o.progress = false;
    return o;
  }
  // The bytes of the batch's .glb with nothing in the way.
  std::uintmax_t glb_bytes(std::size_t buildings) {
    const BatchCommandOptions o = options(buildings, "whole" + std::to_string(buildings) + ".glb");
    EXPECT_EQ(run_batch(o, out_, err_), 0) << err_.str();
    return fs::file_size(o.output);
  }
};

TEST_F(BatchGlbLimit, ABatchTheFileCannotHoldIsRefusedBeforeItsBuildingsAreMade) {
  const std::uintmax_t bytes = glb_bytes(2000);
  // Allowed what it takes: the sample lets it through, and the file is the one written without a limit.
  BatchCommandOptions fits = options(2000, "fits.glb");
  fits.glb_max_bytes = bytes;
  ASSERT_EQ(run_batch(fits, out_, err_), 0) << err_.str();
  EXPECT_TRUE(test::read_text(fits.output) == test::read_text(dir_ / "whole2000.glb"));

  // Allowed half: refused before the batch starts. Progress is asked for and none is shown.
  BatchCommandOptions half = options(2000, "half.glb");
  half.glb_max_bytes = bytes / 2, half.progress = true;
  err_.str("");
  EXPECT_EQ(run_batch(half, out_, err_), kExitUnusableInput);
  const std::string message = err_.str();
  EXPECT_NE(message.find("procex batch: refused: " + half.output.string() + ": its 2000 buildings would make about"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("judged from 256 of them made ahead"), std::string::npos) << message;
  EXPECT_NE(message.find("more than the " + std::to_string(bytes / 2) + " bytes allowed; nothing made"),
            std::string::npos)
      << message;
  // About twice the limit: three shards, each at most 90 % full.
  EXPECT_NE(message.find("--shard i/N, N at least 3"), std::string::npos) << message;
  EXPECT_EQ(message.find("/2000"), std::string::npos) << "buildings were made: " << message;
  EXPECT_FALSE(fs::exists(half.output));
  EXPECT_FALSE(fs::exists(half.report));
}

// Too few buildings for a sample to save anything: the writer stops the batch
// at the group of buildings that passes the limit.
TEST_F(BatchGlbLimit, ASmallBatchIsRefusedWhenItsFilePassesTheLimit) {
  const std::uintmax_t bytes = glb_bytes(1000);
  BatchCommandOptions half = options(1000, "half.glb");
  half.glb_max_bytes = bytes / 2;
  err_.str("");
  EXPECT_EQ(run_batch(half, out_, err_), kExitUnusableInput);
  const std::string message = err_.str();
  EXPECT_NE(message.find("procex batch: refused: cannot write '" + half.output.string() + "': "), std::string::npos)
      << message;
  EXPECT_NE(message.find("more than the " + std::to_string(bytes / 2) + " bytes allowed with "), std::string::npos)
      << message;
  EXPECT_NE(message.find(" of its 1000 buildings made; nothing written"), std::string::npos) << message;
  EXPECT_NE(message.find("--shard i/N, N at least 3"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(half.output));
  EXPECT_FALSE(fs::exists(half.report));
}

// The sample is spread over the batch: an input whose second half is of
// buildings thirty times the first's is judged whole, not by its start.
TEST(GlbSizeEstimate, JudgesTheWholeBatchNotItsStart) {
  const std::size_t n = 100000;
  std::vector<std::uint64_t> sampled;
  for (const std::size_t at : glb_size_sample(n)) sampled.push_back(at < n / 2 ? 1000 : 30000);
  ASSERT_EQ(sampled.size(), kGlbSizeSample);
  const GlbSizeEstimate e = estimate_glb_size(sampled, n);
  EXPECT_NEAR(e.total, 15500.0 * n, 0.01 * 15500.0 * n);
  EXPECT_LT(e.at_least, e.total);
  EXPECT_GT(e.at_least, 0.8 * e.total);
  EXPECT_TRUE(glb_size_sample(4 * kGlbSizeSample - 1).empty());
}

}  // namespace
}  // namespace procex

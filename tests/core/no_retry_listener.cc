// Every hand-made case in this binary must sweep at the first clustering
// scale: a test during which a sweep closed only after a retry fails. The
// data-driven suites over the corpora and the generated classes are left out;
// they count their retries and TESTING.md records the distribution.
#include <cstdint>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/sweep/sweep.h"

namespace procex {
namespace {

class NoRetryListener : public ::testing::EmptyTestEventListener {
  void OnTestStart(const ::testing::TestInfo&) override { before_ = sweeps_retried(); }
  void OnTestEnd(const ::testing::TestInfo& info) override {
    const std::uint64_t retried = sweeps_retried() - before_;
    if (retried == 0) return;
    std::string suite = info.test_suite_name();
    suite = suite.substr(suite.find('/') + 1);  // a parameterised suite's instantiation prefix
    if (kCorpusSuites.contains(suite)) return;
    ADD_FAILURE() << retried << " sweep(s) in " << info.test_suite_name() << "." << info.name()
                  << " closed only after a retry at another clustering scale (Surface::retries)";
  }
  // And SweepRetries, whose subject is the retry, and HeightField, which
  // moves vertices of the grid class's roofs.
  inline static const std::set<std::string> kCorpusSuites = {
      "SweepCorpus",    "SweepMixedSteps", "PlanEditCorpus", "SweepOracleSynthetic",
      "SweepOracleOsm", "GeneratedGrid",   "SweepRetries",   "HeightField"};
  std::uint64_t before_ = 0;
};

const bool registered = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new NoRetryListener);
  return true;
}();

}  // namespace
}  // namespace procex

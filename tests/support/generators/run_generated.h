// Runs a part of a generated class's budget inside a GoogleTest test: every
// failing case is minimised (shrink.h) and reported with its fixture; with
// PROCEX_FINDINGS_DIR set, the fixture is also written there as
// <class>_<seed>.geojson. PROCEX_SOAK=1 selects the soak budget, PROCEX_SEEDS
// given seeds; under the sanitizers (Debug, 20-100x slower) a fiftieth of the
// normal budget runs.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/support/generators/check_case.h"
#include "tests/support/generators/shrink.h"
#include "tests/support/sanitizers.h"

namespace procex::testing {

struct Budget {
  std::size_t normal = 0;       // cases in the normal suite
  std::size_t soak = 0;         // cases with PROCEX_SOAK=1
  std::size_t shrink_tries = 0;  // candidates tried while minimising one failure
};

inline bool soak_run() {
  const char* s = std::getenv("PROCEX_SOAK");
  return s != nullptr && std::string(s) == "1";
}

// The seeds `text` names ("834" or "800-899", both ends in) as [first, end);
// anything else is refused naming `source`, where the text came from.
inline std::pair<std::size_t, std::size_t> seed_range(const std::string& text, const std::string& source) {
  auto number = [&](std::size_t from, std::size_t to) {
    std::size_t value = 0;
    const auto [end, error] = std::from_chars(text.data() + from, text.data() + to, value);
    if (from == to || error != std::errc() || end != text.data() + to)
      throw std::invalid_argument(source + "='" + text + "': expected a seed (834) or a range of seeds (800-899)");
    return value;
  };
  const std::size_t dash = text.find('-');
  const std::size_t first = number(0, std::min(dash, text.size()));
  const std::size_t last = dash == std::string::npos ? first : number(dash + 1, text.size());
  if (last < first) throw std::invalid_argument(source + "='" + text + "': the range ends before it starts");
  return std::pair(first, last + 1);
}

// The seeds PROCEX_SEEDS names, to rerun a reported failure; nullopt when unset.
inline std::optional<std::pair<std::size_t, std::size_t>> seeds_asked() {
  const char* s = std::getenv("PROCEX_SEEDS");
  if (s == nullptr || *s == 0) return std::nullopt;
  return seed_range(s, "PROCEX_SEEDS");
}

inline void run_generated(CaseClass cls, std::size_t part, std::size_t parts, const Budget& budget) {
  constexpr std::size_t kSanitizedShare = kSanitized ? 50 : 1;
  std::size_t begin, end;
  if (const auto asked = seeds_asked()) {
    if (part != 0) return;  // the first part runs the seeds asked for
    std::tie(begin, end) = *asked;
  } else {
    const std::size_t total = soak_run() ? budget.soak : std::max<std::size_t>(parts, budget.normal / kSanitizedShare);
    begin = total * part / parts;
    end = total * (part + 1) / parts;
  }
  std::size_t failed = 0;
  const std::uint64_t retried_before = sweeps_retried();
  for (std::size_t seed = begin; seed < end; ++seed) {
    const GeneratedCase c = generate_case(cls, seed);
    const CaseResult r = check_case(c);
    if (!r.failed()) continue;
    ++failed;
    std::string lines;
    for (std::size_t i = 0; i < r.problems.size() && i < 6; ++i) lines += "\n  " + r.problems[i];
    if (r.refused) lines += "\n  refused by prepare_footprint";
    // Said before minimising, whose candidates of a large case take minutes each: a
    // failure is seen (and its unminimised fixture kept) even if the run is stopped there.
    std::size_t vertices = 0;
    for (const Loop& loop : c.footprint.loops) vertices += loop.points.size();
    std::cout << "FAILED " << c.description << " (rerun: PROCEX_SEEDS=" << seed << "), " << vertices << " vertices in "
              << c.footprint.loops.size() << " loops:" << lines << "\nminimising (at most " << (r.refused ? 0 : budget.shrink_tries)
              << " candidates)" << std::endl;
    const auto first_problem = [](const CaseResult& result) {
      return result.problems.empty() ? std::string("refused by prepare_footprint") : result.problems.front();
    };
    const char* dir = std::getenv("PROCEX_FINDINGS_DIR");
    const std::string findings = dir ? std::string(dir) + "/" + class_name(cls) + "_" + std::to_string(seed) + ".geojson" : "";
    if (!findings.empty()) std::ofstream(findings) << fixture_geojson(c, first_problem(r));
    // The result of the last candidate that still failed is the minimised case's.
    CaseResult small_result = r;
    const GeneratedCase small = shrink(
        c,
        [&small_result](const GeneratedCase& candidate) {
          CaseResult result = check_case(candidate);
          if (result.refused || !result.failed()) return false;
          small_result = std::move(result);
          return true;
        },
        r.refused ? 0 : budget.shrink_tries);
    const std::string problem = first_problem(small_result);
    const std::string fixture = fixture_geojson(small, problem);
    ADD_FAILURE() << c.description << " (rerun: PROCEX_SEEDS=" << seed << ")" << lines << "\nminimised (" << small.description << "): " << problem << "\n" << fixture;
    if (!findings.empty()) std::ofstream(findings) << fixture;
  }
  std::cout << "class " << class_name(cls) << " seeds " << begin << ".." << end - 1 << ": " << end - begin
            << " cases, " << failed << " failed, " << sweeps_retried() - retried_before
            << " sweeps closed after a retry at another clustering scale\n";
}

}  // namespace procex::testing

// Registers class `cls` as the suite `Suite` of `parts` tests,
// Parts/Suite.EveryCasePassesEveryProperty/0 to parts - 1, each running its
// share of the budget (run_generated), so that ctest spreads a class over the
// cores. The budget is the last argument, a Budget's designated initialisers.
#define PROCEX_GENERATED_CLASS(Suite, cls, parts, ...)                                               \
  class Suite : public ::testing::TestWithParam<std::size_t> {};                                     \
  TEST_P(Suite, EveryCasePassesEveryProperty) {                                                      \
    ::procex::testing::run_generated(cls, GetParam(), parts, ::procex::testing::Budget __VA_ARGS__); \
  }                                                                                                  \
  INSTANTIATE_TEST_SUITE_P(Parts, Suite, ::testing::Range<std::size_t>(0, parts))

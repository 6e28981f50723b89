// What one batch of the sweep holds (issue 18): a square with k x k square
// holes puts O(n^1.5) split candidates in one batch (every hole's corner meets,
// at one height, the planes of the k edges along each of its walls' lines),
// few of them by a span. Those that do not wait for their own height; their
// collisions used to be made for all of them at once, which was most of such
// a sweep's memory (16,388 vertices: 592 MB, 189 MB without them).
#include <unistd.h>

#include <vector>

#include <gtest/gtest.h>

#include "core/geom/footprint.h"
#include "core/geom/prepare.h"
#include "core/sweep/sweep.h"
#include "tests/core/sweep_states.h"
#include "tests/support/child_peak_memory.h"
#include "tests/support/sanitizers.h"

namespace procex {
namespace {

// Every edge at 45 degrees.
Footprint square_with_holes(int k) { return prepare_footprint(make_footprint(engine::holes_plan(k), 45.0)).footprint; }

// Peak resident set, in KiB, of a child that sweeps `fp`: it starts from this
// process's pages, so only differences between two children mean anything.
long swept_peak_kib(const Footprint& fp) {
  const pid_t pid = fork();
  if (pid == 0) {
    const Surface s = sweep(fp);
    _exit(s.vertices.empty() ? 1 : 0);
  }
  return test::child_peak_kib(pid);
}

TEST(SweepBatchMemory, WaitingSplitsCostMemoryOnlyWhenTheyMeet) {
  // AddressSanitizer's redzones and quarantine are most of a process's memory there.
  if (kSanitized) GTEST_SKIP() << "resident memory is AddressSanitizer's";
  const Footprint small = square_with_holes(8), large = square_with_holes(32);
  const long small_kib = swept_peak_kib(small), large_kib = swept_peak_kib(large);
  // 4,100 vertices against 260: 72 MB more when every waiting split's
  // collision was made at once, 24 MB more now.
  EXPECT_LT(large_kib - small_kib, 40 * 1024) << small_kib << " KiB at 260 vertices, " << large_kib << " at 4,100";
}

}  // namespace
}  // namespace procex

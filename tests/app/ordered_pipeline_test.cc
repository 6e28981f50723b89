// OrderedPipeline: items come out in the order they were made, each once;
// the workers keep going past a slow item (as far as the bound lets them:
// no further); what is made and not yet taken stays within the bound however
// slowly the consumer takes; an exception stops it and reaches the consumer
// after a prefix of the items; close() stops it early. run_in_order, under it.
#include "app/cli/ordered_pipeline.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

namespace procex {
namespace {

using namespace std::chrono_literals;

struct Item {
  std::size_t index = 0;
  bool worked = false;
};

using Pipeline = OrderedPipeline<Item>;

Item make(std::size_t i) { return Item{i, false}; }

// Every item the consumer gets, in order, until the end (rethrowing).
std::vector<Item> take_all(Pipeline& p) {
  std::vector<Item> out;
  Item item;
  for (Pipeline::Next n; (n = p.next(item, 100ms)) != Pipeline::Next::kEnd;)
    if (n == Pipeline::Next::kItem) out.push_back(item);
  return out;
}

class OrderedPipelineTest : public ::testing::Test {
 protected:
  // Two threads in the arena even on a machine with one core: the tests
  // below need a second thread working while the first waits.
  tbb::global_control threads_{tbb::global_control::max_allowed_parallelism, 2};
  tbb::task_arena arena_{2};
};

// Items that take unequal times (a few microseconds to a millisecond, in a
// fixed pattern) still come out in the order they were made.
TEST_F(OrderedPipelineTest, YieldsEveryItemOnceInOrder) {
  Pipeline p(500, 4, arena_, make, [](Item& item) {
    std::this_thread::sleep_for(std::chrono::microseconds((item.index * 7919) % 1000));
    item.worked = true;
  }, "ordered-test");
  const std::vector<Item> got = take_all(p);
  ASSERT_EQ(got.size(), 500u);
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].index, i);
    EXPECT_TRUE(got[i].worked) << i;
  }
}

// Item 5 does not finish until later items have: with windows of 8 that each
// wait for their slowest (items 0-7, then 8-15), items 8-12 would never start
// and item 5 would wait for ever (the guard below fails the test instead).
// With 8 allowed ahead, exactly the 7 after it finish while it waits: the
// workers go on past a slow item, and no further than the bound.
TEST_F(OrderedPipelineTest, ASlowItemDoesNotStallTheOthers) {
  constexpr std::size_t kAhead = 8, kSlow = 5;
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t later_done = 0;  // items after kSlow that have been worked on
  std::size_t later_done_while_slow = 0;
  bool waited_in_vain = false;
  Pipeline p(100, kAhead, arena_, make, [&](Item& item) {
    std::unique_lock lock(mutex);
    if (item.index == kSlow) {
      // A guard against a hang, not a measurement: nothing is asserted of time.
      waited_in_vain = !changed.wait_for(lock, 60s, [&] { return later_done >= kAhead - 1; });
      later_done_while_slow = later_done;
    } else if (item.index > kSlow) {
      ++later_done;
      changed.notify_all();
    }
    item.worked = true;
  }, "ordered-test");
  const std::vector<Item> got = take_all(p);
  EXPECT_FALSE(waited_in_vain) << "the items after a slow one were not worked on while it was";
  EXPECT_EQ(later_done_while_slow, kAhead - 1);
  ASSERT_EQ(got.size(), 100u);
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].index, i);
}

// What has been made and not taken is never more than the bound's two parts
// (`ahead` in the pipeline, `ahead` ready) and the consumer's own, and
// reaches it when the consumer stops taking for a while.
TEST_F(OrderedPipelineTest, WhatIsMadeAndNotTakenIsBounded) {
  constexpr std::size_t kAhead = 3;
  std::atomic<std::size_t> taken{0}, most_waiting{0};
  Pipeline p(200, kAhead, arena_, [&](std::size_t i) {
    const std::size_t waiting = i + 1 - taken;  // this one and those made before it, not taken
    for (std::size_t m = most_waiting; waiting > m && !most_waiting.compare_exchange_weak(m, waiting);) {
    }
    return make(i);
  }, [](Item& item) { item.worked = true; }, "ordered-test");
  // Nothing taken until the workers hold all they may (a guard against a
  // hang, not a measurement), then every item, pausing every 50.
  const auto give_up = std::chrono::steady_clock::now() + 60s;
  while (most_waiting < 2 * kAhead && std::chrono::steady_clock::now() < give_up) std::this_thread::sleep_for(1ms);
  Item item;
  for (Pipeline::Next n; (n = p.next(item, 100ms)) != Pipeline::Next::kEnd;) {
    if (n != Pipeline::Next::kItem) continue;
    ASSERT_EQ(item.index, taken.load());
    if (++taken % 50 == 0) std::this_thread::sleep_for(5ms);
  }
  EXPECT_EQ(taken, 200u);
  // One more than the two parts: the item next() has just handed over, not
  // yet counted in `taken` when the pipeline may make another in its place.
  EXPECT_LE(most_waiting, 2 * kAhead + 1);
  EXPECT_GE(most_waiting, 2 * kAhead);
}

// An exception in make() or work() ends the items: a prefix of them comes
// out in order, then the exception; and the end after that.
TEST_F(OrderedPipelineTest, AnExceptionReachesTheConsumerAfterAPrefix) {
  for (const bool in_make : {true, false}) {
    Pipeline p(100, 4, arena_, [&](std::size_t i) {
      if (in_make && i == 30) throw std::runtime_error("cannot make 30");
      return make(i);
    }, [&](Item& item) {
      if (!in_make && item.index == 30) throw std::runtime_error("cannot work on 30");
    }, "ordered-test");
    std::vector<Item> got;
    Item item;
    try {
      for (Pipeline::Next n; (n = p.next(item, 100ms)) != Pipeline::Next::kEnd;)
        if (n == Pipeline::Next::kItem) got.push_back(item);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), in_make ? "cannot make 30" : "cannot work on 30");
    }
    EXPECT_LE(got.size(), 30u);
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].index, i);
    EXPECT_EQ(p.next(item, 0ms), Pipeline::Next::kEnd);
  }
}

// Closed part-way, with an item in work() until it sees stopping(): the
// thread is joined, nothing more comes out, nothing more is made.
TEST_F(OrderedPipelineTest, CloseStopsItEarly) {
  std::atomic<std::size_t> made{0};
  Pipeline p(1'000'000, 4, arena_, [&](std::size_t i) {
    ++made;
    return make(i);
  }, [&](Item& item) {
    if (item.index == 10)
      while (!p.stopping()) std::this_thread::sleep_for(1ms);
  }, "ordered-test");
  Item item;
  for (std::size_t taken = 0; taken < 3;) taken += p.next(item, 100ms) == Pipeline::Next::kItem;
  p.close();
  const std::size_t made_when_closed = made;
  EXPECT_LE(made_when_closed, 10u + 2 * 4);
  EXPECT_EQ(p.next(item, 0ms), Pipeline::Next::kEnd);
  EXPECT_EQ(made, made_when_closed);
}

// run_in_order, as procex batch runs it in its own arena: items finish in
// order; an exception from finish (a file that cannot be written) stops the
// items not yet made and reaches the caller, and the items in flight are
// freed (their vectors: LeakSanitizer sees any left behind).
TEST_F(OrderedPipelineTest, RunInOrderFinishesInOrderAndStopsAtAnException) {
  using Payload = std::vector<std::size_t>;
  std::atomic<std::size_t> made{0};
  std::vector<std::size_t> finished;
  arena_.execute([&] {
    EXPECT_THROW(run_in_order<Payload>(
                     1000, 4,
                     [&](std::size_t i) {
                       ++made;
                       return Payload(64, i);
                     },
                     [](Payload& p) { std::this_thread::sleep_for(std::chrono::microseconds((p[0] * 7919) % 300)); },
                     [&](Payload& p) {
                       if (p[0] == 100) throw std::runtime_error("cannot write 100");
                       finished.push_back(p[0]);
                     },
                     [] { return false; }),
                 std::runtime_error);
  });
  ASSERT_EQ(finished.size(), 100u);
  for (std::size_t i = 0; i < finished.size(); ++i) EXPECT_EQ(finished[i], i);
  EXPECT_LE(made, 101u + 4);
}

}  // namespace
}  // namespace procex

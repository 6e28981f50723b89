// ResolveOrder against the order it stands for: the groups sorted by first
// collision (then by index), and each group added during the batch inserted
// in place after every group still to come that is first met no higher.
#include "core/sweep/resolve_order.h"

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace procex::engine {
namespace {

// Heights drawn from few values, so that groups are often first met at one.
double height(std::mt19937_64& rng) { return static_cast<double>(rng() % 8) * 0.25; }

// The groups in the order they stand for: by first collision, then by index.
std::vector<std::size_t> by_first_then_index(const std::vector<double>& first) {
  std::vector<std::size_t> order(first.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return first[a] != first[b] ? first[a] < first[b] : a < b; });
  return order;
}

TEST(ResolveOrder, ResolvesGroupsAsInsertingEachInPlaceWould) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> first(1 + rng() % 40);
    for (double& f : first) f = height(rng);
    const auto first_of = [&](std::size_t g) { return first[g]; };
    std::vector<std::size_t> model = by_first_then_index(first);
    ResolveOrder order;
    order.start(first.size(), first_of);

    std::size_t i = 0;  // the model's next
    while (!order.empty()) {
      ASSERT_LT(i, model.size());
      // Now and then, what is still to come, as LaterGroups reads it.
      if (rng() % 4 == 0) {
        std::vector<std::size_t> pending;
        order.pending(pending);
        EXPECT_EQ(pending, std::vector<std::size_t>(model.begin() + static_cast<std::ptrdiff_t>(i), model.end()))
            << "seed " << seed;
      }
      EXPECT_EQ(order.next(), model[i]) << "seed " << seed << ", group " << i;
      ++i;
      for (std::size_t added = rng() % 3; added > 0 && first.size() < 200; --added) {
        const std::size_t g = first.size();
        first.push_back(height(rng));
        model.insert(std::upper_bound(model.begin() + static_cast<std::ptrdiff_t>(i), model.end(), g,
                                      [&](std::size_t a, std::size_t b) { return first[a] < first[b]; }),
                     g);
        order.add(g, first[g]);
      }
    }
    EXPECT_EQ(i, model.size()) << "seed " << seed;
  }
}

// A batch lists its waiting candidates by height, after its clusters: groups
// mostly in a few runs that already ascend, which start() merges.
TEST(ResolveOrder, GroupsListedInAscendingRunsComeOutByFirstCollisionThenIndex) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> first;
    for (std::size_t runs = rng() % 6; runs > 0; --runs) {
      double f = height(rng);
      for (std::size_t k = rng() % 50; k > 0; --k) {
        first.push_back(f);
        if (rng() % 3 != 0) f += 0.25 * static_cast<double>(rng() % 3);
      }
    }
    const auto first_of = [&](std::size_t g) { return first[g]; };
    std::vector<std::size_t> model = by_first_then_index(first);
    ResolveOrder order;
    order.start(first.size(), first_of);
    std::vector<std::size_t> resolved;
    while (!order.empty()) resolved.push_back(order.next());
    EXPECT_EQ(resolved, model) << "seed " << seed;
  }
}

}  // namespace
}  // namespace procex::engine

// The order a batch's groups of collisions are resolved in (resolve_intersections).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace procex::engine {

// The groups of a batch not yet resolved, in the order they are resolved: by
// first collision, groups first met at one height in the order they are
// listed. A group added while the batch is resolved (a collapse, a member
// that waits) goes after every group first met no higher. The groups added
// wait apart, lowest first, and are merged in as they come: at a jittered
// star's centre a million groups follow the instant where most are added,
// and putting each in its place moved them all.
class ResolveOrder {
 public:
  // Groups 0 .. n - 1, group g first met at first_of(g).
  template <class FirstOf>
  void start(std::size_t n, const FirstOf& first_of) {
    listed_.resize(n);
    for (std::size_t g = 0; g < n; ++g) listed_[g] = {first_of(g), g};
    // The next last (by index among groups first met at one height, not by a
    // stable sort: std::stable_sort takes a buffer from the heap at every batch).
    std::sort(listed_.begin(), listed_.end(), std::greater<>());
    added_.clear();
  }
  bool empty() const { return listed_.empty() && added_.empty(); }
  std::size_t next() {
    if (added_.empty() || (!listed_.empty() && !(added_.front().first < listed_.back().first))) {
      const std::size_t g = listed_.back().second;
      listed_.pop_back();
      return g;
    }
    std::pop_heap(added_.begin(), added_.end(), std::greater<>());
    const std::size_t g = added_.back().second;
    added_.pop_back();
    return g;
  }
  // Group g, first met at `at`, numbered after every group listed or added.
  void add(std::size_t g, double at) {
    added_.push_back({at, g});
    std::push_heap(added_.begin(), added_.end(), std::greater<>());
  }
  // The groups not yet resolved, the next first, into `out`.
  void pending(std::vector<std::size_t>& out) {
    sorted_.assign(added_.begin(), added_.end());
    std::sort(sorted_.begin(), sorted_.end());
    out.clear();
    auto a = sorted_.cbegin();
    for (auto l = listed_.crbegin(); l != listed_.crend(); ++l) {
      for (; a != sorted_.cend() && a->first < l->first; ++a) out.push_back(a->second);
      out.push_back(l->second);
    }
    for (; a != sorted_.cend(); ++a) out.push_back(a->second);
  }

 private:
  // (first met, group): listed_ the next last, added_ a heap, lowest on top.
  std::vector<std::pair<double, std::size_t>> listed_, added_, sorted_;
};

}  // namespace procex::engine

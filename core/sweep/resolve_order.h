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
    // By (first met, index), a strict order, so one result however it is
    // reached. The runs that already ascend are merged rather than sorted
    // again: a batch's waiting candidates come in its order, by height, and in
    // a random 262,144-gon's sweep a batch holds 17,000 of them on average.
    merge_runs();
    std::reverse(listed_.begin(), listed_.end());  // the next last
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
  // listed_ sorted ascending by merging its ascending runs pairwise, through
  // sorted_ (kept, as every list here, from batch to batch).
  void merge_runs() {
    runs_.clear();
    runs_.push_back(0);
    for (std::size_t i = 1; i < listed_.size(); ++i)
      if (listed_[i] < listed_[i - 1]) runs_.push_back(i);
    runs_.push_back(listed_.size());
    while (runs_.size() > 2) {
      sorted_.resize(listed_.size());
      std::size_t kept = 0;
      for (std::size_t r = 0; r + 1 < runs_.size(); r += 2) {
        const auto at = [&](std::size_t k) { return listed_.begin() + static_cast<std::ptrdiff_t>(runs_[k]); };
        const std::size_t end = std::min(r + 2, runs_.size() - 1);
        std::merge(at(r), at(r + 1), at(r + 1), at(end), sorted_.begin() + static_cast<std::ptrdiff_t>(runs_[r]));
        runs_[kept++] = runs_[r];
      }
      runs_[kept++] = listed_.size();
      runs_.resize(kept);
      listed_.swap(sorted_);
    }
  }

  // (first met, group): listed_ the next last, added_ a heap, lowest on top.
  std::vector<std::pair<double, std::size_t>> listed_, added_, sorted_;
  std::vector<std::size_t> runs_;  // merge_runs': where each run starts, then the end
};

}  // namespace procex::engine

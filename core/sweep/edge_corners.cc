#include "core/sweep/edge_corners.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include <glm/geometric.hpp>

namespace procex::engine {
namespace {

// Queries may look at this many entries beyond the index's size before its
// places are taken again: a small index is not redone at every query.
constexpr std::size_t kSlack = 64;
// Entries made since the last merge that queries look through one by one.
constexpr std::size_t kFew = 32;

// Drops the entries (place or partner, corner) whose corner has died.
template <class Entry>
void drop_dead(const State& st, std::vector<Entry>& entries) {
  entries.erase(std::remove_if(entries.begin(), entries.end(),
                               [&](const Entry& entry) { return !st.corners[entry.second].alive; }),
                entries.end());
}

}  // namespace

void EdgeCorners::take_new_corners(const State& st) {
  for (; seen_ < st.corners.size(); ++seen_) {
    const int c = static_cast<int>(seen_);
    for (int e : {st.corners[c].prev_edge, st.corners[c].next_edge}) {
      const auto k = static_cast<std::size_t>(e);
      if (k < slot_.size() && slot_[k] >= 0) add(st, indexes_[static_cast<std::size_t>(slot_[k])], e, c);
    }
  }
}

void EdgeCorners::add(const State& st, Index& index, int e, int c) {
  const Corner& k = st.corners[c];
  const glm::dvec2 dir = st.edges[e].dir;
  index.places.recent.emplace_back(glm::dot(st.position(c, index.z0), dir), c);
  index.partners.recent.emplace_back(k.next_edge == e ? k.prev_edge : k.next_edge, c);
  index.fastest = std::max(index.fastest, std::abs(glm::dot(k.velocity, dir)));
}

template <class Entry>
std::size_t EdgeCorners::Runs<Entry>::size() const {
  std::size_t n = recent.size();
  for (const auto& run : sorted) n += run.size();
  return n;
}

template <class Entry>
void EdgeCorners::merge_recent(const State& st, Runs<Entry>& runs) {
  drop_dead(st, runs.recent);
  if (runs.recent.empty()) return;
  std::sort(runs.recent.begin(), runs.recent.end());
  moved_ += runs.recent.size();
  runs.sorted.emplace_back(runs.recent.begin(), runs.recent.end());
  runs.recent.clear();
  while (runs.sorted.size() >= 2 && runs.sorted[runs.sorted.size() - 2].size() <= 2 * runs.sorted.back().size()) {
    std::vector<Entry>& into = runs.sorted[runs.sorted.size() - 2];
    const std::vector<Entry>& last = runs.sorted.back();
    const auto middle = static_cast<std::ptrdiff_t>(into.size());
    into.insert(into.end(), last.begin(), last.end());
    std::inplace_merge(into.begin(), into.begin() + middle, into.end());
    drop_dead(st, into);
    moved_ += into.size();
    runs.sorted.pop_back();
  }
}

void EdgeCorners::retake(const State& st, Index& index, int e, double z) {
  auto& [sorted, recent] = index.places;
  for (auto& run : sorted) recent.insert(recent.end(), run.begin(), run.end());
  sorted.clear();
  drop_dead(st, recent);
  const glm::dvec2 dir = st.edges[e].dir;
  index.z0 = z;
  index.fastest = 0.0;
  for (auto& [key, c] : recent) {
    key = glm::dot(st.position(c, z), dir);
    index.fastest = std::max(index.fastest, std::abs(glm::dot(st.corners[c].velocity, dir)));
  }
  merge_recent(st, index.places);
  index.looked_at = 0;
}

EdgeCorners::Index& EdgeCorners::index_of(const State& st, int e, double z) {
  take_new_corners(st);
  const auto k = static_cast<std::size_t>(e);
  if (slot_.size() <= k) slot_.resize(st.edges.size(), -1);
  if (slot_[k] < 0) {
    slot_[k] = static_cast<int>(indexes_.size());
    Index& index = indexes_.emplace_back();
    index.z0 = z;
    for (int s : st.listed_spans(e)) {
      if (!st.corners[s].alive) continue;  // a stale entry
      add(st, index, e, s);
      if (const int t = st.corners[s].next; t != kNone) add(st, index, e, t);
    }
  }
  Index& index = indexes_[static_cast<std::size_t>(slot_[k])];
  // Taken again at this height once the queries, widened by how far places
  // drift from z0 (and by dead entries, which only merges drop), looked at as
  // many entries as it holds.
  if (index.looked_at > index.places.size() + kSlack) retake(st, index, e, z);
  // The unsorted entries are looked through at every query.
  if (index.places.recent.size() > kFew) merge_recent(st, index.places);
  if (index.partners.recent.size() > kFew) merge_recent(st, index.partners);
  return index;
}

void EdgeCorners::near(const State& st, int e, glm::dvec2 p, double z, double reach, std::vector<int>& out) {
  Index& index = index_of(st, e, z);
  const double along = glm::dot(p, st.edges[e].dir);
  // Places were taken at z0: a corner drifts by at most `fastest` per unit of
  // height from there; the rest is room for rounding, relative to the
  // coordinates.
  const double range =
      reach + 2.0 * index.fastest * std::abs(z - index.z0) + 1e-7 * (1.0 + std::abs(p.x) + std::abs(p.y));
  for (const auto& run : index.places.sorted) {
    auto it = std::lower_bound(run.begin(), run.end(), std::pair{along - range, INT_MIN});
    const auto first = it;
    for (; it != run.end() && it->first <= along + range; ++it)
      if (st.corners[it->second].alive) out.push_back(it->second);
    index.looked_at += static_cast<std::size_t>(it - first);
  }
  for (const auto& [key, c] : index.places.recent)
    if (std::abs(key - along) <= range && st.corners[c].alive) out.push_back(c);
}

void EdgeCorners::between(const State& st, int e, int f, std::vector<int>& out) {
  Index& index = index_of(st, e, st.height);
  for (const auto& run : index.partners.sorted) {
    const auto [lo, hi] = std::equal_range(run.begin(), run.end(), std::pair{f, 0},
                                           [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto it = lo; it != hi; ++it)
      if (st.corners[it->second].alive) out.push_back(it->second);
  }
  for (const auto& [other, c] : index.partners.recent)
    if (other == f && st.corners[c].alive) out.push_back(c);
}

}  // namespace procex::engine

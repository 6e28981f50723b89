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
  index.recent.emplace_back(glm::dot(st.position(c, index.z0), dir), c);
  index.recent_partners.emplace_back(k.next_edge == e ? k.prev_edge : k.next_edge, c);
  index.fastest = std::max(index.fastest, std::abs(glm::dot(k.velocity, dir)));
}

void EdgeCorners::merge(const State& st, Index& index, int e, double z) {
  auto dead = [&](const auto& entry) { return !st.corners[entry.second].alive; };
  auto merge_in = [&](auto& sorted, auto& recent) {
    const auto middle = static_cast<std::ptrdiff_t>(sorted.size());
    std::sort(recent.begin(), recent.end());
    sorted.insert(sorted.end(), recent.begin(), recent.end());
    std::inplace_merge(sorted.begin(), sorted.begin() + middle, sorted.end());
    sorted.erase(std::remove_if(sorted.begin(), sorted.end(), dead), sorted.end());
    recent.clear();
  };
  merge_in(index.partners, index.recent_partners);
  index.looked_at = 0;
  if (z == index.z0) {
    merge_in(index.sorted, index.recent);
    return;
  }
  index.sorted.insert(index.sorted.end(), index.recent.begin(), index.recent.end());
  index.recent.clear();
  index.sorted.erase(std::remove_if(index.sorted.begin(), index.sorted.end(), dead), index.sorted.end());
  const glm::dvec2 dir = st.edges[e].dir;
  index.z0 = z;
  index.fastest = 0.0;
  for (auto& [key, c] : index.sorted) {
    key = glm::dot(st.position(c, z), dir);
    index.fastest = std::max(index.fastest, std::abs(glm::dot(st.corners[c].velocity, dir)));
  }
  std::sort(index.sorted.begin(), index.sorted.end());
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
    merge(st, index, e, z);
    return index;
  }
  Index& index = indexes_[static_cast<std::size_t>(slot_[k])];
  // Merged once the unsorted part costs as much to look through per query as
  // the merge costs per corner made since; taken again at this height once
  // the queries, widened by how far places drift from z0, looked at as many
  // entries as it holds.
  const std::size_t held = index.sorted.size() + index.recent.size();
  const auto few = static_cast<std::size_t>(32.0 + std::sqrt(static_cast<double>(index.sorted.size())));
  if (index.recent.size() > few || index.looked_at > held + kSlack) merge(st, index, e, z);
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
  auto it = std::lower_bound(index.sorted.begin(), index.sorted.end(), std::pair{along - range, INT_MIN});
  const auto first = it;
  for (; it != index.sorted.end() && it->first <= along + range; ++it)
    if (st.corners[it->second].alive) out.push_back(it->second);
  for (const auto& [key, c] : index.recent)
    if (std::abs(key - along) <= range && st.corners[c].alive) out.push_back(c);
  index.looked_at += static_cast<std::size_t>(it - first);
}

void EdgeCorners::between(const State& st, int e, int f, std::vector<int>& out) {
  Index& index = index_of(st, e, st.height);
  const auto [lo, hi] = std::equal_range(index.partners.begin(), index.partners.end(), std::pair{f, 0},
                                         [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto it = lo; it != hi; ++it)
    if (st.corners[it->second].alive) out.push_back(it->second);
  for (const auto& [other, c] : index.recent_partners)
    if (other == f && st.corners[c].alive) out.push_back(c);
}

}  // namespace procex::engine

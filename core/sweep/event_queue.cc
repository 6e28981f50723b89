#include "core/sweep/event_queue.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>
#include <tuple>

#include <glm/geometric.hpp>

#include "core/sweep/meeting_heights.h"

namespace procex::engine {
bool EventQueue::EntryLater::operator()(const Entry& a, const Entry& b) const {
  if (a.z != b.z) return a.z > b.z;
  if (a.corner != b.corner) return a.corner > b.corner;
  return a.edge > b.edge;
}

void EventQueue::clear() {
  heap_.clear();
  // Dropped, not freed for reuse: a queue kept from a sweep of many lists
  // would have every later sweep walk them all (6 % of the OSM corpus's
  // instructions and most of its first-level data misses).
  lists_.clear();
  free_lists_.clear();
  live_ = std::make_shared<Targets>();
  some_.reset();
  listed_.clear();
  outward_.clear();
  closing_.clear();
  live_corners_ = rebuilt_at_ = 0;
  held_ = peak_held_ = worked_ = 0;
  kt_.clear();
  triangulated_ = leave_triangulation_ = lists_twice_ = false;
  made_by_.clear();
  made_at_.clear();
  fresh_.clear();
  listed_whole_.clear();
}

void EventQueue::start(State& st) {
  if (triangulated_from_ == SIZE_MAX || st.any_outward) return;
  const auto live = static_cast<std::size_t>(
      std::count_if(st.corners.begin(), st.corners.end(), [](const Corner& k) { return k.alive; }));
  if (live < triangulated_from_ || !kt_.build(st)) return kt_.clear();
  triangulated_ = lists_twice_ = true;
  st.relinked = &kt_.relinked();
}

double EventQueue::listed_from(const State& st, int c) const {
  return static_cast<std::size_t>(c) < made_at_.size() && !std::isnan(made_at_[c]) ? made_at_[c] : st.height;
}

const std::vector<int>& EventQueue::made_by(int c) const {
  static const std::vector<int> none;
  return static_cast<std::size_t>(c) < made_by_.size() ? made_by_[c] : none;
}

void EventQueue::drop_triangulation(State& st) {
  triangulated_ = leave_triangulation_ = false;
  st.relinked = nullptr;
  kt_.clear();
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) list_every_plane(st, c);
  made_by_.clear();
  made_at_.clear();
  fresh_.clear();
  listed_whole_.clear();
}

bool EventQueue::listed_whole(int c) const {
  return static_cast<std::size_t>(c) < listed_whole_.size() && listed_whole_[c];
}

void EventQueue::list_every_plane(State& st, int c) {
  if (!st.corners[c].alive || !st.may_split(c) || listed_whole(c)) return;
  listed_whole_.resize(std::max(listed_whole_.size(), static_cast<std::size_t>(c) + 1), 0);
  listed_whole_[c] = 1;
  refresh_live(st);
  add_splits(st, c, live_, live_->edge.size(), made_by(c), listed_from(st, c));
}

void EventQueue::catch_up(State& st) {
  if (!triangulated_) return;
  // What the batch did to triangles standing past their collapse first
  // (collapse_through asks them again), then the region round what it
  // relinked is triangulated again.
  if (leave_triangulation_ || st.any_outward || !kt_.collapse_through(st, st.height) || !kt_.update(st))
    return drop_triangulation(st);
  // The corners the batch made were not there when it was popped: the
  // splits that may wait round them are handed out as round its events.
  places_.clear();
  for (int c : fresh_)
    if (st.corners[c].alive) places_.push_back({st.position(c, made_at_[c]), made_at_[c], c, kNone, kNone});
  if (!places_.empty()) kt_.hand_around(st, places_, reach(st), st.tol().height());
  for (;;) {
    // Splits listed now may come below the candidate that was next: flips
    // up to theirs are due too.
    list_facing(st);
    for (int c : fresh_) made_at_[c] = NAN;
    fresh_.clear();
    if (heap_.empty()) return;
    const double through = heap_.top().z + st.tol().height();
    if (kt_.next_collapse() > through) return;
    if (!kt_.collapse_through(st, through)) return drop_triangulation(st);
    if (kt_.facing().empty()) return;
  }
}

void EventQueue::list_facing(State& st) {
  auto& facing = kt_.facing();
  std::sort(facing.begin(), facing.end(), [](const auto& a, const auto& b) { return a.corner < b.corner; });
  for (std::size_t r = 0; r < facing.size();) {
    const int c = facing[r].corner;
    facing_edges_.clear();
    for (; r < facing.size() && facing[r].corner == c; ++r) facing_edges_.push_back(facing[r].edge);
    if (st.corners[c].alive && !listed_whole(c)) list_splits(st, c, facing_edges_, made_by(c));
  }
  facing.clear();
  for (int c : kt_.tangled()) list_every_plane(st, c);
  kt_.tangled().clear();
}

void EventQueue::schedule_edge_event(State& st, int c) {
  const Corner& k = st.corners[c];
  const int n = k.next;
  if (n == kNone || n == c) return;
  const double z = st.height;
  // A meeting point below the sweep plane means the planes diverge from here.
  const double at = st.span_closes_at(c, z);
  if (std::isnan(at)) return;
  st.count_events(1);
  heap_.push({std::max(at, z), at, c, n, kNone, kNone});
}

void EventQueue::Targets::add(int e, const Plane& pl) {
  edge.push_back(e);
  push_back(pl);
}

void EventQueue::Targets::reserve(std::size_t n) {
  PlaneColumns::reserve(n);
  edge.reserve(n);
}

bool EventQueue::Targets::same_as(const Targets& o) const {
  const auto bits = [](const auto& a, const auto& b) {
    // An empty vector's data() may be null, which memcmp must not be given even for no bytes.
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
  };
  return bits(edge, o.edge) && bits(nx, o.nx) && bits(ny, o.ny) && bits(k, o.k) && bits(c, o.c) && shared == o.shared;
}

void EventQueue::list_planes(const State& st, const std::vector<int>& edges, Targets& t) {
  // The edges by plane, to the bit (then in the order given): each run is a plane.
  keyed_.clear();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Plane& pl = st.edges[edges[i]].plane;
    const double fields[4] = {pl.n.x, pl.n.y, pl.k, pl.c};
    PlaneKey key;
    std::memcpy(key.bits.data(), fields, sizeof fields);
    keyed_.push_back({key, i});
  }
  std::sort(keyed_.begin(), keyed_.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.bits, a.second) < std::tie(b.first.bits, b.second);
  });
  // Each edge's first with its plane (its place in the order given), and how many share it.
  first_.resize(edges.size());
  sharing_.assign(edges.size(), 0);
  for (std::size_t r = 0; r < keyed_.size();) {
    std::size_t end = r + 1;
    while (end < keyed_.size() && keyed_[end].first.bits == keyed_[r].first.bits) ++end;
    for (std::size_t j = r; j < end; ++j) first_[keyed_[j].second] = keyed_[r].second;
    sharing_[keyed_[r].second] = end - r;
    r = end;
  }
  // A plane takes the place of its first edge; the others join its list.
  place_.resize(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const int e = edges[i];
    const std::size_t first = first_[i];
    if (first != i) {
      t.shared[static_cast<std::size_t>(t.edge[place_[first]] - kShared)].push_back(e);
      continue;
    }
    place_[i] = t.edge.size();
    t.add(e, st.edges[e].plane);
    if (sharing_[i] > 1) {
      t.edge.back() = kShared + static_cast<int>(t.shared.size());
      t.shared.push_back({e});
      t.spans.emplace_back();
    }
  }
}

void EventQueue::refresh_live(State& st) {
  const std::size_t corners = st.corners.size();
  if (corners == live_corners_) return;
  // Listing only the edges of new corners is O(1) per corner; the edges that
  // lost their spans are dropped by a full pass once half as many corners
  // came. The pass starts a new set: lists of the old one still read it.
  if (corners - rebuilt_at_ > std::max<std::size_t>(64, live_->edge.size() / 2)) {
    live_ = std::make_shared<Targets>();
    live_->live = true;
    live_->reserve(st.edges.size());
    listed_.assign(st.edges.size(), 0);
    live_edges_.clear();
    for (int e = 0; e < static_cast<int>(st.edges.size()); ++e)
      if (!st.spans(e).empty()) {
        live_edges_.push_back(e);
        listed_[e] = 1;
      }
    list_planes(st, live_edges_, *live_);
    rebuilt_at_ = live_corners_ = corners;
    return;
  }
  // Room for every edge (few are made after the first, against many
  // corners): grown by doubling, the five lists were 7 % of the city's
  // allocations.
  live_->reserve(st.edges.size());
  listed_.resize(st.edges.size(), 0);
  for (std::size_t c = live_corners_; c < corners; ++c)
    if (st.corners[c].alive) list_live(st, st.corners[c].next_edge);
  live_corners_ = corners;
}

void EventQueue::list_live(const State& st, int e) {
  if (listed_[e]) return;
  listed_[e] = 1;
  live_->add(e, st.edges[e].plane);
}

void EventQueue::schedule(State& st, int c, const std::vector<int>& resolved) {
  if (triangulated_) {
    // Its splits are listed once the triangulation has taken it in (catch_up).
    if (!resolved.empty()) {
      made_by_.resize(std::max(made_by_.size(), static_cast<std::size_t>(c) + 1));
      made_by_[c] = resolved;
    }
    made_at_.resize(std::max(made_at_.size(), static_cast<std::size_t>(c) + 1), NAN);
    made_at_[c] = st.height;
    fresh_.push_back(c);
    schedule_edge_event(st, c);
    return;
  }
  if (st.any_outward) {
    outward_.resize(std::max(outward_.size(), static_cast<std::size_t>(c) + 1), 0);
    outward_[c] = 1;
  }
  schedule_edge_event(st, c);
  if (!st.may_split(c)) return;
  refresh_live(st);
  add_splits(st, c, live_, live_->edge.size(), resolved, st.height);
}

void EventQueue::schedule_splits(State& st, int c, const std::vector<int>& edges, const std::vector<int>& resolved) {
  // New planes met by corners that stay (a profile's or a plan edit's): the
  // triangulation does not follow planes changing under its corners.
  if (triangulated_) {
    leave_triangulation_ = true;  // at the next catch_up(), which lists this corner's splits too
    return;
  }
  list_splits(st, c, edges, resolved);
}

void EventQueue::list_splits(State& st, int c, const std::vector<int>& edges, const std::vector<int>& resolved) {
  if (!st.may_split(c)) return;
  // Callers give every corner the same new planes in turn: one copy serves them all.
  auto some = std::make_shared<Targets>();
  list_planes(st, edges, *some);
  if (!some_ || !some_->same_as(*some)) some_ = std::move(some);
  add_splits(st, c, some_, some_->edge.size(), resolved, listed_from(st, c));
}

inline void EventQueue::offer(const SplitList& list, const Split& s, double through) {
  if (queued_at(list, s) <= through) {
    within_.push_back(s);
    return;
  }
  ++after_through_;
  // Most splits are above the highest held: one comparison turns them away.
  if (lowest_.size() == list.hold && !SplitEarlier{list.path.z}(s, lowest_.back())) return;
  hold_among_lowest(list, s);
}

void EventQueue::hold_among_lowest(const SplitList& list, const Split& s) {
  // The highest held drops out when all are held.
  if (lowest_.size() < list.hold) lowest_.emplace_back();
  const auto last = lowest_.end() - 1;
  const auto at = std::upper_bound(lowest_.begin(), last, s, SplitEarlier{list.path.z});
  std::move_backward(at, last, lowest_.end());
  *at = s;
}

std::size_t EventQueue::find_splits(const SplitList& list, double through) {
  const Targets& t = *list.targets;
  const std::size_t n = list.size;
  // Whole runs of kRun, the tail never meeting: the test for a run with any
  // meeting then compiles to a few vector compares.
  constexpr std::size_t kRun = 8;
  const std::size_t padded = (n + kRun - 1) / kRun * kRun;
  at_.resize(padded);
  meeting_heights(t.nx.data(), t.ny.data(), t.k.data(), t.c.data(), n, list.path, at_.data());
  std::fill(at_.begin() + static_cast<std::ptrdiff_t>(n), at_.end(), HUGE_VAL);
  const double* meet = at_.data();
  // The few that meet, gathered without a branch per edge; in a capped
  // (nested) sweep whole runs of edges are out of reach.
  hits_.resize(padded);
  std::size_t m = 0;
  for (std::size_t j0 = 0; j0 < padded; j0 += kRun) {
    bool any = false;
    for (std::size_t j = j0; j < j0 + kRun; ++j) any |= meet[j] != HUGE_VAL;
    if (!any) continue;
    for (std::size_t j = j0; j < j0 + kRun; ++j) {
      hits_[m] = static_cast<std::uint32_t>(j);
      m += meet[j] != HUGE_VAL;
    }
  }
  // Those queued already: up to the last, and as many equal to it as were queued.
  const SplitEarlier earlier{list.path.z};
  std::size_t same = list.same, worked = 0;
  for (std::size_t h = 0; h < m; ++h) {
    const std::size_t j = hits_[h];
    const Split s{meet[j], t.edge[j]};
    if (!queues(list, s.at, s.edge)) continue;
    ++worked;
    if (list.last.edge != kNone && !earlier(list.last, s)) {
      if (earlier(s, list.last)) continue;
      if (same > 0) {
        --same;
        continue;
      }
    }
    offer(list, s, through);
  }
  return worked;
}

void EventQueue::add_splits(const State& st, int c, std::shared_ptr<const Targets> targets, std::size_t size,
                            const std::vector<int>& resolved, double from) {
  if (size == 0) return;
  const Corner& k = st.corners[c];
  int i;
  if (free_lists_.empty()) {
    i = static_cast<int>(lists_.size());
    lists_.emplace_back();
  } else {
    i = free_lists_.back();
    free_lists_.pop_back();
  }
  SplitList& list = lists_[i];
  list.targets = std::move(targets);
  list.size = size;
  // Nothing above the cap is ever resolved.
  list.path = st.corner_path(st.position(c, from), k.velocity, from, from - st.tol().height(),
                             st.options().max_height.value_or(HUGE_VAL));
  list.near = from + st.tol().height();
  list.prev_edge = k.prev_edge;
  list.next_edge = k.next_edge;
  list.resolved = resolved;
  std::sort(list.resolved.begin(), list.resolved.end());
  list.splits.clear();
  list.hold = kHeld;
  list.complete = false;
  list.last = {0.0, kNone};
  list.same = 0;
  st.count_events(hold_next(i));
  advance(i, c);
}

std::size_t EventQueue::hold_next(int i, double through) {
  SplitList& list = lists_[i];
  const Targets& t = *list.targets;
  within_.clear();
  lowest_.clear();
  after_through_ = 0;
  std::optional<std::size_t> worked;
  bool every = true;  // every split not yet queued was offered
  const CornerPath& path = list.path;
  if (t.live && list.size >= indexed_from_ && t.index.worth_searching() && std::isfinite(path.p.x) &&
      std::isfinite(path.p.y) && std::isfinite(path.v.x) && std::isfinite(path.v.y) && std::isfinite(path.z)) {
    // The live edges are each listed once, so the splits not queued yet are
    // those after the last queued. Of the lowest of them, the list does not
    // queue at most its two edges' and its collision's: as many more hold
    // the lowest it queues.
    const std::size_t more = 2 + list.resolved.size();
    t.index.extend(t.planes(), list.size, path.p);
    worked = t.index.lowest(t.planes(), {path, list.size, list.last, through}, list.hold + more, found_,
                            found_within_, index_scratch_);
    if (worked) {
      every = found_.size() < list.hold + more;
      for (const auto* found : {&found_within_, &found_})
        for (const Split& s : *found)
          if (queues(list, s.at, s.edge)) offer(list, s, through);
    }
  }
  if (!worked) worked = find_splits(list, through);
  list.splits.assign(lowest_.rbegin(), lowest_.rend());
  list.complete = every && after_through_ == lowest_.size();
  held_ += list.splits.size();
  peak_held_ = std::max(peak_held_, held_);
  worked_ += *worked;
  return *worked;
}

void EventQueue::free_list(int i) {
  SplitList& list = lists_[i];
  held_ -= list.splits.size();
  list.splits.clear();
  list.targets.reset();
  free_lists_.push_back(i);
}

void EventQueue::advance(int i, int c) {
  SplitList& list = lists_[i];
  if (list.splits.empty() && !list.complete) {
    list.hold = std::min(2 * list.hold, kHeldMost);
    hold_next(i);
  }
  if (list.splits.empty()) {
    free_list(i);
    return;
  }
  const Split s = list.splits.back();
  list.splits.pop_back();
  --held_;
  note_queued(list, s);
  heap_.push({queued_at(list, s), s.at, c, kNone, s.edge, i});
}

void EventQueue::note_queued(SplitList& list, const Split& s) {
  // A list queues its splits lowest first, except those drain() takes in one
  // pass, unordered: the last is the highest, and `same` counts its equals.
  const SplitEarlier earlier{list.path.z};
  if (list.last.edge == kNone || earlier(list.last, s)) {
    list.last = s;
    list.same = 1;
  } else if (!earlier(s, list.last)) {
    ++list.same;
  }
}

bool EventQueue::closes_here(State& st, const Candidate& k) const {
  const auto closes = [&](int c) {
    return c != kNone && closing_[c].batch == batch_ && glm::distance(closing_[c].p, k.p) <= st.tol().position();
  };
  if (!closes(k.corner) && !closes(st.corners[k.corner].prev)) return false;
  // The span resolve_intersections checks the split against (hits_span).
  return closes(st.span_through(k.edge, k.p, k.z, st.tol().position()));
}

void EventQueue::named(const State& st, const SplitList& list, const Split& s, glm::dvec2 p, double z,
                       std::vector<int>& out) {
  out.clear();
  const Targets& t = *list.targets;
  const std::size_t g = static_cast<std::size_t>(s.edge - kShared);
  const std::vector<int>& edges = t.shared[g];
  SharedSpans& spans = t.spans[g];
  const glm::dvec2 dir = st.edges[edges.front()].dir;
  if (spans.batch != batch_) {
    // Sorted once a batch: nothing changes the spans while it is popped.
    spans.batch = batch_;
    spans.z = z;
    spans.drift = 0.0;
    auto& sorted = shared_sorted_;
    sorted.clear();
    for (int e : edges)
      for (int a : st.listed_spans(e)) {
        const int b = st.corners[a].next;
        if (!st.corners[a].alive || st.corners[a].next_edge != e || b == kNone) continue;
        const double u = glm::dot(st.position(a, z), dir), w = glm::dot(st.position(b, z), dir);
        sorted.emplace_back(std::min(u, w), std::max(u, w), e);
        spans.drift = std::max({spans.drift, std::abs(glm::dot(st.corners[a].velocity, dir)),
                                std::abs(glm::dot(st.corners[b].velocity, dir))});
      }
    std::sort(sorted.begin(), sorted.end());
    spans.lo.clear();
    spans.hi.clear();
    spans.hi_max.clear();
    spans.edge.clear();
    for (const auto& [lo, hi, e] : sorted) {
      spans.lo.push_back(lo);
      spans.hi.push_back(hi);
      spans.hi_max.push_back(spans.hi_max.empty() ? hi : std::max(hi, spans.hi_max.back()));
      spans.edge.push_back(e);
    }
  }
  // As span_through takes a span to hold the point, with the drift of the
  // spans' ends since the height they were sorted at and the rounding of
  // taking places along the line here and there.
  const double u = glm::dot(p, dir);
  const double reach = st.tol().span_margin() + spans.drift * std::abs(z - spans.z) * (1.0 + 1e-9) +
                       1e-12 * (std::abs(u) + std::abs(p.x) + std::abs(p.y));
  // The spans holding the point start at or before it (before `to`) and end at
  // or after it (from `from` on, where the highest end so far first reaches it).
  const std::size_t to = static_cast<std::size_t>(
      std::upper_bound(spans.lo.begin(), spans.lo.end(), u + reach) - spans.lo.begin());
  const std::size_t from = static_cast<std::size_t>(
      std::lower_bound(spans.hi_max.begin(), spans.hi_max.end(), u - reach) - spans.hi_max.begin());
  for (std::size_t j = from; j < to; ++j)
    if (spans.hi[j] >= u - reach) out.push_back(spans.edge[j]);
  if (out.empty()) {
    if (to > 0) {
      std::size_t j = to - 1;
      while (j > 0 && spans.hi[j] != spans.hi_max[to - 1]) --j;
      out.push_back(spans.edge[j]);
    }
    if (to < spans.lo.size()) out.push_back(spans.edge[to]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void EventQueue::hand_out(State& st, const SplitList& list, int c, const Split& s) {
  const Candidate k{queued_at(list, s), st.position(c, s.at), c, kNone, s.edge};
  if (s.edge < kShared) {
    if (!closes_here(st, k)) cluster_.push_back(k);
    return;
  }
  named(st, list, s, k.p, k.z, named_);
  for (int e : named_) {
    if (!queues(list, s.at, e)) continue;
    const Candidate split{k.z, k.p, c, kNone, e};
    if (!closes_here(st, split)) cluster_.push_back(split);
  }
}

void EventQueue::drain(State& st, int i, int c, double through) {
  SplitList& list = lists_[i];
  const auto take = [&](const Split& s) {
    note_queued(list, s);
    hand_out(st, list, c, s);
  };
  for (;;) {
    while (!list.splits.empty() && queued_at(list, list.splits.back()) <= through) {
      const Split s = list.splits.back();
      list.splits.pop_back();
      --held_;
      take(s);
    }
    if (!list.splits.empty() || list.complete) break;
    // Worked out again, every split in the batch at once: at the apex of an
    // exact star each list has n of them, which kHeldMost at a time cost a
    // pass over the edges per kHeldMost (n^3 / 256 tests in all).
    list.hold = std::min(2 * list.hold, kHeldMost);
    hold_next(i, through);
    for (const Split& s : within_) take(s);
  }
  advance(i, c);
}

double EventQueue::slack(const State& st, const Entry& e) const {
  const Corner& k = st.corners[e.corner];
  if (!k.alive) return 0.0;
  if (e.list != kNone) {
    const Targets& t = *lists_[e.list].targets;
    const int edge = e.edge < kShared ? e.edge : t.shared[e.edge - kShared].front();
    return st.meeting_slack(k.prev_edge, k.next_edge, edge, std::span(&e.corner, 1));
  }
  if (k.next != e.next || !st.corners[e.next].alive) return 0.0;
  const int ends[] = {e.corner, e.next};
  return st.meeting_slack(k.prev_edge, k.next_edge, st.corners[e.next].next_edge, ends);
}

void EventQueue::pop_through(State& st, double through) {
  std::vector<Candidate>& out = cluster_;
  while (!heap_.empty() && heap_.top().z <= through) {
    const Entry e = heap_.top();
    heap_.pop();
    // A dead corner's events are void, and so is the rest of its list.
    if (!st.corners[e.corner].alive) {
      if (e.list != kNone) free_list(e.list);
      continue;
    }
    if (e.list != kNone) {
      // A shared plane's edges are named once the batch's collapses are known:
      // its candidates join the splits drained after these.
      if (e.edge >= kShared) {
        heads_.push_back({SIZE_MAX, e.list});
        shared_heads_.push_back({e.corner, {e.at, e.edge}});
        continue;
      }
      heads_.push_back({out.size(), e.list});
      out.push_back({e.z, st.position(e.corner, e.at), e.corner, kNone, e.edge});
      continue;
    }
    // An edge event happens between the two corners.
    const glm::dvec2 p = 0.5 * (st.position(e.corner, e.at) + st.position(e.next, e.at));
    out.push_back({e.z, p, e.corner, e.next, e.edge});
    // The span closes if its corners are still neighbours (as meets() takes it).
    Closing& closing = closing_[e.corner];
    if (st.corners[e.corner].next == e.next && st.corners[e.next].alive && closing.batch != batch_)
      closing = {batch_, p};
  }
}

double EventQueue::reach(const State& st) {
  return std::max(st.tol().position(), st.tol().most_meeting_slack());
}

bool EventQueue::widen(State& st, std::size_t& widened, std::size_t& widened_shared, double rise) {
  places_.clear();
  for (; widened < cluster_.size(); ++widened) {
    const Candidate& k = cluster_[widened];
    places_.push_back({k.p, k.z, k.corner, k.next, k.next == kNone ? k.edge : kNone});
  }
  for (; widened_shared < shared_heads_.size(); ++widened_shared) {
    const auto& [c, s] = shared_heads_[widened_shared];
    places_.push_back({st.position(c, s.at), s.at, c, kNone, kNone});
  }
  if (places_.empty() || !kt_.hand_around(st, places_, reach(st), rise)) return false;
  list_facing(st);
  return true;
}

const std::vector<Candidate>& EventQueue::pop_cluster(State& st) {
  std::vector<Candidate>& out = cluster_;
  out.clear();
  heads_.clear();
  shared_heads_.clear();
  ++batch_;
  closing_.resize(st.corners.size());
  // The lowest event and those within its own uncertainty above it, where
  // that passes delta2: the edge events of a finely drawn circle lie apart by
  // what rounding makes of their planes' conditioning, not by the geometry.
  const double lowest = heap_.top().z;
  const double through = lowest + std::max(st.tol().height(), slack(st, heap_.top()));
  // The edge events first, and each list's first split: which spans close in
  // the batch is known before any split is dropped for one (closes_here).
  // Triangulated, the pairs that may meet near them are listed too, and
  // those of their splits in the batch are taken in with them.
  std::size_t widened = 0, widened_shared = 0;
  for (bool more = true; more;) {
    pop_through(st, through);
    more = triangulated_ && widen(st, widened, widened_shared, through - lowest);
  }
  if (heads_.empty()) return out;
  // Then the rest of each list in the batch, and the candidates in the
  // queue's order again (by height, corner, edge).
  const std::size_t popped = out.size();
  std::size_t shared = 0;
  for (const auto& [at, i] : heads_) {
    int c;
    if (at == SIZE_MAX) {
      const auto& [corner, s] = shared_heads_[shared++];
      c = corner;
      hand_out(st, lists_[i], c, s);
    } else {
      c = out[at].corner;
      if (closes_here(st, out[at])) out[at].corner = kNone;
    }
    drain(st, i, c, through);
    st.hold_candidates(out.size());
    st.check_time();
  }
  const auto dropped = std::remove_if(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(popped),
                                      [](const Candidate& k) { return k.corner == kNone; });
  const auto middle = out.erase(dropped, out.begin() + static_cast<std::ptrdiff_t>(popped));
  const auto earlier = [](const Candidate& a, const Candidate& b) {
    return std::tie(a.z, a.corner, a.edge) < std::tie(b.z, b.corner, b.edge);
  };
  std::sort(middle, out.end(), earlier);
  std::inplace_merge(out.begin(), middle, out.end(), earlier);
  if (lists_twice_) drop_repeated_splits();
  return out;
}

void EventQueue::drop_repeated_splits() {
  std::vector<Candidate>& out = cluster_;
  repeated_.clear();
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i].next == kNone) repeated_.push_back({out[i].corner, out[i].edge, i});
  std::sort(repeated_.begin(), repeated_.end());
  bool any = false;
  for (std::size_t r = 1; r < repeated_.size(); ++r)
    if (std::get<0>(repeated_[r]) == std::get<0>(repeated_[r - 1]) &&
        std::get<1>(repeated_[r]) == std::get<1>(repeated_[r - 1])) {
      out[std::get<2>(repeated_[r])].corner = kNone;
      any = true;
    }
  if (any) out.erase(std::remove_if(out.begin(), out.end(), [](const Candidate& k) { return k.corner == kNone; }), out.end());
}

}  // namespace procex::engine

// The lazy event queue (paper 4.1): potential events wherever three planes
// meet, ordered by height. Nothing is checked against the live loops until the
// sweep plane reaches the event.
//
// A reflex corner may run into any live edge: O(n) potential split events per
// corner, most of which never happen (the corner dies first, or the edge's
// spans are elsewhere by then). Each scheduling keeps its split candidates in
// a list of its own, and only the lowest of each list sits in the height
// queue; popping it brings up the list's next one. The queue stays O(n), and
// a list whose corner has died is dropped unread.
#pragma once

#include <algorithm>
#include <cstdint>
#include <queue>
#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

struct Candidate {
  double z = 0.0;
  glm::dvec2 p{0.0};
  int corner = kNone;  // the corner that collides
  int next = kNone;    // edge event: the following corner it meets (snapshot)
  int edge = kNone;    // split event: the edge the corner runs into
};

class EventQueue {
 public:
  // Queues every potential event of corner c: meeting its next corner (the
  // span between them shrinks to nothing) and, where c can cut into the loop,
  // meeting any other live edge. `resolved` lists the edges of the collision
  // that made c, if any: c does not collide with them again where it stands.
  void schedule(State& st, int c, const std::vector<int>& resolved = {});
  // Queues the events of corner c running into each of `edges` (if c can cut
  // into the loop at all).
  void schedule_splits(State& st, int c, const std::vector<int>& edges, const std::vector<int>& resolved = {});
  // Queues only the event of corner c with its next corner.
  void schedule_edge_event(State& st, int c);
  // Whether corner c's splits were listed by the rule in force now: once a
  // plane leans out, convex corners split too, and corners meet planes from
  // outside.
  bool knows_outward(const State& st, int c) const {
    return !st.any_outward || (static_cast<std::size_t>(c) < outward_.size() && outward_[c]);
  }

  bool empty() const { return heap_.empty(); }
  double next_height() const { return heap_.top().z; }
  // Removes every candidate within the height tolerance of the lowest and
  // returns those of live corners, lowest first (valid until the next call).
  const std::vector<Candidate>& pop_cluster(const State& st);

 private:
  // A split candidate waiting in its corner's list: where the corner meets
  // the edge's plane (queued no lower than the list's height).
  struct Split {
    double at;
    int edge;
  };
  // One scheduling's split candidates. A corner lives to see only a few of
  // them popped, so they are not kept sorted: the lowest few are picked out
  // (one pass) into the back, lowest last, and picked again when used up.
  struct SplitList {
    std::vector<Split> splits;
    std::size_t picked = 0;  // the last `picked` splits are the lowest, in order
    double z = 0.0;          // the sweep plane's height when listed
  };
  // A candidate in the height queue; its point is worked out when it is popped.
  struct Entry {
    double z, at;  // queued at height z; the planes meet at height `at`
    int corner, next, edge;
    int list;  // the split list it heads, or kNone (an edge event)
  };
  struct EntryLater {
    bool operator()(const Entry& a, const Entry& b) const;
  };
  // The order of one list's splits, as the queue orders them.
  struct SplitEarlier {
    double z;
    bool operator()(const Split& a, const Split& b) const {
      const double za = std::max(a.at, z), zb = std::max(b.at, z);
      return za != zb ? za < zb : a.edge < b.edge;
    }
  };
  // Edges a corner may run into, their planes' coefficients side by side
  // (the test of every corner against every edge is the sweep's inner loop).
  struct Targets {
    std::vector<int> edge;
    std::vector<double> nx, ny, k, c;
    void clear();
    void add(int e, const Plane& pl);
  };
  // The edges with live spans. Edges gain spans only with new corners, which
  // add their edges; an edge that lost its spans since only costs candidates
  // that fail validation, until a full pass drops it.
  void refresh_live(State& st);
  void list_live(const State& st, int e);
  // Lists the splits of corner c against `targets`.
  void add_splits(const State& st, int c, const Targets& targets, const std::vector<int>& resolved);
  // Puts the lowest split of list i (of corner c) in the queue, or frees the list.
  void advance(int i, int c);

  std::priority_queue<Entry, std::vector<Entry>, EntryLater> heap_;
  std::vector<SplitList> lists_;
  std::vector<int> free_lists_;
  Targets live_, some_;
  std::vector<char> listed_;                        // edge -> in live_
  std::vector<char> outward_;                       // corner -> scheduled once a plane leaned out
  std::size_t live_corners_ = 0, rebuilt_at_ = 0;    // corners seen by live_, at its last full pass
  std::vector<double> at_;                          // scratch of add_splits
  std::vector<std::uint32_t> hits_;
  std::vector<Candidate> cluster_;  // what pop_cluster returned last
};

}  // namespace procex::engine

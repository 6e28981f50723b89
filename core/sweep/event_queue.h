// The lazy event queue (paper 4.1): potential events wherever three planes
// meet, ordered by height. Nothing is checked against the live loops until the
// sweep plane reaches the event.
#pragma once

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

struct CandidateLater {
  bool operator()(const Candidate& a, const Candidate& b) const {
    if (a.z != b.z) return a.z > b.z;
    if (a.corner != b.corner) return a.corner > b.corner;
    return a.edge > b.edge;
  }
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

  bool empty() const { return heap_.empty(); }
  double next_height() const { return heap_.top().z; }
  // Removes and returns every candidate within the height tolerance of the lowest.
  std::vector<Candidate> pop_cluster(double height_tolerance);
  std::size_t size() const { return heap_.size(); }

 private:
  void push(State& st, const Candidate& c);
  std::priority_queue<Candidate, std::vector<Candidate>, CandidateLater> heap_;
};

}  // namespace procex::engine

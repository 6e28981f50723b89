// Edge direction events (paper 4.2, 4.4): at each vertex of a profile the
// plane of every edge following it is replaced by the next segment's plane,
// through the edge's line on the sweep plane at that height. Only the next
// pending event of each edge is queued.
#pragma once

#include <queue>
#include <utility>
#include <vector>

#include "core/sweep/event_queue.h"

namespace procex::engine {

class ProfileEvents {
 public:
  // Queues the next profile vertex of source s above its current plane's start.
  void schedule(const State& st, int s);
  bool empty() const { return heap_.empty(); }
  double next_height() const { return heap_.top().first; }
  // Removes and returns every source whose event is within `tolerance` of the lowest.
  std::vector<int> pop(double tolerance);

 private:
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap_;
};

// The first segment at or after profile point `point` that is not horizontal
// (rises more than `flat`): the slope a source continues with, the point it
// starts at (the last point once the profile is used up, so no event follows),
// and the outward offset of the horizontal segments skipped on the way.
struct NextPlane {
  std::size_t segment;
  std::size_t point;
  double outward_step;
};
NextPlane next_plane(const Profile& profile, std::size_t point, double flat);

// Slope (inward offset per unit height) and tag of a profile segment.
double segment_slope(const Profile& profile, std::size_t segment);

// Moves every source in `sources` on to its next profile segment at the
// current height: new planes, new corners, output where the old faces end.
// Horizontal runs step the cross-section sideways (horizontal_event.h).
void apply_profile_events(State& st, EventQueue& queue, ProfileEvents& events, const std::vector<int>& sources);

}  // namespace procex::engine

// Plan edit events (paper 4.6, fig. 20, 21): at an edit's height, new corners
// and edges are spliced into the live loops where its anchor lies, the
// neighbouring corners keeping the edge they share; only the new corners and
// edges get their intersections computed. A natural step is spliced in
// vanishingly shallow and grown to its depth by a horizontal run (a nested
// sweep), so it stays simple wherever it runs into the rest of the loop.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "core/geom/plan_edit.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/horizontal_event.h"
#include "core/sweep/profile_event.h"

namespace procex::engine {

class PlanEditEvents {
 public:
  // One request per edit (st.options().plan_edits) and footprint edge its
  // anchor selects; the inserted edges' profiles index `profiles`. Throws
  // InputError naming a malformed edit.
  PlanEditEvents(const State& st, const std::vector<Profile>& profiles);

  bool empty() const { return next_ == order_.size(); }
  double next_height() const;
  // Inserts the requests at the lowest pending height (st.height is there).
  void apply_next(State& st, EventQueue& queue, ProfileEvents& profile_events);
  // Where each request was applied, or why not (requests above the roof are absent).
  std::vector<ResolvedAnchor> finish();

 private:
  struct Request {
    std::size_t edit;
    int source;
    double height;
  };
  // A natural step's sliver: its horizontal face and its front's bottom.
  struct Sliver {
    int face;
    HalfEdge front;
  };
  // What the splices at one height leave to do.
  struct Batch {
    std::map<int, SourceStep> steps;  // natural steps' growth
    std::vector<Sliver> slivers;
    std::vector<int> made;            // forced steps' corners
    std::vector<int> new_edges, new_sources;
  };
  void splice(State& st, const Request& q, ResolvedAnchor& r, Batch& batch);
  void finish_batch(State& st, EventQueue& queue, ProfileEvents& profile_events, Batch& batch);

  const std::vector<Profile>* profiles_;
  std::vector<Request> requests_;
  std::vector<std::size_t> order_;  // requests by height
  std::size_t next_ = 0;
  std::vector<ResolvedAnchor> out_;
};

}  // namespace procex::engine

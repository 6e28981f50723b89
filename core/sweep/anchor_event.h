// Anchor events (paper 4.2, fig. 29): when the sweep plane reaches an
// anchor's height, each selected edge that still has a live span there turns
// the anchor into a position and a frame on its face; an edge gone by then,
// or a plan anchor beyond the edge's ends, makes it absent, with the reason.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Whether anchor `a` selects source s (by its profile and edge ids).
bool selects(const Anchor& a, const Source& s);

// Throws InputError, starting with `what`, for an anchor whose numbers are unusable.
void check_anchor(const Anchor& a, const std::string& what);

// Where a plan anchor lies on a source's edge at height z (the live loops as they are).
struct EdgePoint {
  int span = kNone;       // the corner starting the live span that holds it
  glm::dvec2 point{0.0};  // on the edge's line
  double u = 0.0;         // the point along the edge's direction
};
// The point, moved `shift` along the edge, or nothing (with r's absence and
// reason saying why) when the edge is gone or the point lies beyond its ends.
std::optional<EdgePoint> locate(State& st, int source, const PlanAnchor& plan, double z, ResolvedAnchor& r,
                                double shift = 0.0);

class AnchorEvents {
 public:
  // One request per anchor and selected footprint edge (sources are the
  // footprint's edges in order). Throws InputError naming a malformed anchor.
  AnchorEvents(const State& st, const std::vector<Anchor>& anchors);

  bool empty() const { return next_ == order_.size(); }
  double next_height() const { return requests_[order_[next_]].height; }
  // Resolves every request at or below `height` against the live loops.
  void resolve_up_to(State& st, double height);
  // Requests the sweep never reached (above the roof) become absent.
  std::vector<ResolvedAnchor> finish();

 private:
  struct Request {
    std::size_t anchor;
    int source;
    double height;
    PlanAnchor plan;
  };
  std::vector<Request> requests_;
  std::vector<std::size_t> order_;  // requests by height
  std::size_t next_ = 0;
  std::vector<ResolvedAnchor> out_;
};

}  // namespace procex::engine

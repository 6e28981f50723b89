#include "core/sweep/anchor_event.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <glm/geometric.hpp>

#include "core/geom/error.h"

namespace procex::engine {
namespace {

std::string named(const Anchor& a, std::size_t i) {
  return "anchor '" + (a.name.empty() ? std::to_string(i) : a.name) + "'";
}

// Where along the edge's direction the plan anchor sits, given the extent of
// the edge's live spans at this height (for fractions).
double along(const PlanAnchor& plan, const Source& src, glm::dvec2 dir, double lo, double hi) {
  switch (plan.mode) {
    case PlanAnchor::Mode::Fraction:
      return lo + plan.value * (hi - lo);
    case PlanAnchor::Mode::FromStart:
      return glm::dot(src.start, dir) + plan.value;
    case PlanAnchor::Mode::FromEnd:
      return glm::dot(src.end, dir) - plan.value;
  }
  return lo;
}

}  // namespace

bool selects(const Anchor& a, const Source& s) {
  if (a.profile >= 0 && s.profile_index != a.profile) return false;
  return a.edges.empty() || std::find(a.edges.begin(), a.edges.end(), s.id) != a.edges.end();
}

void check_anchor(const Anchor& a, const std::string& what) {
  if (!std::isfinite(a.height) || a.height < 0.0)
    throw InputError(what + ": height " + std::to_string(a.height) + " is not a height above the footprint");
  if (!std::isfinite(a.plan.value)) throw InputError(what + ": its position on the edge is not a finite number");
  if (a.plan.mode == PlanAnchor::Mode::Fraction && (a.plan.value < 0.0 || a.plan.value > 1.0))
    throw InputError(what + ": fraction " + std::to_string(a.plan.value) + " is outside [0, 1]");
}

std::optional<EdgePoint> locate(State& st, int source, const PlanAnchor& plan, double z, ResolvedAnchor& r,
                                double shift) {
  const Source& src = st.sources[source];
  const Edge& edge = st.edges[src.edge];
  const SpanList spans = st.spans(src.edge);
  if (spans.empty()) {
    r.absence = Absence::EdgeGone;
    r.reason = "edge " + std::to_string(src.id) + " no longer exists at height " + std::to_string(z);
    return std::nullopt;
  }
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int s : spans) {
    lo = std::min(lo, glm::dot(st.position(s, z), edge.dir));
    hi = std::max(hi, glm::dot(st.position(st.corners[s].next, z), edge.dir));
  }
  const double u = along(plan, src, edge.dir, lo, hi) + shift;
  const glm::dvec2 on_line = edge.plane.n * edge.plane.offset_at(z);
  const double margin = st.tol().span_margin();
  for (int s : spans) {
    const glm::dvec2 a = st.position(s, z), b = st.position(st.corners[s].next, z);
    if (glm::dot(a, edge.dir) - margin > u || glm::dot(b, edge.dir) + margin < u) continue;
    return EdgePoint{s, on_line + edge.dir * (u - glm::dot(on_line, edge.dir)), u};
  }
  r.absence = Absence::OffEdge;
  r.reason = "it lies beyond the ends of edge " + std::to_string(src.id) + " at height " + std::to_string(z);
  return std::nullopt;
}

AnchorEvents::AnchorEvents(const State& st, const std::vector<Anchor>& anchors) {
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    const Anchor& a = anchors[i];
    check_anchor(a, named(a, i));
    bool any = false;
    for (int s = 0; s < static_cast<int>(st.sources.size()); ++s) {
      if (!selects(a, st.sources[s])) continue;
      any = true;
      requests_.push_back({i, s, a.height, a.plan});
      ResolvedAnchor r;
      r.name = a.name;
      r.anchor = i;
      r.edge_id = st.sources[s].id;
      out_.push_back(std::move(r));
    }
    if (!any) throw InputError(named(a, i) + " selects no edge of the footprint");
  }
  order_.resize(requests_.size());
  std::iota(order_.begin(), order_.end(), 0);
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t x, std::size_t y) { return requests_[x].height < requests_[y].height; });
  for (ResolvedAnchor& r : out_) {
    r.absence = Absence::AboveSweep;
    r.reason = "the sweep ends below its height";
  }
}

void AnchorEvents::resolve_up_to(State& st, double height) {
  while (!empty() && next_height() <= height) {
    const std::size_t i = order_[next_++];
    const Request& q = requests_[i];
    ResolvedAnchor& r = out_[i];
    const std::optional<EdgePoint> hit = locate(st, q.source, q.plan, q.height, r);
    if (!hit) continue;
    const Edge& edge = st.edges[st.sources[q.source].edge];
    const FaceGroup& face = st.faces[edge.face];
    r.present = true;
    r.absence = Absence::None;
    r.reason.clear();
    r.frame.origin = {hit->point, q.height};
    r.frame.along = {edge.dir, 0.0};
    r.frame.normal = face.outward;
    r.frame.up = glm::cross(face.outward, r.frame.along);
    r.span_from = {st.position(hit->span, q.height), q.height};
    r.span_to = {st.position(st.corners[hit->span].next, q.height), q.height};
  }
}

std::vector<ResolvedAnchor> AnchorEvents::finish() {
  next_ = order_.size();
  return std::move(out_);
}

}  // namespace procex::engine

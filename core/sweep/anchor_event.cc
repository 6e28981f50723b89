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

bool selects(const Anchor& a, const Source& s) {
  if (a.profile >= 0 && s.profile_index != a.profile) return false;
  return a.edges.empty() || std::find(a.edges.begin(), a.edges.end(), s.id) != a.edges.end();
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

AnchorEvents::AnchorEvents(const State& st, const std::vector<Anchor>& anchors) {
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    const Anchor& a = anchors[i];
    if (!std::isfinite(a.height) || a.height < 0.0)
      throw InputError(named(a, i) + ": height " + std::to_string(a.height) + " is not a height above the footprint");
    if (!std::isfinite(a.plan.value))
      throw InputError(named(a, i) + ": its position on the edge is not a finite number");
    if (a.plan.mode == PlanAnchor::Mode::Fraction && (a.plan.value < 0.0 || a.plan.value > 1.0))
      throw InputError(named(a, i) + ": fraction " + std::to_string(a.plan.value) + " is outside [0, 1]");
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
  for (ResolvedAnchor& r : out_) r.reason = "the sweep ends below its height";
}

void AnchorEvents::resolve_up_to(State& st, double height) {
  while (!empty() && next_height() <= height) {
    const std::size_t i = order_[next_++];
    const Request& q = requests_[i];
    ResolvedAnchor& r = out_[i];
    const Source& src = st.sources[q.source];
    const int e = src.edge;
    const Edge edge = st.edges[e];
    const auto& spans = st.spans(e);
    if (spans.empty()) {
      r.reason = "edge " + std::to_string(src.id) + " no longer exists at height " + std::to_string(q.height);
      continue;
    }
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int s : spans) {
      lo = std::min(lo, glm::dot(st.position(s, q.height), edge.dir));
      hi = std::max(hi, glm::dot(st.position(st.corners[s].next, q.height), edge.dir));
    }
    const double u = along(q.plan, src, edge.dir, lo, hi);
    const glm::dvec2 on_line = edge.plane.n * edge.plane.offset_at(q.height);
    const glm::dvec2 p = on_line + edge.dir * (u - glm::dot(on_line, edge.dir));
    r.reason = "it lies beyond the ends of edge " + std::to_string(src.id) + " at height " + std::to_string(q.height);
    for (int s : spans) {
      const glm::dvec2 a = st.position(s, q.height), b = st.position(st.corners[s].next, q.height);
      const double margin = st.tol().span_margin();
      if (glm::dot(a, edge.dir) - margin > u || glm::dot(b, edge.dir) + margin < u) continue;
      const FaceGroup& face = st.faces[edge.face];
      r.present = true;
      r.reason.clear();
      r.frame.origin = {p, q.height};
      r.frame.along = {edge.dir, 0.0};
      r.frame.normal = face.outward;
      r.frame.up = glm::cross(face.outward, r.frame.along);
      r.span_from = {a, q.height};
      r.span_to = {b, q.height};
      break;
    }
  }
}

std::vector<ResolvedAnchor> AnchorEvents::finish() {
  next_ = order_.size();
  return std::move(out_);
}

}  // namespace procex::engine

#include "app/studio/editor/canvas_layout.h"

#include <algorithm>
#include <cstdlib>

#include <glm/common.hpp>

namespace procex::studio {

void CanvasView::zoom_at(glm::vec2 screen, float factor) {
  const glm::vec2 anchor = to_canvas(screen);
  zoom = std::clamp(zoom * factor, 0.2f, 3.0f);
  pan = (screen - origin) / zoom - anchor;
}

void CanvasView::frame(const Rect& bounds, glm::vec2 size, float min_zoom) {
  const glm::vec2 extent = glm::max(bounds.size(), glm::vec2(1.0f));
  const float margin = 40.0f;
  const glm::vec2 avail = glm::max(size - glm::vec2(2.0f * margin), glm::vec2(1.0f));
  zoom = std::clamp(std::min(avail.x / extent.x, avail.y / extent.y), std::min(min_zoom, 1.5f), 1.5f);
  // Centred along each axis that fits; otherwise its start at the margin.
  pan = size * 0.5f / zoom - (bounds.min + bounds.max) * 0.5f;
  for (int axis = 0; axis < 2; ++axis)
    if (extent[axis] * zoom > avail[axis]) pan[axis] = margin / zoom - bounds.min[axis];
}

namespace {

NodeBox make_box(NodeId id, glm::vec2 pos, std::size_t inputs, std::size_t outputs) {
  NodeBox b;
  b.id = id;
  b.rect = {pos, pos + node_size(inputs, outputs)};
  for (std::size_t i = 0; i < inputs; ++i) b.inputs.push_back(pos + glm::vec2(0.0f, pin_offset(i)));
  for (std::size_t i = 0; i < outputs; ++i) b.outputs.push_back(pos + glm::vec2(kNodeWidth, pin_offset(i)));
  return b;
}

}  // namespace

glm::vec2 node_size(std::size_t inputs, std::size_t outputs) {
  const std::size_t rows = std::max<std::size_t>(std::max(inputs, outputs), 1);
  return {kNodeWidth, kHeaderHeight + kRowHeight * static_cast<float>(rows) + 6.0f};
}

std::vector<NodeBox> layout(const Graph& g) {
  std::vector<NodeBox> boxes;
  for (const auto& [id, n] : g.nodes())
    boxes.push_back(make_box(id, {static_cast<float>(n.editor.x), static_cast<float>(n.editor.y)}, n.decl().inputs().size(),
                             n.decl().outputs().size()));
  const Rect all = boxes.empty() ? Rect{} : bounds(boxes);
  if (!g.inputs().empty()) boxes.push_back(make_box(kGraphInputs, {all.min.x - kNodeWidth - 80.0f, all.min.y}, 0, g.inputs().size()));
  if (!g.outputs().empty()) boxes.push_back(make_box(kGraphOutputs, {all.max.x + 80.0f, all.min.y}, g.outputs().size(), 0));
  return boxes;
}

const NodeBox* find_box(const std::vector<NodeBox>& boxes, NodeId id) {
  for (const NodeBox& b : boxes)
    if (b.id == id) return &b;
  return nullptr;
}

std::optional<PinHit> pin_at(const std::vector<NodeBox>& boxes, glm::vec2 p, float radius) {
  const float r2 = radius * radius;
  auto near = [&](glm::vec2 q) { return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) <= r2; };
  for (auto b = boxes.rbegin(); b != boxes.rend(); ++b) {
    for (std::uint32_t i = 0; i < b->inputs.size(); ++i)
      if (near(b->inputs[i])) return PinHit{{b->id, i}, false};
    for (std::uint32_t i = 0; i < b->outputs.size(); ++i)
      if (near(b->outputs[i])) return PinHit{{b->id, i}, true};
  }
  return std::nullopt;
}

NodeId node_at(const std::vector<NodeBox>& boxes, glm::vec2 p) {
  for (auto b = boxes.rbegin(); b != boxes.rend(); ++b)
    if (b->id <= kMaxNodeId && b->rect.contains(p)) return b->id;
  return 0;
}

std::vector<NodeId> nodes_in(const std::vector<NodeBox>& boxes, const Rect& r) {
  std::vector<NodeId> out;
  for (const NodeBox& b : boxes)
    if (b.id <= kMaxNodeId && b.rect.overlaps(r)) out.push_back(b.id);
  return out;
}

Rect bounds(const std::vector<NodeBox>& boxes, const std::vector<NodeId>& ids) {
  Rect r;
  bool first = true;
  for (const NodeBox& b : boxes) {
    if (!ids.empty() && std::find(ids.begin(), ids.end(), b.id) == ids.end()) continue;
    r.min = first ? b.rect.min : glm::min(r.min, b.rect.min);
    r.max = first ? b.rect.max : glm::max(r.max, b.rect.max);
    first = false;
  }
  return r;
}

glm::vec2 free_spot(const std::vector<NodeBox>& boxes, glm::vec2 centre, glm::vec2 size) {
  const glm::vec2 want = centre - size * 0.5f;
  const auto free = [&](glm::vec2 corner) {
    // Grown by a little less than the gap: a box exactly the gap away is free (overlaps counts touching).
    const Rect r{corner - glm::vec2(kPlacementGap - 0.5f), corner + size + glm::vec2(kPlacementGap - 0.5f)};
    return std::none_of(boxes.begin(), boxes.end(), [&](const NodeBox& b) { return b.rect.overlaps(r); });
  };
  // Rings of grid points around `want`, nearest first by their square ring;
  // the search stops once no farther ring can hold a nearer point. Outside the
  // boxes' bounds every point is free, so it ends by the ring that leaves them.
  std::optional<glm::vec2> best;
  float best_d2 = 0.0f;
  for (int ring = 0;; ++ring) {
    const float ring_d = static_cast<float>(ring) * kPlacementGap;
    if (best && ring_d * ring_d > best_d2) return *best;
    for (int i = -ring; i <= ring; ++i)
      for (int j = -ring; j <= ring; j += std::abs(i) == ring ? 1 : std::max(2 * ring, 1)) {  // the ring's points only
        const glm::vec2 step(static_cast<float>(i) * kPlacementGap, static_cast<float>(j) * kPlacementGap);
        const float d2 = step.x * step.x + step.y * step.y;
        if ((!best || d2 < best_d2) && free(want + step)) {
          best = want + step;
          best_d2 = d2;
        }
      }
  }
}

}  // namespace procex::studio

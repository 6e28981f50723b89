#include "core/placement/place_mesh.h"

#include <glm/gtc/matrix_transform.hpp>

#include "core/placement/box.h"
#include "core/placement/frame_transform.h"
#include "core/placement/placement_error.h"
#include "core/placement/stretch.h"

namespace procex {
namespace {

std::vector<const ResolvedAnchor*> named(const std::vector<ResolvedAnchor>& anchors, const std::string& name) {
  std::vector<const ResolvedAnchor*> out;
  for (const ResolvedAnchor& a : anchors)
    if (a.name == name) out.push_back(&a);
  if (out.empty()) {
    std::string names;
    for (const ResolvedAnchor& a : anchors)
      if (names.find("'" + a.name + "'") == std::string::npos) names += (names.empty() ? "" : ", ") + ("'" + a.name + "'");
    throw PlacementError("no anchor named '" + name + "' was resolved" +
                         (names.empty() ? std::string(" (there are none)") : " (there are " + names + ")"));
  }
  return out;
}

std::string where(const ResolvedAnchor& a) { return "anchor '" + a.name + "' on edge " + std::to_string(a.edge_id); }

// The offset, given in the frame's axes, as a world translation.
glm::dmat4 shift(const Frame& f, const glm::dvec3& offset) {
  return glm::translate(glm::dmat4(1.0), offset.x * f.along + offset.y * f.up + offset.z * f.normal);
}

// The transforms for one present resolution.
std::vector<glm::dmat4> transforms(const Box3& box, const ResolvedAnchor& a, const std::vector<ResolvedAnchor>& anchors,
                                   const MeshPlacementSpec& spec, PlaceMeshReport& report) {
  const FramePlacement at{box.at(spec.pivot), spec.scale, spec.offset};
  std::vector<glm::dmat4> out;
  switch (spec.mode) {
    case MeshPlacementSpec::Mode::Single:
      out.push_back(place_at(a.frame, at));
      break;
    case MeshPlacementSpec::Mode::Row:
    case MeshPlacementSpec::Mode::Grid: {
      const bool row = spec.mode == MeshPlacementSpec::Mode::Row;
      for (const Cell& cell : row ? repeat_on_span(a, spec.columns)
                                  : repeat_grid(a, spec.z_from, spec.z_to, spec.columns, spec.rows))
        out.push_back(spec.fit ? shift(cell.frame, spec.offset) * fit_to_cell(box, cell, spec.margin)
                               : place_at(cell.frame, at));
      break;
    }
    case MeshPlacementSpec::Mode::Stretch: {
      const ResolvedAnchor* top = nullptr;
      for (const ResolvedAnchor* t : named(anchors, spec.top_anchor))
        if (t->edge_id == a.edge_id) top = t;
      if (!top || !top->present) {
        report.absent.push_back(where(a) + ": its top anchor '" + spec.top_anchor + "' is " +
                                (top ? "absent there: " + top->reason : std::string("not resolved on that edge")));
        break;
      }
      out.push_back(shift(a.frame, spec.offset) *
                    stretch_between(box, a.frame, a.frame.origin, top->frame.origin, 1, spec.pivot));
      break;
    }
  }
  return out;
}

}  // namespace

PlaceMeshReport place_mesh(PlacementResult& result, const PlaceableMesh& mesh,
                           const std::vector<ResolvedAnchor>& anchors, const MeshPlacementSpec& spec) {
  const std::vector<const ResolvedAnchor*> resolutions = named(anchors, spec.anchor);
  if (!mesh.mesh) throw PlacementError("the mesh '" + mesh.name + "' to place is null");
  const Box3 box = bounds(*mesh.mesh);
  PlaceMeshReport report;
  std::vector<Instance> placed;  // added at the end, so a failure leaves `result` as it was
  for (const ResolvedAnchor* a : resolutions) {
    if (!a->present) {
      report.absent.push_back(where(*a) + " is absent: " + a->reason);
      continue;
    }
    try {
      for (const glm::dmat4& t : transforms(box, *a, anchors, spec, report)) placed.push_back({0, t, spec.tag, a->edge_id});
    } catch (const PlacementError& e) {
      throw PlacementError(where(*a) + ": " + e.what());
    }
  }
  const std::size_t index = result.add_mesh(mesh);
  for (Instance& in : placed) {
    in.mesh = index;
    result.add_instance(std::move(in));
  }
  report.instances = placed.size();
  return report;
}

}  // namespace procex

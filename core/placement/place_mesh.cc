#include "core/placement/place_mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/placement/box.h"
#include "core/placement/face_cover.h"
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
                                   const MeshPlacementSpec& spec, double z_to, PlaceMeshReport& report) {
  const FramePlacement at{box.at(spec.pivot), spec.scale, spec.offset};
  std::vector<glm::dmat4> out;
  switch (spec.mode) {
    case MeshPlacementSpec::Mode::Single:
    case MeshPlacementSpec::Mode::Tiles:  // place_in_tiles
      out.push_back(place_at(a.frame, at));
      break;
    case MeshPlacementSpec::Mode::Row:
    case MeshPlacementSpec::Mode::Grid: {
      const bool row = spec.mode == MeshPlacementSpec::Mode::Row;
      for (const Cell& cell : row ? repeat_on_span(a, spec.columns)
                                  : repeat_grid(a, spec.z_from, z_to, spec.columns, spec.rows))
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

// The world height of the highest point of `faces` (in a's frame coordinates); the anchor's own if none.
double top_of(const std::vector<std::vector<glm::dvec2>>& faces, const ResolvedAnchor& a) {
  double top = 0;
  for (const auto& face : faces)
    for (const glm::dvec2& p : face) top = std::max(top, p.y);
  return a.frame.origin.z + top * a.frame.up.z;
}

// The box, placed by t, seen along the frame's normal: a rectangle in its (along, up) coordinates.
Opening outline(const Box3& box, const glm::dmat4& t, std::int32_t edge, const Frame& frame) {
  Opening o{edge, frame, glm::dvec2(HUGE_VAL), glm::dvec2(-HUGE_VAL)};
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner(k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z);
    const glm::dvec3 d = glm::dvec3(t * glm::dvec4(corner, 1.0)) - frame.origin;
    const glm::dvec2 p(glm::dot(d, frame.along), glm::dot(d, frame.up));
    o.lo = glm::min(o.lo, p), o.hi = glm::max(o.hi, p);
  }
  return o;
}

// Adds the mesh and its instances to `result` once every one of them was
// placed, so that a failure leaves `result` as it was.
PlaceMeshReport commit(PlacementResult& result, const PlaceableMesh& mesh, std::vector<Instance>& placed,
                       PlaceMeshReport report) {
  const std::size_t index = result.add_mesh(mesh);
  for (Instance& in : placed) {
    in.mesh = index;
    result.add_instance(std::move(in));
  }
  report.instances = placed.size();
  return report;
}

}  // namespace

PlaceMeshReport place_mesh(PlacementResult& result, const PlaceableMesh& mesh,
                           const std::vector<ResolvedAnchor>& anchors, const MeshPlacementSpec& spec,
                           const FaceCover* cover) {
  const std::vector<const ResolvedAnchor*> resolutions = named(anchors, spec.anchor);
  if (!mesh.mesh) throw PlacementError("the mesh '" + mesh.name + "' to place is null");
  const Box3 box = bounds(*mesh.mesh);
  PlaceMeshReport report;
  std::vector<Instance> placed;  // committed at the end
  for (const ResolvedAnchor* a : resolutions) {
    if (!a->present) {
      report.absent.push_back(where(*a) + " is absent: " + a->reason);
      continue;
    }
    const bool clipped = cover && (spec.mode == MeshPlacementSpec::Mode::Row || spec.mode == MeshPlacementSpec::Mode::Grid);
    const auto faces = clipped ? cover->faces_in_plane(a->edge_id, a->frame) : std::vector<std::vector<glm::dvec2>>();
    try {
      double z_to = spec.z_to;
      if (spec.z_to_top) {
        if (!clipped) throw PlacementError("z_to_top needs the anchor's face: a grid, not stood upright");
        z_to = top_of(faces, *a);
      }
      for (const glm::dmat4& t : transforms(box, *a, anchors, spec, z_to, report)) {
        const Opening o = outline(box, t, a->edge_id, a->frame);
        if (clipped && !covered(faces, o.lo, o.hi)) {
          ++report.dropped;
          continue;
        }
        placed.push_back({0, t, spec.tag, a->edge_id});
        report.outlines.push_back(o);
      }
    } catch (const PlacementError& e) {
      throw PlacementError(where(*a) + ": " + e.what());
    }
  }
  return commit(result, mesh, placed, std::move(report));
}

PlaceMeshReport place_in_tiles(PlacementResult& result, const PlaceableMesh& mesh, const std::vector<FacadeTile>& tiles,
                               const MeshPlacementSpec& spec) {
  if (!mesh.mesh) throw PlacementError("the mesh '" + mesh.name + "' to place is null");
  const Box3 box = bounds(*mesh.mesh);
  const FramePlacement at{box.at(spec.pivot), spec.scale, spec.offset};
  std::vector<Instance> placed;
  PlaceMeshReport report;
  for (const FacadeTile& t : tiles) {
    if (t.name != spec.anchor || t.floor < spec.floor_from || t.floor > spec.floor_to) continue;
    Cell cell{t.frame, t.width, t.height, t.bay, t.floor};
    cell.frame.origin += t.height / 2 * t.frame.up;  // a cell's origin is its centre
    try {
      placed.push_back({0, spec.fit ? shift(cell.frame, spec.offset) * fit_to_cell(box, cell, spec.margin) : place_at(t.frame, at),
                        spec.tag, t.edge_id});
      report.outlines.push_back(outline(box, placed.back().transform, t.edge_id, t.frame));
    } catch (const PlacementError& e) {
      throw PlacementError("tile '" + t.name + "' on edge " + std::to_string(t.edge_id) + ", floor " + std::to_string(t.floor) +
                           ", bay " + std::to_string(t.bay) + ": " + e.what());
    }
  }
  return commit(result, mesh, placed, std::move(report));
}

}  // namespace procex

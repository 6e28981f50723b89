// Extrusion as the Extrude node runs it: prepare the footprint, sweep it along
// its edges' profiles (capped at the highest profile top), build the mesh and
// tag every face with its profile segment's tag (wall or roof by angle for
// edges without a profile), resolving the anchors it is given on the way up.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geom/footprint.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "nodes/values.h"

namespace procex {

struct Extrusion {
  TaggedMesh mesh;
  ValidationOptions validation;  // what the mesh is held to (roof_validation)
  // For warnings: repairs made by prepare_footprint, anchors resolved absent
  // (with why) and plan edits not applied.
  std::vector<std::string> notes;
};

// `anchors` are resolved on the mesh (Extrusion::mesh.anchors, each
// ResolvedAnchor::anchor an index into `anchors`); they replace
// options.anchors. One that selects no edge of this footprint resolves absent
// once, with edge id -1. Throws what prepare_footprint, sweep and build_mesh throw
// (InputError, SweepError, MeshError), and InputError for an anchor naming a
// profile or an edge id the footprint does not have.
// `plan_edits` are inserted where their anchors lie (absent ones become notes);
// they replace options.plan_edits.
Extrusion extrude(const Footprint& footprint, const SweepOptions& options, const std::vector<AnchorSpec>& anchors = {},
                  const std::vector<PlanEditSpec>& plan_edits = {});

}  // namespace procex

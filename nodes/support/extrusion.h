// Extrusion as the Extrude node runs it: prepare the footprint, sweep it along
// its edges' profiles (capped at the highest profile top), build the mesh and
// tag every face with its profile segment's tag (wall or roof by angle for
// edges without a profile).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geom/footprint.h"
#include "core/sweep/sweep.h"
#include "nodes/values.h"

namespace procex {

struct Extrusion {
  TaggedMesh mesh;
  std::vector<std::string> notes;  // repairs made by prepare_footprint
};

// Throws what prepare_footprint, sweep and build_mesh throw (InputError,
// SweepError, MeshError).
Extrusion extrude(const Footprint& footprint, const SweepOptions& options);

}  // namespace procex

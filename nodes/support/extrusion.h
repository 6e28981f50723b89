// Extrusion as the Extrude node runs it: prepare the footprint, sweep it,
// build the mesh and tag every face.
//
// The sweep does not follow profiles yet. Until it does, engine_input() stands
// in: each edge with a profile leans at its profile's first segment and the
// sweep is capped at the highest profile top; faces take that segment's tag.
// The engine gets plain angles, no profiles. When it follows profiles,
// engine_input() goes away (the footprint goes to sweep() with its profiles)
// and the faces' segment tags come from the surface.
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
  std::vector<std::string> notes;  // repairs made by prepare_footprint and stand-ins taken
};

// Throws what prepare_footprint, sweep and build_mesh throw (InputError,
// SweepError, MeshError).
Extrusion extrude(const Footprint& footprint, const SweepOptions& options);

}  // namespace procex

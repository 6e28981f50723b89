// A building's coarser levels of detail, made from its closed mesh as CityGML
// counts them: LOD0 its footprint, LOD1 a block of the same volume.
#pragma once

#include "core/mesh/mesh.h"

namespace procex {

// The faces the building stands on (FaceKind::Base), turned to face up: a
// plan seen from above. Empty if it has none.
Mesh footprint_mesh(const Mesh& building);

// The roof's mean height above the footprint: the building's volume over its
// footprint's area, so the footprint raised this high encloses the same
// volume as the building. 0 without a footprint.
double mean_height(const Mesh& building);

// The footprint extruded from its ground up by mean_height: a closed prism
// (faces: base, wall, cap) with the building's volume. Empty without a footprint.
Mesh mean_height_block(const Mesh& building);

}  // namespace procex

// What a "mesh" graph output shows below full detail (ValueType::
// at_level_of_detail, registered in nodes/values.cc): at level 1 each building
// becomes its mean-height block, at 0 its footprint (core/mesh/level_of_detail.h).
// Placed meshes never reach a lower level: Mesh Placement hands its input on
// there (NodeDecl::detail_level).
#pragma once

#include "nodes/values.h"

namespace procex {

MeshSet mesh_set_at_level_of_detail(const MeshSet& set, int level);

}  // namespace procex

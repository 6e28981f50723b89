// What a written building says about where it came from (nodes/values.h
// TaggedMesh labels, written to .glb extras and GeoPackage columns): the
// feature it was made for and the recipe's exposed values. procex eval, batch
// and the studio's export label their meshes here, so a file says the same
// whichever wrote it.
#pragma once

#include "core/io/geojson.h"
#include "graph/graph.h"
#include "nodes/values.h"

namespace procex {

// Marks every part with f's id, index and properties.
void label_parts(MeshSet& meshes, const GeoJsonFeature& f);

// Records the recipe's exposed parameter values on every part (JSON text per
// name), so a building says what made it.
void label_parameters(MeshSet& meshes, const Graph& graph);

}  // namespace procex

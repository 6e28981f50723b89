// The value types the building nodes pass along links, registered with the
// graph's value registry in values.cc: "footprint" (core Footprint, profiles
// included), "profile", "list<profile>", "anchor" (an AnchorSpec for Extrude),
// "plan edit" (a PlanEditSpec for Extrude) and "mesh" (a MeshSet: building meshes with their resolved anchors and the
// meshes placed on them).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/geom/anchor.h"
#include "core/geom/footprint.h"
#include "core/geom/plan_edit.h"
#include "core/geom/profile.h"
#include "core/mesh/material.h"
#include "core/mesh/mesh.h"
#include "core/placement/facade_split.h"
#include "core/placement/placement.h"

namespace procex {

// One closed mesh whose faces carry a tag ("wall", "roof", ...), belonging to
// one building. The mesh is shared: merging and copying parts copies no geometry.
struct TaggedMesh {
  std::shared_ptr<const Mesh> mesh;
  std::vector<std::uint32_t> face_tags;  // per face (by index): an index into tags
  std::vector<std::string> tags;         // distinct tag names, in order of first use
  // The tags' materials (a Material node's, a placed mesh's own where
  // flattening joined it in), beside the mesh and shared like it: a new look
  // is a new table, never a copy of the geometry.
  MaterialTable materials;
  std::string building;                  // building id ("" when not bound)
  std::int64_t feature = -1;             // the building's position in its GeoJSON file (batch), else -1
  // Written to glTF extras: the feature's GeoJSON properties and the
  // recipe's exposed values, each value as compact JSON text.
  std::map<std::string, std::string> properties, parameters;
  // Where the sweep resolved the footprint's anchors on this mesh (Extrude),
  // in the same coordinates as the mesh: what Mesh placement places at.
  std::vector<ResolvedAnchor> anchors;
  // Facade tiles on this mesh (Facade Split), in the mesh's coordinates: what
  // Mesh placement's `tiles` mode places in. Shared like the mesh and never
  // changed in place (a node that moves or adds tiles makes a new vector):
  // a node after the split (each Material) copied a building's hundreds of
  // tiles per building (BENCHMARKS, Batch). Null: none (tiles_of).
  std::shared_ptr<const std::vector<FacadeTile>> tiles;
  // The names of the Facade Splits this mesh went through, also those that
  // kept no tile on it (no street front): a name Mesh placement asks for that
  // is none of them is a misspelling, not a building without such walls.
  std::set<std::string> split_names;
  // Meshes placed on this one (windows, chimneys), kept as instances
  // (placed.building is null; transforms in the mesh's coordinates): .glb
  // files instance them, OBJ and PLY get them flattened into the mesh.
  PlacementResult placed;
};

// What "mesh" links carry: any number of tagged meshes (one Extrude makes one,
// Merge concatenates).
struct MeshSet {
  std::vector<TaggedMesh> parts;
};

// An anchor as the Anchor node makes it: the edges it selects name their
// profile by Profile::name (empty: every edge, whatever its profile), which
// Extrude resolves against its footprint's profiles into anchor.profile.
struct AnchorSpec {
  Anchor anchor;
  std::string profile;
};

// Plan edits as the Plan Edit node makes them: where (`at`, placed like an
// anchor) and the steps there (copies side by side differ in offset). Their
// inserted edges' profiles index `profiles`, which Extrude adds to its
// footprint's; Extrude sets each edit's anchor from `at`.
struct PlanEditSpec {
  AnchorSpec at;
  std::vector<PlanEdit> edits;
  std::vector<Profile> profiles;
};

// Sets part.face_tags from its mesh's face tags, adding to part.tags those it lacks.
void face_tags_from_mesh(TaggedMesh& part);

// A part's facade tiles; empty if it has none.
const std::vector<FacadeTile>& tiles_of(const TaggedMesh& part);

// The tag of face f of a part.
inline const std::string& face_tag(const TaggedMesh& part, std::size_t f) { return part.tags[part.face_tags[f]]; }

}  // namespace procex

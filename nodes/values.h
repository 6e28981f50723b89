// The value types the building nodes pass along links, registered with the
// graph's value registry in values.cc: "footprint" (core Footprint, profiles
// included), "profile", "list<profile>" and "mesh" (a MeshSet).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/geom/footprint.h"
#include "core/geom/profile.h"
#include "core/mesh/mesh.h"

namespace procex {

// One closed mesh whose faces carry a tag ("wall", "roof", ...), belonging to
// one building. The mesh is shared: merging and copying parts copies no geometry.
struct TaggedMesh {
  std::shared_ptr<const Mesh> mesh;
  std::vector<std::uint32_t> face_tags;  // per face (by index): an index into tags
  std::vector<std::string> tags;         // distinct tag names, in order of first use
  std::string building;                  // building id ("" when not bound)
  std::int64_t feature = -1;             // the building's position in its GeoJSON file (batch), else -1
};

// What "mesh" links carry: any number of tagged meshes (one Extrude makes one,
// Merge concatenates).
struct MeshSet {
  std::vector<TaggedMesh> parts;
};

// The tag of face f of a part.
inline const std::string& face_tag(const TaggedMesh& part, std::size_t f) { return part.tags[part.face_tags[f]]; }

}  // namespace procex

// preview_mesh.h -- evaluation results turned into what the 3D preview draws:
// triangles coloured by face tag and the polygon edges for the wireframe.
// Built on the evaluation thread so the UI thread only uploads buffers.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh/mesh.h"
#include "graph/value.h"
#include "nodes/values.h"

namespace procex::studio {

// One face tag of the preview and how much of the mesh carries it.
struct TagSummary {
  std::string name;
  glm::vec3 color{0.0f};
  std::size_t faces = 0;
  double area = 0.0;       // total area of its faces
  double area_up = 0.0;    // of which faces whose normal has a positive z component
};

struct PreviewMesh {
  // Interleaved per vertex: position xyz, normal xyz, colour rgb (flat shaded:
  // every triangle has its own three vertices).
  std::vector<float> vertices;
  // Polygon edges (not the triangulation's diagonals): pairs of xyz points.
  std::vector<float> edge_points;
  std::vector<TagSummary> tags;  // sorted by name
  glm::dvec3 min{0.0}, max{0.0};
  std::size_t meshes = 0, faces = 0;

  static constexpr std::size_t kFloatsPerVertex = 9;
  std::size_t vertex_count() const { return vertices.size() / kFloatsPerVertex; }
  bool empty() const { return vertices.empty(); }
  const TagSummary* tag(std::string_view name) const;
};

// The tagged meshes inside a value of type "mesh" (a MeshSet); empty for any
// other type.
std::vector<const TaggedMesh*> meshes_in(const Value& v);

// Triangulates every face (non-convex faces through core's convex partition).
PreviewMesh make_preview(const std::vector<const TaggedMesh*>& meshes);

// The tag a face shows: its tag, or its face kind ("base", "side", "cap")
// when the mesh carries no tags.
std::string preview_tag(const TaggedMesh& part, Mesh::FaceHandle f);

// A stable colour per tag: fixed colours for the common architectural tags,
// a hue from the name's hash for others. Distinct chromaticities, so a lit
// (scaled) colour can still be told apart in a screenshot.
glm::vec3 tag_color(std::string_view tag);

}  // namespace procex::studio

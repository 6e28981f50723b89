// preview_mesh.h -- evaluation results turned into what the 3D preview draws:
// triangles coloured by face tag (or by their material: its colour, times its
// texture where it has one), the polygon edges for the wireframe, the
// meshes placed on the buildings (one set of triangles per distinct placed
// mesh, drawn instanced) and markers at the resolved anchors. Built on the
// evaluation thread so the UI thread only uploads buffers, once per result.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "app/studio/editor/preview_texture.h"
#include "core/io/gltf_write.h"
#include "core/mesh/mesh.h"
#include "graph/value.h"
#include "nodes/values.h"

namespace procex::studio {

// One face tag of the preview and how much of the mesh carries it.
struct TagSummary {
  std::string name;
  glm::vec3 color{0.0f};   // the tag's colour, or its material's (the first mesh's with one)
  int texture = -1;        // its material's texture: an index into PreviewMesh::textures, -1 for none
  std::size_t faces = 0;
  double area = 0.0;       // total area of its faces
  double area_up = 0.0;    // of which faces whose normal has a positive z component
};

// A run of triangle vertices drawn with one texture (or none).
struct PreviewRange {
  std::size_t first = 0, count = 0;  // vertices
  int texture = -1;                  // an index into PreviewMesh::textures, -1 for none
};

// A mesh placed on the buildings (a window model), drawn instanced: its
// triangles once, in its own coordinates, and a transform per placement.
struct PreviewInstances {
  std::vector<float> vertices;    // as PreviewMesh::vertices, in the placed mesh's own coordinates
  std::vector<PreviewRange> ranges;  // of vertices, by texture
  // Per instance: the model matrix (16 floats, column-major; it places the
  // mesh relative to PreviewMesh::origin), then the matrix
  // that carries its normals (the inverse transpose of its 3x3 part, 9 floats).
  std::vector<float> transforms;
  static constexpr std::size_t kFloatsPerInstance = 25;
  std::size_t count() const { return transforms.size() / kFloatsPerInstance; }
};

// A resolved anchor of a shown mesh (present or absent), for the anchor list.
struct PreviewAnchor {
  std::string building;
  ResolvedAnchor anchor;
};

struct PreviewMesh {
  // Interleaved per vertex: position xyz (from `origin`), normal xyz, colour rgb, texture
  // coordinates uv (flat shaded: every triangle has its own three vertices).
  // The texture coordinates are in repeats of the face's texture (metres
  // divided by its material's tile size; v up the image), zero where there is
  // none.
  std::vector<float> vertices;
  std::vector<PreviewRange> ranges;      // of vertices, by texture
  std::vector<PreviewTexture> textures;  // each distinct image once
  // Polygon edges (not the triangulation's diagonals): pairs of xyz points.
  std::vector<float> edge_points;
  std::vector<TagSummary> tags;  // sorted by name; placed meshes' faces included
  glm::dvec3 min{0.0}, max{0.0};  // buildings and placed meshes, in the scene's own coordinates
  // Every position drawn (vertices, edge points, markers, the placed meshes'
  // translations) is relative to this point, the centre of the buildings'
  // bounds: as float32, a coordinate at a UTM northing (5,000,000 m) would
  // snap to half a metre; near the origin it keeps micrometres.
  glm::dvec3 origin{0.0};
  std::size_t meshes = 0, faces = 0;
  std::vector<PreviewInstances> placed;  // one per distinct placed mesh (and instance tag)
  std::size_t instances = 0;
  std::vector<PreviewAnchor> anchors;
  // Markers at the present anchors, in the vertex layout above, drawn over the
  // meshes: a small square on the face (triangles) and the frame's axes
  // along, up and out (lines, red, green, blue).
  std::vector<float> marker_triangles, marker_lines;
  static constexpr glm::vec3 kAnchorColor{1.0f, 0.85f, 0.1f};  // no tag colour is this saturated a yellow

  static constexpr std::size_t kFloatsPerVertex = 11;
  std::size_t vertex_count() const { return vertices.size() / kFloatsPerVertex; }
  bool empty() const { return vertices.empty() && placed.empty(); }
  std::size_t absent_anchors() const;
  const TagSummary* tag(std::string_view name) const;
};

// The tagged meshes inside a value of type "mesh" (a MeshSet); empty for any
// other type.
std::vector<const TaggedMesh*> meshes_in(const Value& v);

// Triangulates every face (non-convex faces through core's convex partition),
// groups the placed instances by mesh and builds the anchor markers.
PreviewMesh make_preview(const std::vector<const TaggedMesh*>& meshes);
// The same for a .glb procex wrote (read by core/io's reader, which refuses
// anything else): its triangles joined back into the faces they were cut
// from, in procex's frame (z up), its placed meshes instanced.
PreviewMesh make_preview(const GltfScene& scene);

// The tag a face shows: its tag, or its face kind ("base", "side", "cap")
// when the mesh carries no tags.
std::string preview_tag(const TaggedMesh& part, Mesh::FaceHandle f);

// A stable colour per tag: fixed colours for the common architectural tags,
// a hue from the name's hash for others. Distinct chromaticities, so a lit
// (scaled) colour can still be told apart in a screenshot.
glm::vec3 tag_color(std::string_view tag);

}  // namespace procex::studio

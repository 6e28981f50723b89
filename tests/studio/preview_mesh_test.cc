// Preview meshes: triangulation keeps every face's area (non-convex faces
// too), tags and bounds are reported, tag colours are stable and distinct.
#include "app/studio/editor/preview_mesh.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/footprint.h"
#include "core/mesh/mesh.h"
#include "core/sweep/sweep.h"

namespace procex::studio {
namespace {

// Area of the preview's triangles.
double triangle_area(const PreviewMesh& p) {
  double area = 0;
  const std::size_t k = PreviewMesh::kFloatsPerVertex;
  for (std::size_t v = 0; v + 2 < p.vertex_count(); v += 3) {
    auto at = [&](std::size_t i) { return glm::dvec3(p.vertices[i * k], p.vertices[i * k + 1], p.vertices[i * k + 2]); };
    area += 0.5 * glm::length(glm::cross(at(v + 1) - at(v), at(v + 2) - at(v)));
  }
  return area;
}

//   (0,8) +----+ (4,8)
//         |    |
//         |    +------+ (10,4)
//         |           |
//   (0,0) +-----------+ (10,0)
TaggedMesh l_block(double height) {
  const Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 8}, {0, 8}}}, 0.0);
  SweepOptions o;
  o.max_height = height;
  TaggedMesh part;
  part.mesh = std::make_shared<const Mesh>(build_mesh(sweep(fp, o)));
  return part;
}

TEST(PreviewMesh, TriangulationKeepsTheAreaOfNonConvexFaces) {
  const TaggedMesh part = l_block(3.0);
  const PreviewMesh p = make_preview({&part});
  // Two L-shaped caps of 56 m2 and walls of perimeter 36 m times 3 m.
  const double expected = 2 * 56.0 + 36.0 * 3.0;
  EXPECT_NEAR(triangle_area(p), expected, 1e-6 * expected);
  double tag_total = 0;
  for (const TagSummary& t : p.tags) tag_total += t.area;
  EXPECT_NEAR(tag_total, expected, 1e-6 * expected);
  EXPECT_EQ(p.min, glm::dvec3(0, 0, 0));
  EXPECT_EQ(p.max, glm::dvec3(10, 8, 3));
  // Untagged faces show their kind; the upward area is the top cap's.
  ASSERT_TRUE(p.tag("cap"));
  EXPECT_NEAR(p.tag("cap")->area_up, 56.0, 1e-9);
  EXPECT_TRUE(p.tag("base"));
  EXPECT_TRUE(p.tag("side"));
  // Every polygon edge once, as a pair of points: 18 edges of the L prism.
  EXPECT_EQ(p.edge_points.size(), 18u * 2 * 3);
}

TEST(PreviewMesh, FaceTagsComeFromTheTaggedMesh) {
  TaggedMesh part = l_block(3.0);
  part.tags = {"wall", "roof"};
  part.face_tags.assign(part.mesh->n_faces(), 0);
  part.face_tags[0] = 1;
  const PreviewMesh p = make_preview({&part});
  ASSERT_EQ(p.tags.size(), 2u);
  EXPECT_EQ(p.tag("roof")->faces, 1u);
  EXPECT_EQ(p.tag("wall")->faces, part.mesh->n_faces() - 1);
  EXPECT_EQ(p.tag("wall")->color, tag_color("wall"));
}

TEST(PreviewMesh, OnlyMeshValuesHaveMeshes) {
  EXPECT_TRUE(meshes_in(Value::make(1.0)).empty());
  EXPECT_TRUE(meshes_in(Value()).empty());
  MeshSet set;
  set.parts.push_back(l_block(2.0));
  set.parts.push_back(l_block(4.0));
  EXPECT_EQ(meshes_in(Value::make(set)).size(), 2u);
}

TEST(TagColor, StableAndDistinguishableByChromaticity) {
  EXPECT_EQ(tag_color("chimney-cap"), tag_color("chimney-cap"));
  const char* names[] = {"wall", "roof", "cap", "eave", "soffit", "window", "dormer", "my-own-tag"};
  for (const char* a : names) {
    for (const char* b : names) {
      if (std::string(a) == b) continue;
      const glm::vec3 ca = tag_color(a), cb = tag_color(b);
      const glm::vec3 na = ca / (ca.r + ca.g + ca.b), nb = cb / (cb.r + cb.g + cb.b);
      EXPECT_GT(glm::length(na - nb), 0.02f) << a << " vs " << b;
    }
  }
}

}  // namespace
}  // namespace procex::studio

// Preview meshes: triangulation keeps every face's area (non-convex faces
// too), tags and bounds are reported, tag colours are stable and distinct.
#include "app/studio/editor/preview_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/geom/footprint.h"
#include "core/io/texture_image.h"
#include "core/mesh/material.h"
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
// moved by `at`.
TaggedMesh l_block(double height, const glm::dvec2& at = {0, 0}) {
  std::vector<glm::dvec2> plan = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 8}, {0, 8}};
  for (glm::dvec2& p : plan) p += at;
  const Footprint fp = make_footprint({plan}, 0.0);
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

// At a UTM position (500 km east, 5,000 km north) float32 steps by half a
// metre: the preview draws from the centre of the bounds, so the block far
// away is drawn with the same numbers as at the origin, and its bounds are
// still where it stands.
TEST(PreviewMesh, PositionsAreDrawnFromTheBoundsCentreSoFarAwayPlansKeepTheirPrecision) {
  const TaggedMesh near = l_block(3.0), far = l_block(3.0, {500000.0, 5000000.0});
  const PreviewMesh a = make_preview({&near}), b = make_preview({&far});
  EXPECT_EQ(a.origin, glm::dvec3(5, 4, 1.5));
  EXPECT_EQ(b.origin, glm::dvec3(500005, 5000004, 1.5));
  EXPECT_EQ(b.min, glm::dvec3(500000, 5000000, 0));
  EXPECT_EQ(b.max, glm::dvec3(500010, 5000008, 3));
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) ASSERT_NEAR(a.vertices[i], b.vertices[i], 1e-6) << "float " << i;
  ASSERT_EQ(a.edge_points.size(), b.edge_points.size());
  for (std::size_t i = 0; i < a.edge_points.size(); ++i) ASSERT_NEAR(a.edge_points[i], b.edge_points[i], 1e-6) << "float " << i;
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

// A 1 x 1 x 1 cube at the origin, its faces tagged "frame", as a placeable mesh.
PlaceableMesh unit_cube(const std::string& name) {
  const Footprint fp = make_footprint({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, 0.0);
  SweepOptions o;
  o.max_height = 1.0;
  auto mesh = std::make_shared<Mesh>(build_mesh(sweep(fp, o)));
  const auto tags = face_tag_property(*mesh);
  for (Mesh::FaceHandle f : mesh->faces()) mesh->property(tags, f) = "frame";
  return {name, std::move(mesh)};
}

TEST(PreviewMesh, PlacedMeshesAreGroupedPerMeshWithOneTransformPerInstance) {
  TaggedMesh part = l_block(3.0);
  const PlaceableMesh window = unit_cube("window");
  part.placed.add_mesh(window);
  // Two plain instances, one scaled by (2, 1, 3) and one retagged: two groups.
  Instance a;
  a.transform = glm::translate(glm::dmat4(1.0), glm::dvec3(1, -1, 0));
  Instance b;
  b.transform = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(20, 0, 0)), glm::dvec3(2, 1, 3));
  Instance c = a;
  c.tag = "glass";
  for (const Instance& in : {a, b, c}) part.placed.add_instance(in);
  const PreviewMesh p = make_preview({&part});
  EXPECT_EQ(p.instances, 3u);
  ASSERT_EQ(p.placed.size(), 2u);
  EXPECT_EQ(p.placed[0].count(), 2u);
  EXPECT_EQ(p.placed[1].count(), 1u);
  // The cube's triangles once per group, in its own coordinates (12 triangles).
  EXPECT_EQ(p.placed[0].vertices.size(), 36 * PreviewMesh::kFloatsPerVertex);
  // Instance b's model matrix, column-major: the translation in floats 12..14, from the preview's origin.
  const float* m = p.placed[0].transforms.data() + PreviewInstances::kFloatsPerInstance;
  EXPECT_FLOAT_EQ(m[0], 2.0f);
  EXPECT_FLOAT_EQ(m[10], 3.0f);
  EXPECT_FLOAT_EQ(m[12], static_cast<float>(20.0 - p.origin.x));
  EXPECT_FLOAT_EQ(m[13], static_cast<float>(0.0 - p.origin.y));
  // Its normal matrix (inverse transpose): x normals shrink by 2, z by 3 (renormalised in the shader).
  EXPECT_FLOAT_EQ(m[16], 0.5f);
  EXPECT_FLOAT_EQ(m[24], 1.0f / 3.0f);
  // Areas per tag count every instance as placed: two unit cubes and a 2 x 1 x 3 box (22 m2).
  ASSERT_TRUE(p.tag("frame"));
  EXPECT_NEAR(p.tag("frame")->area, 6.0 + 22.0, 1e-9);
  EXPECT_NEAR(p.tag("frame")->area_up, 1.0 + 2.0, 1e-9);
  ASSERT_TRUE(p.tag("glass"));
  EXPECT_EQ(p.tag("glass")->faces, 6u);
  EXPECT_EQ(p.tag("glass")->color, tag_color("glass"));
  // Bounds take the placed meshes in: the scaled box reaches x = 22 and z = 3, the others y = -1.
  EXPECT_EQ(p.max, glm::dvec3(22, 8, 3));
  EXPECT_EQ(p.min, glm::dvec3(0, -1, 0));
}

TEST(PreviewMesh, UntaggedPlacedFacesTakeTheMeshName) {
  TaggedMesh part = l_block(3.0);
  PlaceableMesh bare = unit_cube("pillar");
  auto mesh = std::make_shared<Mesh>(*bare.mesh);
  const auto tags = face_tag_property(*mesh);
  for (Mesh::FaceHandle f : mesh->faces()) mesh->property(tags, f) = "";
  bare.mesh = mesh;
  part.placed.add_mesh(bare);
  part.placed.add_instance(Instance{});
  const PreviewMesh p = make_preview({&part});
  ASSERT_TRUE(p.tag("pillar"));
  EXPECT_EQ(p.tag("pillar")->faces, 6u);
}

TEST(PreviewMesh, PresentAnchorsGetMarkersAbsentOnesAreListed) {
  TaggedMesh part = l_block(3.0);
  part.building = "b7";
  ResolvedAnchor present;
  present.name = "door";
  present.edge_id = 0;
  present.present = true;
  present.frame = {{5, 0, 1}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
  ResolvedAnchor absent;
  absent.name = "door";
  absent.edge_id = 3;
  absent.reason = "the edge is gone at 1 m";
  part.anchors = {present, absent};
  const PreviewMesh p = make_preview({&part});
  ASSERT_EQ(p.anchors.size(), 2u);
  EXPECT_EQ(p.absent_anchors(), 1u);
  EXPECT_EQ(p.anchors[0].building, "b7");
  EXPECT_EQ(p.anchors[1].anchor.reason, "the edge is gone at 1 m");
  // One marker: a square (two triangles) in the anchor colour, just off the face, centred on the origin.
  ASSERT_EQ(p.marker_triangles.size(), 6 * PreviewMesh::kFloatsPerVertex);
  glm::dvec3 centre(0.0);
  for (std::size_t v = 0; v < 6; ++v) {
    const float* at = p.marker_triangles.data() + v * PreviewMesh::kFloatsPerVertex;
    EXPECT_LT(p.origin.y + at[1], 0.0);  // in front of the wall y = 0 (outward is -y)
    EXPECT_EQ(glm::vec3(at[6], at[7], at[8]), PreviewMesh::kAnchorColor);
    centre += (p.origin + glm::dvec3(at[0], at[1], at[2])) / 6.0;
  }
  EXPECT_NEAR(centre.x, 5.0, 0.05);
  EXPECT_NEAR(centre.z, 1.0, 0.05);
  // And its three axes: along (red), up (green), out (blue).
  ASSERT_EQ(p.marker_lines.size(), 6 * PreviewMesh::kFloatsPerVertex);
  const float* out_tip = p.marker_lines.data() + 5 * PreviewMesh::kFloatsPerVertex;
  EXPECT_LT(p.origin.y + out_tip[1], -0.3);
}

// A tag with a textured material: its faces are one run drawn with the
// decoded image, coloured by the material, their texture coordinates metres
// divided by the tile size (u round the footprint, v up the wall); the other
// faces one untextured run.
TEST(PreviewMesh, TexturedMaterialsGetTheirImageAndTileScaledCoordinates) {
  Material brick;
  brick.colour = {1.0, 0.5, 0.5};
  brick.texture = std::filesystem::path(PROCEX_SAMPLES) / "textures" / "brick.png";
  brick.image = shared_texture_image(brick.texture);
  brick.tile_size = 2.0;
  TaggedMesh part = l_block(3.0);
  part.materials = material_table({{"side", brick}});
  const PreviewMesh p = make_preview({&part});
  ASSERT_EQ(p.textures.size(), 1u);
  EXPECT_EQ(p.textures[0].width, 64);
  EXPECT_EQ(p.textures[0].rgba.size(), 64u * 64u * 4u);
  ASSERT_NE(p.tag("side"), nullptr);
  EXPECT_EQ(p.tag("side")->texture, 0);
  EXPECT_EQ(p.tag("side")->color, glm::vec3(1.0f, 0.5f, 0.5f));
  EXPECT_EQ(p.tag("cap")->texture, -1);
  ASSERT_EQ(p.ranges.size(), 2u);
  EXPECT_EQ(p.ranges[0].texture, -1);
  EXPECT_EQ(p.ranges[1].texture, 0);
  EXPECT_EQ(p.ranges[0].count + p.ranges[1].count, p.vertex_count());
  const std::size_t k = PreviewMesh::kFloatsPerVertex;
  float u_max = -1e9f, v_max = -1e9f, v_min = 1e9f;
  for (std::size_t v = p.ranges[1].first; v < p.ranges[1].first + p.ranges[1].count; ++v) {
    const float* at = p.vertices.data() + v * k;
    EXPECT_EQ(glm::vec3(at[6], at[7], at[8]), glm::vec3(1.0f, 0.5f, 0.5f));
    u_max = std::max(u_max, at[9]);
    v_min = std::min(v_min, at[10]);
    v_max = std::max(v_max, at[10]);
  }
  EXPECT_NEAR(v_min, 0.0, 1e-6);
  EXPECT_NEAR(v_max, 3.0 / 2.0, 1e-6);   // 3 m walls, 2 m a tile
  EXPECT_NEAR(u_max, 36.0 / 2.0, 1e-5);  // round the 36 m footprint
  for (std::size_t v = 0; v < p.ranges[0].count; ++v) EXPECT_EQ(p.vertices[v * k + 9], 0.0f);
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

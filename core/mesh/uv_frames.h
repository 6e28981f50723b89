// Texture coordinates in metres (world scale), so one tiling facade texture
// keeps its size on every building and lines up across the faces of a wall:
//
//  - a face swept by a footprint edge (wall, roof, soffit) takes u along
//    that edge, measured round its footprint loop from the loop's first
//    edge (so u runs on across corners), and v up the face in its own plane
//    from the height of its lowest point (so v is the height on a wall and
//    runs on from the eave up a roof);
//  - a horizontal face (footprint, cap, ledge) takes plan coordinates,
//    mirrored on faces that look down so no face shows a mirrored texture;
//  - any other face (a placed mesh's) is treated as a wall facing its own way,
//    unless it has texture coordinates of its own (core/mesh/material.h).
//
// (u, v, outward normal) is right-handed on every face: textures are seen
// the right way round from outside.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/mesh/material.h"
#include "core/mesh/mesh.h"

namespace procex {

// uv(p) = (dot(p, u) + offset.x, dot(p, v) + offset.y).
struct UvFrame {
  glm::dvec3 u{1, 0, 0}, v{0, 1, 0};
  glm::dvec2 offset{0, 0};
  glm::dvec2 at(const glm::dvec3& p) const;
};

// One frame per face of the mesh (by index). A face with no area gets the
// plan frame. Source edges come from procex:source_edge and the footprint
// from the faces of kind Base, when the mesh has them.
// Frames take points relative to `origin` (a building's local origin: plan
// coordinates stay small enough for float32 texture coordinates).
std::vector<UvFrame> face_uv_frames(const Mesh& mesh, const glm::dvec3& origin = {0, 0, 0});

// What a flat-shaded, textured export carries beside the positions: each
// face corner's texture coordinates (corners in face order, each face's as
// fv_range walks them; a placed mesh's own where it has them) and each
// face's outward unit normal ((0, 0, 1) for a face with no area). Where the
// mesh has normals of its own, corner_normals holds each corner's (its own,
// else its face's); else it is empty. The OBJ writer and the Python module
// hand on these.
struct SurfaceAttributes {
  std::vector<glm::dvec2> corner_uvs;
  std::vector<glm::dvec3> face_normals;
  std::vector<glm::dvec3> corner_normals;
};
SurfaceAttributes surface_attributes(const Mesh& mesh, const glm::dvec3& origin = {0, 0, 0});

// A corner's own texture coordinates and unit normal (core/mesh/material.h),
// each absent where its face has none (or the property is invalid).
struct CornerAttribute {
  std::optional<glm::dvec2> uv;
  std::optional<glm::dvec3> normal;
};
CornerAttribute corner_attribute(const Mesh& mesh, OpenMesh::HPropHandleT<OpenMesh::Vec2d> uv,
                                 OpenMesh::HPropHandleT<OpenMesh::Vec3d> normal, Mesh::HalfedgeHandle h);

}  // namespace procex

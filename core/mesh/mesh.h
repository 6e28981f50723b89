// The mesh type procex hands out: an OpenMesh polygon mesh in double precision
// whose faces carry where they came from.
#pragma once

#include <string>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "core/mesh/surface.h"

namespace procex {

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

// Names of the persistent face properties every procex mesh carries.
inline constexpr const char* kSourceEdgeProperty = "procex:source_edge";  // int
inline constexpr const char* kFaceKindProperty = "procex:face_kind";      // FaceKind
inline constexpr const char* kFaceTagProperty = "procex:tag";             // std::string

// Turns a surface into a mesh. Faces with holes are split into simple planar
// polygons; every piece keeps its face's kind and source edge. Throws
// MeshError naming the face and its vertices if OpenMesh refuses a face.
Mesh build_mesh(const Surface& surface);

// Per-face property accessors (the properties exist on any mesh build_mesh made).
int source_edge(const Mesh& mesh, Mesh::FaceHandle f);
FaceKind face_kind(const Mesh& mesh, Mesh::FaceHandle f);
const std::string& face_tag(const Mesh& mesh, Mesh::FaceHandle f);

// The property handles themselves, for loops over many faces (each lookup by
// name walks the mesh's property list). Invalid if the mesh lacks them.
OpenMesh::FPropHandleT<int> source_edge_property(const Mesh& mesh);
OpenMesh::FPropHandleT<FaceKind> face_kind_property(const Mesh& mesh);
OpenMesh::FPropHandleT<std::string> face_tag_property(const Mesh& mesh);

// Adds the properties to a mesh made some other way (no-op if present).
void add_face_properties(Mesh& mesh);

// "base", "side" or "cap".
const char* face_kind_name(FaceKind kind);

}  // namespace procex

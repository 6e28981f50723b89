// Writing procex meshes to OBJ and PLY. Files are written atomically (a temp
// file beside the target, then rename), so a reader never sees half a file.
// Failures throw IoError naming the file and the reason. Coordinates are
// metres, +Y up unless `up` says Z (core/io/up_axis.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/io/up_axis.h"
#include "core/mesh/mesh.h"

namespace procex {

// One mesh of a multi-mesh file, e.g. one per footprint feature id.
struct NamedMesh {
  std::string name;  // an OBJ group name; whitespace is replaced by '_'
  const Mesh* mesh = nullptr;
};

// Wavefront OBJ: polygons as they are (not triangulated), coordinates with
// shortest round-trip precision, one "g name" group per mesh, vertices
// numbered across the file.
void write_obj(const std::filesystem::path& path, const Mesh& mesh, UpAxis up = UpAxis::Y);
void write_obj(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes, UpAxis up = UpAxis::Y);

// ASCII PLY (double x y z; faces as int vertex_indices lists with int
// procex_source_edge, uchar procex_face_kind and int procex_tag, the face's
// tag numbered in order of first use and named in "comment procex_tag i name"
// lines, -1 for none). Several meshes are written as one vertex/face list, in
// order, with an int procex_group face property giving the mesh's position in
// the list ("comment procex_group i name").
void write_ply(const std::filesystem::path& path, const Mesh& mesh, UpAxis up = UpAxis::Y);
void write_ply(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes, UpAxis up = UpAxis::Y);

// Chooses the format from the extension (.obj or .ply, case-insensitive);
// throws IoError for any other extension.
void write_mesh_file(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes, UpAxis up = UpAxis::Y);

}  // namespace procex

// Reading a mesh to place (a window, a pillar, a dormer) from a Wavefront OBJ
// file into procex's mesh type, through OpenMesh.
//
// OpenMesh's OBJ reader is lenient: it drops a vertex with a malformed number
// and the faces using it, says nothing useful about where, and keeps single
// precision. So the file is first checked line by line here (every 'v' has
// three finite coordinates, every 'f' at least three distinct vertices that
// exist); OpenMesh then reads exactly the checked 'v' and 'f' lines, and the
// coordinates get their full precision back.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/mesh.h"

namespace procex {

// The mesh in the file, with procex's face properties: each face's tag is
// the material named by the last 'usemtl' before it ("" before any), its
// source edge -1, its kind Side. Texture coordinates, normals, groups and
// material libraries are ignored. Faces are in file order.
//
// Throws IoError naming the file, and the line where there is one, if the
// file cannot be read, is not .obj, is not text, has a malformed 'v' or 'f'
// line, has no faces, or OpenMesh refuses a face. Faces OpenMesh can only add
// by duplicating vertices (more than two faces at an edge, or neighbours
// facing opposite ways) are kept and reported in `warnings` when given
// (OpenMesh also prints "complex edge" on stderr for each). Thread-safe.
Mesh read_mesh_file(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr);
// The same on the file's text already in memory; path names it in messages.
Mesh parse_obj_mesh(std::string_view text, const std::filesystem::path& path,
                    std::vector<std::string>* warnings = nullptr);

}  // namespace procex

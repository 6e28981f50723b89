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
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/material.h"
#include "core/mesh/mesh.h"

namespace procex {

// A file the OBJ names (a material library, a library's texture), given as
// its name joined to the naming file's folder, to the path to read. It
// throws IoError where the file may not be read: every file a recipe's mesh
// names is confined as the recipe's own (base/confined_path.h).
using ReferencedFileResolver = std::function<std::filesystem::path(const std::filesystem::path&)>;

// The mesh in the file, with procex's face properties: each face's tag is
// the material named by the last 'usemtl' before it ("" before any), its
// source edge -1, its kind Side. Faces are in file order. A face whose every
// corner names a 'vt' (a 'vn') keeps them as its corners' texture
// coordinates (unit normals) (core/mesh/material.h). The 'mtllib' libraries
// give the mesh's materials (colour Kd and texture map_Kd, a PNG or JPEG
// image), read through `resolve` and checked always, handed back in
// `materials` when given (the mesh does not carry them); a library that is not there is reported in
// `warnings`, one outside the confinement refused. Groups are ignored.
// read_mesh_file's default resolver confines to the OBJ's folder;
// parse_obj_mesh without one reads no libraries.
//
// Throws IoError naming the file, and the line where there is one, if the
// file cannot be read, is not .obj, is not text, has a malformed 'v', 'vt',
// 'vn' or 'f' line (a corner naming a 'vt' or 'vn' that does not exist), a
// library has a malformed Kd or map_Kd or names a texture that is not a PNG
// or JPEG, has no faces, or OpenMesh refuses a face. Faces OpenMesh can only add
// by duplicating vertices (more than two faces at an edge, or neighbours
// facing opposite ways) are kept and reported in `warnings` when given
// (OpenMesh also prints "complex edge" on stderr for each). Thread-safe.
Mesh read_mesh_file(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
                    const ReferencedFileResolver& resolve = {}, Materials* materials = nullptr);
// The same on the file's text already in memory; path names it in messages.
Mesh parse_obj_mesh(std::string_view text, const std::filesystem::path& path,
                    std::vector<std::string>* warnings = nullptr, const ReferencedFileResolver& resolve = {},
                    Materials* materials = nullptr);

// The files an OBJ names: its material libraries ('mtllib'), and the
// textures a library names ('map_Kd'), each joined to the naming file's
// folder as read_mesh_file joins them before `resolve` confines them. What a
// cache key stamps beside the OBJ, so an edited library or texture is read
// again. Never throws: a file that is not there, no regular file or
// unreadable names nothing (reading it says why).
std::vector<std::filesystem::path> obj_material_libraries(const std::filesystem::path& obj);
std::vector<std::filesystem::path> material_library_textures(const std::filesystem::path& library);

}  // namespace procex

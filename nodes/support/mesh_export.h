// Writing a MeshSet to a file, the format chosen by the extension:
// .obj (one group per mesh, one material per face tag, with a .mtl beside it),
// .ply (core's writer: source edges and face kinds, one group per mesh) or
// .glb (one glTF mesh per building: consecutive parts with the same building
// id and feature join; one primitive per tag; placed meshes instanced; the
// scene georeferenced in ExportOptions::crs if given: core/io/gltf_crs.h) or
// .gpkg (core/io/geopackage_write.h: each building's shell and its faces in
// ExportOptions::crs; placed meshes are left out, a GIS layer holds the
// closed shells) or CityJSON, .json (core/io/cityjson_write.h; .city.json
// is its usual name, likewise without placed meshes). OBJ
// and PLY get placed meshes flattened into their part. glTF is +Y up; OBJ and
// PLY +Y up unless ExportOptions::up says Z (core/io/up_axis.h). Atomic writes;
// IoError naming the file on failure.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/io/gltf_write.h"
#include "core/io/up_axis.h"
#include "core/placement/placement_gltf.h"
#include "nodes/values.h"

namespace procex {

// How the files are written beyond their format.
struct ExportOptions {
  UpAxis up = UpAxis::Y;  // OBJ and PLY (glTF is +Y up by its specification)
  std::string crs;        // .gpkg, .json and .glb: the footprints' CRS (output_crs_problem)
};

void write_mesh_set(const std::filesystem::path& path, const MeshSet& set, const ExportOptions& options = {});

// The glTF form of the parts, in order, consecutive parts of one building
// joined, their placed meshes as instances (each distinct placed mesh once),
// converted through `prototypes` when given (a batch's, shared by its buildings).
GltfScene to_gltf(const MeshSet& set, std::shared_ptr<GltfPrototypeMemo> prototypes = nullptr);

// The part with its placed meshes flattened into its mesh (core flatten():
// instance faces tagged by the instance's tag, else their own, else the
// placed mesh's name) and no placed meshes left; the part itself if it has none.
TaggedMesh flattened(const TaggedMesh& part);

// Whether the extension (case-insensitive) is a mesh format write_mesh_set
// writes, or one of its GIS formats (which need ExportOptions::crs).
bool is_mesh_file(const std::filesystem::path& path);
bool is_gis_file(const std::filesystem::path& path);
// Why `crs` cannot georeference a file of path's format, or nullopt: a
// GeoPackage needs a projected CRS in metres, CityJSON one with an EPSG code,
// a .glb given one a metric one; the other formats carry none.
std::optional<std::string> output_crs_problem(const std::filesystem::path& path, const std::string& crs);
// Every extension write_mesh_set writes, lower case with the dot, for a menu
// or a file chooser: the mesh formats, then the GIS one.
const std::vector<std::string>& export_extensions();

}  // namespace procex

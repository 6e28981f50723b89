// The CRS a .glb's buildings stand in, so a GIS puts them back where their
// footprints were: the scene's extras "crs", the CRS as WKT2 (2019) text,
// which GDAL, PROJ and QGIS read. Each building's node stands at its origin
// (extras "origin": east, north, up in that CRS; its translation is the same
// point in glTF's frame), so a vertex (x, y, z) of its mesh is at
// east = origin[0] + x, north = origin[1] - z, up = origin[2] + y.
#pragma once

#include <filesystem>
#include <string>

#include "core/io/gltf_write.h"

namespace procex {

inline constexpr const char* kGltfCrsKey = "crs";

// Sets the scene's CRS from `crs` (EPSG code, WKT or PROJ string); none when
// crs is empty. Throws IoError naming `path` if crs cannot georeference the
// output (core/io/output_crs.h).
void set_gltf_crs(GltfScene& scene, const std::string& crs, const std::filesystem::path& path);

}  // namespace procex

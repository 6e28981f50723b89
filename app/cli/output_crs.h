// The coordinate reference system a GeoPackage (or .glb) output is in: the one
// the buildings were made in (GeoJsonCollection::crs: the footprints' own
// metric CRS, or the frame procex projected longitude/latitude footprints to;
// core/io/footprint_read.h), else --crs when no footprints are read. Checked
// before any building is evaluated, so a long batch does not fail at its end.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/io/geojson.h"
#include "nodes/support/mesh_export.h"

namespace procex {

// Sets options.crs to the footprints' (may be null); if `output` is a GIS
// file, or a .glb given a CRS, returns why that CRS cannot georeference it.
std::optional<std::string> settle_output_crs(const std::filesystem::path& output, const GeoJsonCollection* footprints,
                                             ExportOptions& options);

}  // namespace procex

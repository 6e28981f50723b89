// The coordinate reference system a GeoPackage output is written in: --crs,
// else the footprints' GeoJSON "crs" member (the 2008 GeoJSON form, e.g.
// {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::32632"}},
// which GDAL writes for projected data; RFC 7946 itself allows only
// longitude/latitude, which procex cannot take as metres). Checked before
// any building is evaluated, so a long batch does not fail at its end.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/io/geojson.h"
#include "nodes/support/mesh_export.h"

namespace procex {

// Fills options.crs from the footprints (may be null) when it is empty; if
// `output` is a GIS file, returns why the CRS cannot georeference it.
std::optional<std::string> settle_output_crs(const std::filesystem::path& output, const GeoJsonCollection* footprints,
                                             ExportOptions& options);

}  // namespace procex

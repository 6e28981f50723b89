// Writing buildings to an OGC GeoPackage through GDAL/OGR, for GIS tools
// (QGIS, ArcGIS, PostGIS via ogr2ogr). Two layers:
//  - `buildings`: one feature per building, its closed shell as a
//    MultiPolygon Z (one polygon per face, outward-facing), with the
//    building's id, its GeoJSON properties as typed columns and measures
//    procex computed (procex_ground, procex_height, procex_volume);
//  - `surfaces`: one Polygon Z per face with its building's id and its tag
//    (wall, roof, base, ...), the semantic surfaces a GIS styles by.
// Coordinates are the footprints' own (metres, z up) in the CRS given, which
// PROJ reads (EPSG code, WKT or PROJ string). The file is built in memory and
// written atomically; its bytes do not depend on the time it was written.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/io/gis_building.h"

namespace procex {

// Throws IoError naming the file on failure (a CRS that cannot georeference
// the output, core/io/output_crs.h, included; nothing is written then).
void write_geopackage(const std::filesystem::path& path, const std::string& crs, const std::vector<GisBuilding>& buildings);

}  // namespace procex

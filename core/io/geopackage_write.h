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
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace procex {

struct GisBuilding {
  std::string id;
  // GeoJSON properties, each value as compact JSON text: a column per name,
  // typed Real, Boolean or String by the values all buildings give it (null
  // leaves the cell empty). Names are kept; one that repeats another
  // ignoring case (SQLite's columns do) or a column procex writes gets _2, _3.
  std::map<std::string, std::string> properties;
  // Its faces, each a polygon (not closed: the first corner is not repeated).
  std::vector<std::vector<glm::dvec3>> faces;
  std::vector<std::string> face_tags;  // per face
  double volume = 0;                   // of the closed shell
};

// Why `crs` cannot georeference procex's output, or nullopt if it can: it
// must be a CRS PROJ knows whose horizontal axes are in metres (a projected
// or local one). A geographic CRS (longitude/latitude) is refused: procex
// computes in metres, and degrees taken as metres are no building.
std::optional<std::string> crs_problem(const std::string& crs);

// Throws IoError naming the file on failure (a CRS crs_problem refuses
// included; nothing is written then).
void write_geopackage(const std::filesystem::path& path, const std::string& crs, const std::vector<GisBuilding>& buildings);

}  // namespace procex

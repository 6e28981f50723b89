// Writing buildings as CityJSON 2.0 (https://www.cityjson.org/specs/2.0.1/),
// the 3D city model format GIS tools (QGIS's CityJSON loader, cjio, ninja,
// cityjson-threejs-loader) read. One "Building" CityObject per building, its
// feature's properties as attributes, with two geometries:
//  - LoD 1.2: its footprint (the faces at its ground facing down) extruded to
//    its highest point, a block model;
//  - LoD 2.2: its closed shells as procex made them (placed meshes left out),
//    each face a semantic surface: GroundSurface (facing down at the ground),
//    OuterCeilingSurface (facing down above it: soffits, overhangs),
//    WallSurface and RoofSurface (the tags "wall" and "roof" say which; other
//    tags by slope: within 10 degrees of vertical is a wall), each surface
//    keeping its tag as "procex_tag".
// One shell is a Solid, several (parts of one building) a MultiSolid.
// Vertices are shared and quantised to millimetres ("transform": scale 0.001,
// translated to the lowest corner). The CRS goes into
// metadata.referenceSystem as its OGC URL, so it must be one with an EPSG code
// (a UTM zone, a national grid): procex's local frame for longitude/latitude
// footprints has none, and --target-crs names one. Written atomically.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/io/gis_building.h"

namespace procex {

// Why `crs` cannot georeference a CityJSON file, or nullopt if it can.
std::optional<std::string> cityjson_crs_problem(const std::string& crs);

// Throws IoError naming the file on failure (a CRS cityjson_crs_problem
// refuses included; nothing is written then).
void write_cityjson(const std::filesystem::path& path, const std::string& crs, const std::vector<GisBuilding>& buildings);

}  // namespace procex

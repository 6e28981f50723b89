// A building as procex's GIS writers take it (core/io/geopackage_write.h,
// core/io/cityjson_write.h): its id, its feature's properties and its closed
// shells' faces with their tags, in metres (x east, y north, z up) in the CRS
// the footprints were built in.
#pragma once

#include <cstddef>
#include <map>
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
  // Where each closed shell (a part of the building) starts in faces: 0 first.
  std::vector<std::size_t> shells;
  double volume = 0;  // of the closed shells
};

}  // namespace procex

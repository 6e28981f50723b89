// The coordinate reference system procex's output is georeferenced in (the
// GeoPackage's layers, the .glb's scene extras): one PROJ knows whose
// horizontal axes are in metres (a projected or local one). A geographic CRS
// (longitude/latitude) is refused: procex computes in metres, and degrees
// taken as metres are no building.
#pragma once

#include <optional>
#include <string>

namespace procex {

// Why `crs` cannot georeference procex's output, or nullopt if it can.
std::optional<std::string> crs_problem(const std::string& crs);

// `crs` as WKT2 (2019), the form GDAL, PROJ and QGIS read back; the problem
// if it cannot georeference the output.
struct OutputCrsText {
  std::string wkt2;
  std::optional<std::string> problem;
};
OutputCrsText output_crs_wkt2(const std::string& crs);

// The EPSG code of `crs` (as PROJ identifies it: "32632"), or nullopt if it
// has none (procex's local transverse Mercator) or PROJ does not know it.
std::optional<std::string> crs_epsg_code(const std::string& crs);

}  // namespace procex

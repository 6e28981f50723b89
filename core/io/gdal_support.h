// What procex's GDAL/OGR readers and writers share: GDAL's messages kept for
// the IoError instead of printed, the drivers registered once, and a CRS read
// the way PROJ reads user input (EPSG code, WKT or PROJ string) with x east
// and y north whatever the CRS's own axis order.
#pragma once

#include <optional>
#include <string>

#include <ogr_spatialref.h>

namespace procex {

// GDAL reports through a global handler that prints to stderr; while this
// object lives, this thread's messages are kept for gdal_reason() instead.
class QuietGdal {
 public:
  QuietGdal();
  ~QuietGdal();
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

// GDAL's last message on this thread, or "GDAL gave no reason".
std::string gdal_reason();

void register_gdal_drivers();

// Sets srs from `crs`; the problem (naming crs) if PROJ does not know it.
std::optional<std::string> read_crs(const std::string& crs, OGRSpatialReference& srs);

// As read_crs, and the problem if the CRS cannot georeference procex's
// output (core/io/output_crs.h): empty, geographic, or not in metres.
std::optional<std::string> read_metric_crs(const std::string& crs, OGRSpatialReference& srs);

// A CRS as WKT2 (2019), the form GeoJsonCollection::crs and the outputs carry;
// nullopt if GDAL cannot write it.
std::optional<std::string> wkt2(const OGRSpatialReference& srs);

}  // namespace procex

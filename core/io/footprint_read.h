// Building footprints from a GIS vector file, into the structure the GeoJSON
// reader gives (core/io/geojson.h), in metres:
//  - .geojson / .json: procex's own reader (line/column errors, depth limits);
//  - anything else through GDAL/OGR, and only with its GeoJSON, ESRI Shapefile,
//    GPKG, FlatGeobuf and OSM drivers (no VRT, no /vsi paths, no network): the
//    layer named (--layer), else the first, or for OSM (.osm, .pbf) the
//    multipolygons with building=*. A Shapefile's field names cut to 10
//    characters get the OSM building keys they were cut from back
//    ("building_l" is "building:levels").
// The CRS the coordinates are in is the file's own (a Shapefile's .prj, a
// GeoPackage's srs, a GeoJSON "crs" member), which --crs replaces. A
// projected CRS in metres is kept as it is; a geographic one (longitude/
// latitude), or one in feet, is projected with PROJ to a transverse Mercator
// centred on the data: scale 1 at the centre, so buildings keep their true
// size (UTM's 0.9996 would make a 100 m building 4 cm short) wherever they
// are, zone edges and poles included. --target-crs (metric) replaces it.
//
// A file that declares no CRS is taken in metres, as procex's own samples
// are, unless every coordinate is a longitude/latitude and every footprint
// would be under 5 cm across as metres: then it is refused, since it is
// almost surely RFC 7946 longitude/latitude and no building is 5 cm wide.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/io/geojson.h"

namespace procex {

struct FootprintReadOptions {
  GeoJsonReadOptions geojson;  // for the GeoJSON reader (edge angles)
  std::string crs;             // the file's CRS, replacing what it declares (--crs)
  std::string target_crs;      // the metric CRS to build in (--target-crs); empty: as above
  std::string layer;           // the layer to read (--layer); empty: the first (OSM: multipolygons)
  // A second file whose LineStrings are streets (--streets; its polygons are
  // not read), in the CRS it declares or `crs`, brought to the footprints' frame.
  std::filesystem::path streets;
  std::string streets_layer;   // its layer (--streets-layer); empty: the first
};

// The footprints in `path` (and its LineStrings, with those of options.streets,
// as GeoJsonCollection::lines), GeoJsonCollection::crs naming the CRS their
// coordinates are now in (empty when none is known). Throws IoError naming the
// file if it cannot be read or its CRS used; a feature that cannot be read or
// projected goes to GeoJsonCollection::errors, naming it.
GeoJsonCollection read_footprints(const std::filesystem::path& path, const FootprintReadOptions& options = {});
// The same with the footprints put in `footprints` (in the frame the
// collection's crs names), not the collection's features: a batch's spool.
GeoJsonCollection read_footprints(const std::filesystem::path& path, const FootprintReadOptions& options,
                                  FeatureStore& footprints);

// The files read_footprints(path) reads: path, and for a Shapefile the
// sidecars beside it (.dbf, .shx, .prj, .cpg, in either case; those missing
// too, since adding one changes what is read). What a cache key hashes.
std::vector<std::filesystem::path> footprint_files(const std::filesystem::path& path);

}  // namespace procex

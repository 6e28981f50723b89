// Footprints handed in from Python, read by the same GeoJSON reader as the
// command line's --footprints: a path to a GeoJSON file, a FeatureCollection,
// Feature or Polygon/MultiPolygon geometry as a dict (what json.load and
// geopandas' __geo_interface__ give), or plain loops (sequences of (x, y),
// outer counter-clockwise, holes clockwise). Problems raise FootprintError
// naming the feature.
#pragma once

#include <pybind11/pybind11.h>

#include "core/geom/footprint.h"
#include "core/io/geojson.h"

namespace procex::python {

// One footprint: a Feature or geometry dict, or a sequence of loops.
GeoJsonFeature feature_from_python(pybind11::handle footprint);

// The inverse: f as a GeoJSON Feature dict (its id, its properties as JSON
// values, its loops as a Polygon or MultiPolygon in the frame they were read
// into), which feature_from_python reads back to the same feature.
pybind11::dict feature_to_python(const GeoJsonFeature& f);

// Many: a path, a FeatureCollection dict, or a sequence of what feature_from_python takes.
// Features that cannot be read are in the result's errors (a batch reports them and goes on).
GeoJsonCollection collection_from_python(pybind11::handle footprints);

// Adds the street lines of `streets` to c.lines, as procex batch --streets
// does: a file's path (any format read_footprints reads; its polygons are not
// read), brought into c's frame, or a FeatureCollection dict in c's own
// coordinates. None adds nothing.
void add_streets(GeoJsonCollection& c, pybind11::handle streets);

// Loops as a sequence of (n, 2) array-likes, in order.
std::vector<std::vector<glm::dvec2>> loops_from_python(pybind11::handle loops);

}  // namespace procex::python

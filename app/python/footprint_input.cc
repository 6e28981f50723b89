#include "app/python/footprint_input.h"

#include <pybind11/numpy.h>

#include "app/python/errors.h"
#include "app/python/python_json.h"
#include "core/io/footprint_read.h"
#include "core/io/io_error.h"

namespace py = pybind11;

namespace procex::python {
namespace {

bool is_path(py::handle h) { return py::isinstance<py::str>(h) || py::hasattr(h, "__fspath__"); }

std::string type_name(py::handle h) { return py::str(h.get_type().attr("__name__")); }

// A Feature or geometry dict (or an object with __geo_interface__) as a
// Feature dict; none for anything else.
py::object as_feature_dict(py::handle h) {
  if (py::hasattr(h, "__geo_interface__")) return as_feature_dict(h.attr("__geo_interface__"));
  if (!py::isinstance<py::dict>(h)) return py::none();
  const py::dict d = py::reinterpret_borrow<py::dict>(h);
  const std::string type = d.contains("type") ? std::string(py::str(d["type"])) : "";
  if (type == "Feature") return d;
  if (type == "Polygon" || type == "MultiPolygon") {
    py::dict feature;
    feature["type"] = "Feature";
    feature["properties"] = py::dict();
    feature["geometry"] = d;
    return feature;
  }
  raise(ErrorKind::Footprint, "a footprint dict must be a GeoJSON Feature or a Polygon or MultiPolygon geometry, not type '" +
                                  type + "'");
}

GeoJsonCollection parse(const std::string& text, const std::string& source) {
  try {
    return parse_geojson(text, {}, source);
  } catch (const IoError& e) {
    raise(ErrorKind::Footprint, e.what());
  }
}

GeoJsonFeature loops_feature(py::handle loops, std::size_t index) {
  GeoJsonFeature f;
  f.index = index;
  f.id = std::to_string(index);
  f.loops = loops_from_python(loops);
  f.polygon_of_loop.assign(f.loops.size(), 0);
  return f;
}

}  // namespace

std::vector<std::vector<glm::dvec2>> loops_from_python(py::handle loops) {
  if (is_path(loops) || !py::isinstance<py::sequence>(loops))
    raise(ErrorKind::Footprint, "loops must be a sequence of (n, 2) point arrays, not a " + type_name(loops));
  std::vector<std::vector<glm::dvec2>> out;
  std::size_t i = 0;
  for (py::handle loop : loops) {
    py::array_t<double, py::array::c_style | py::array::forcecast> a;
    try {
      a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(loop);
    } catch (const py::error_already_set&) {
    }
    if (!a || a.ndim() != 2 || a.shape(1) != 2)
      raise(ErrorKind::Footprint, "loop " + std::to_string(i) + ": expected an (n, 2) array of (x, y) points");
    auto& points = out.emplace_back();
    for (py::ssize_t k = 0; k < a.shape(0); ++k) points.push_back({a.at(k, 0), a.at(k, 1)});
    ++i;
  }
  return out;
}

GeoJsonFeature feature_from_python(py::handle footprint) {
  const py::object feature = as_feature_dict(footprint);
  if (feature.is_none()) return loops_feature(footprint, 0);
  py::dict collection;
  collection["type"] = "FeatureCollection";
  collection["features"] = py::make_tuple(feature);
  GeoJsonCollection c = parse(json_text(collection), "footprint");
  if (!c.errors.empty()) raise(ErrorKind::Footprint, "footprint: " + c.errors.front().message);
  return std::move(c.features.front());
}

py::dict feature_to_python(const GeoJsonFeature& f) {
  // GeoJSON rings repeat their first point at the end; the reader dropped it.
  auto ring = [](const std::vector<glm::dvec2>& loop) {
    py::list points;
    for (const glm::dvec2& p : loop) points.append(py::make_tuple(p.x, p.y));
    if (!loop.empty()) points.append(py::make_tuple(loop.front().x, loop.front().y));
    return points;
  };
  py::list polygons;
  for (std::size_t i = 0; i < f.loops.size(); ++i) {
    const std::size_t polygon = i < f.polygon_of_loop.size() ? f.polygon_of_loop[i] : 0;
    while (py::len(polygons) <= polygon) polygons.append(py::list());
    polygons[polygon].cast<py::list>().append(ring(f.loops[i]));
  }
  py::dict geometry;
  geometry["type"] = py::len(polygons) == 1 ? "Polygon" : "MultiPolygon";
  geometry["coordinates"] = py::len(polygons) == 1 ? py::object(polygons[0]) : py::object(polygons);
  py::dict properties;
  for (const auto& [name, text] : f.properties) properties[py::str(name)] = from_json_text(text);
  py::dict feature;
  feature["type"] = "Feature";
  feature["id"] = f.id;
  feature["properties"] = properties;
  feature["geometry"] = geometry;
  return feature;
}

GeoJsonCollection collection_from_python(py::handle footprints) {
  if (is_path(footprints)) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(footprints));
    try {
      return read_footprints(path);  // any format procex batch reads, projected as it projects them
    } catch (const IoError& e) {
      raise(ErrorKind::Footprint, e.what());
    }
  }
  py::handle source = py::hasattr(footprints, "__geo_interface__") ? footprints.attr("__geo_interface__") : footprints;
  if (py::isinstance<py::dict>(source)) return parse(json_text(source), "footprints");
  if (!py::isinstance<py::sequence>(source))
    raise(ErrorKind::Footprint, "footprints must be a footprint file's path (GeoJSON, Shapefile, GeoPackage, FlatGeobuf, OSM), a FeatureCollection or a sequence of footprints, not a " +
                                    type_name(footprints));
  // Features go through the GeoJSON reader together, as one collection; loops are read here.
  py::list features;
  GeoJsonCollection c;
  for (py::handle item : source) {
    if (py::object f = as_feature_dict(item); !f.is_none()) features.append(f);
    else c.features.push_back(loops_feature(item, c.features.size()));
  }
  if (!features.empty() && !c.features.empty())
    raise(ErrorKind::Footprint, "footprints: give either GeoJSON features or loops, not both in one sequence");
  if (!features.empty()) {
    py::dict collection;
    collection["type"] = "FeatureCollection";
    collection["features"] = features;
    c = parse(json_text(collection), "footprints");
  }
  return c;
}

void add_streets(GeoJsonCollection& c, py::handle streets) {
  if (streets.is_none()) return;
  GeoJsonCollection more;
  if (is_path(streets)) {
    FootprintReadOptions read;
    read.target_crs = c.crs;
    try {
      more = read_footprints(std::string(py::str(py::module_::import("os").attr("fspath")(streets))), read);
    } catch (const IoError& e) {
      raise(ErrorKind::Footprint, e.what());
    }
  } else {
    py::handle source = py::hasattr(streets, "__geo_interface__") ? streets.attr("__geo_interface__") : streets;
    if (!py::isinstance<py::dict>(source))
      raise(ErrorKind::Footprint, "streets must be a file's path or a FeatureCollection of LineStrings, not a " +
                                      type_name(streets));
    more = parse(json_text(source), "streets");
  }
  c.lines.insert(c.lines.end(), std::make_move_iterator(more.lines.begin()), std::make_move_iterator(more.lines.end()));
}

}  // namespace procex::python

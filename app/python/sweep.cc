// procex.sweep: the engine alone, as the Extrude node runs it (nodes/support/extrusion.h).
#include "app/python/sweep.h"

#include <map>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "app/python/errors.h"
#include "app/python/footprint_input.h"
#include "app/python/mesh_arrays.h"
#include "nodes/support/extrusion.h"

namespace py = pybind11;

namespace procex::python {
namespace {

// A profile: an (m, 2) array of (outward offset, height) points from (0, 0),
// or a dict {"points": ..., "tags": [one per segment], "name": ...}.
Profile profile_from_python(py::handle h, const std::string& fallback_name) {
  Profile p;
  p.name = fallback_name;
  py::handle points = h;
  if (py::isinstance<py::dict>(h)) {
    const py::dict d = py::reinterpret_borrow<py::dict>(h);
    if (!d.contains("points")) raise(ErrorKind::Footprint, fallback_name + ": a profile dict needs 'points'");
    points = d["points"];
    if (d.contains("name")) p.name = py::str(d["name"]);
    if (d.contains("tags")) p.tags = d["tags"].cast<std::vector<std::string>>();
  }
  const auto loops = loops_from_python(py::make_tuple(points));
  for (const glm::dvec2& q : loops.front()) p.points.push_back(q);
  if (p.tags.empty()) p.tags.assign(p.segments(), "");
  return p;
}

bool is_one_profile(py::handle h) {
  if (py::isinstance<py::dict>(h)) return true;
  try {
    const auto a = py::array_t<double, py::array::forcecast>::ensure(h);
    return a && a.ndim() == 2 && a.shape(1) == 2;
  } catch (const py::error_already_set&) {
    return false;
  }
}

// `per_edge` is None, one value for every edge, or one sequence per loop with
// one entry per edge; calls set(loop, edge, value) for each edge it gives.
template <class Set>
void per_edge(const char* what, py::handle values, const Footprint& fp, bool one, Set set) {
  if (values.is_none()) return;
  if (one) {
    for (std::size_t l = 0; l < fp.loops.size(); ++l)
      for (std::size_t e = 0; e < fp.loops[l].edges.size(); ++e) set(l, e, values);
    return;
  }
  const auto loops = values.cast<std::vector<py::object>>();
  if (loops.size() != fp.loops.size())
    raise(ErrorKind::Footprint, std::string(what) + ": " + std::to_string(loops.size()) + " lists for " +
                                    std::to_string(fp.loops.size()) + " loops (give one per loop, one entry per edge)");
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto edges = loops[l].cast<std::vector<py::object>>();
    if (edges.size() != fp.loops[l].edges.size())
      raise(ErrorKind::Footprint, std::string(what) + ": loop " + std::to_string(l) + " has " +
                                      std::to_string(fp.loops[l].edges.size()) + " edges, given " +
                                      std::to_string(edges.size()));
    for (std::size_t e = 0; e < edges.size(); ++e) set(l, e, edges[e]);
  }
}

std::shared_ptr<MeshArrays> sweep(py::handle loops, py::handle angles, py::handle profiles, py::handle max_height) {
  Footprint fp = make_footprint(loops_from_python(loops), 45.0);
  per_edge("angles", angles, fp, py::isinstance<py::float_>(angles) || py::isinstance<py::int_>(angles),
           [&](std::size_t l, std::size_t e, py::handle v) { fp.loops[l].edges[e].angle_deg = v.cast<double>(); });
  std::map<PyObject*, int> profile_of;  // the same Python object is one profile
  per_edge("profiles", profiles, fp, is_one_profile(profiles), [&](std::size_t l, std::size_t e, py::handle v) {
    if (v.is_none()) return;
    auto [it, inserted] = profile_of.try_emplace(v.ptr(), static_cast<int>(fp.profiles.size()));
    if (inserted) fp.profiles.push_back(profile_from_python(v, "profile " + std::to_string(fp.profiles.size())));
    fp.loops[l].edges[e].profile = it->second;
  });
  SweepOptions options;
  if (!max_height.is_none()) options.max_height = max_height.cast<double>();
  Extrusion extrusion;
  {
    py::gil_scoped_release release;
    try {
      extrusion = extrude(fp, options);
    } catch (const std::exception& e) {
      raise_core(e);
    }
  }
  for (const std::string& note : extrusion.notes)
    if (PyErr_WarnEx(PyExc_UserWarning, ("procex.sweep: " + note).c_str(), 1) != 0) throw py::error_already_set();
  PlaceableCache placeables;  // a sweep places nothing
  return wrap(std::move(extrusion.mesh), placeables);
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("loops"), py::arg("angles") = py::none(), py::arg("profiles") = py::none(),
        py::arg("max_height") = py::none(),
        "The sweep-plane engine alone (procedural extrusions): loops of (x, y) points (outer counter-clockwise, holes "
        "clockwise; orientation is repaired with a warning) to one closed mesh. angles: degrees from the vertical, one "
        "number for every edge (default 45) or one list per loop with one per edge. profiles: one profile for every "
        "edge or one list per loop with one per edge (None: the edge's angle); a profile is an (m, 2) array of "
        "(outward offset, height) points from (0, 0), or a dict with points, tags (one per segment) and name. "
        "max_height caps the sweep with flat faces. Faces are tagged by their profile segment (wall or roof by angle "
        "without one), base and cap. Raises FootprintError (loop, vertex), SweepError (height, edges), MeshError.");
}

}  // namespace procex::python

#include "app/python/mesh_arrays.h"

#include "core/mesh/material.h"

#include <map>

#include <pybind11/numpy.h>
#include <pybind11/pytypes.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace procex::python {
namespace {

void lay_out_faces(MeshArrays& m) {
  const Mesh& mesh = *m.mesh;
  m.face_offsets.reserve(mesh.n_faces() + 1);
  m.face_indices.reserve(mesh.n_halfedges() / 2);
  m.face_offsets.push_back(0);
  for (const auto f : mesh.faces()) {
    for (const auto v : mesh.fv_range(f)) m.face_indices.push_back(v.idx());
    m.face_offsets.push_back(static_cast<std::int32_t>(m.face_indices.size()));
  }
}

// A placed mesh's faces keep their own tag; untagged ones take the mesh's name.
std::shared_ptr<MeshArrays> wrap_placeable(const PlaceableMesh& placeable) {
  auto m = std::make_shared<MeshArrays>();
  m->mesh = placeable.mesh;
  m->materials = placeable.materials;
  m->name = placeable.name;
  const auto tag_property = face_tag_property(*m->mesh);
  std::map<std::string, std::uint32_t, std::less<>> index;
  m->face_tags.reserve(m->mesh->n_faces());
  for (const auto f : m->mesh->faces()) {
    const std::string& own = tag_property.is_valid() ? m->mesh->property(tag_property, f) : placeable.name;
    const std::string& tag = own.empty() ? placeable.name : own;
    const auto [it, inserted] = index.try_emplace(tag, static_cast<std::uint32_t>(m->tags.size()));
    if (inserted) m->tags.push_back(tag);
    m->face_tags.push_back(it->second);
  }
  lay_out_faces(*m);
  return m;
}

// A read-only array over `data`, kept alive by `owner`.
template <class T>
py::array view(const T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  std::vector<py::ssize_t> strides(shape.size(), sizeof(T));
  for (std::size_t i = shape.size() - 1; i > 0; --i) strides[i - 1] = strides[i] * shape[i];
  py::array a(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

template <class T>
py::array view(const std::vector<T>& v, py::handle owner) {
  return view(v.data(), {static_cast<py::ssize_t>(v.size())}, owner);
}

// (n, N) float64 over n glm vectors of N doubles.
template <glm::length_t N>
py::array rows(const std::vector<glm::vec<N, double>>& v, py::handle owner) {
  static_assert(sizeof(glm::vec<N, double>) == N * sizeof(double));
  return view(reinterpret_cast<const double*>(v.data()), {static_cast<py::ssize_t>(v.size()), N}, owner);
}

py::array matrix(const glm::dmat4& t) {
  py::array_t<double> a({4, 4});
  auto r = a.mutable_unchecked<2>();
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) r(row, col) = t[col][row];  // glm is column-major
  return a;
}

MeshArrays& self_of(py::handle self) { return *self.cast<std::shared_ptr<MeshArrays>>(); }

const SurfaceAttributes& surface_of(py::handle self) {
  MeshArrays& m = self_of(self);
  if (!m.surface) m.surface = surface_attributes(*m.mesh);
  return *m.surface;
}

}  // namespace

std::shared_ptr<MeshArrays> PlaceableCache::get(const PlaceableMesh& placeable) {
  const std::tuple<const Mesh*, std::string, const Materials*> key{placeable.mesh.get(), placeable.name,
                                                                   placeable.materials.get()};
  {
    std::lock_guard lock(mutex_);
    if (auto found = wrapped_.find(key); found != wrapped_.end()) return found->second;
  }
  // Wrapped outside the lock; two threads wrapping the same mesh at once keep the first.
  std::shared_ptr<MeshArrays> made = wrap_placeable(placeable);
  std::lock_guard lock(mutex_);
  return wrapped_.try_emplace(key, std::move(made)).first->second;
}

std::shared_ptr<MeshArrays> wrap(TaggedMesh part, PlaceableCache& placeables) {
  auto m = std::make_shared<MeshArrays>();
  m->mesh = std::move(part.mesh);
  m->face_tags = std::move(part.face_tags);
  m->tags = std::move(part.tags);
  m->materials = std::move(part.materials);
  m->building = std::move(part.building);
  m->feature = part.feature;
  lay_out_faces(*m);
  std::vector<std::shared_ptr<MeshArrays>> wrapped;
  for (const PlaceableMesh& p : part.placed.meshes) wrapped.push_back(placeables.get(p));
  m->placed.reserve(part.placed.instances.size());
  for (const Instance& i : part.placed.instances)
    m->placed.push_back({wrapped[i.mesh], i.transform, i.tag, i.source_edge});
  return m;
}

WrappedMeshes wrap_all(MeshSet set, PlaceableCache& placeables) {
  WrappedMeshes out;
  out.reserve(set.parts.size());
  for (TaggedMesh& part : set.parts) out.push_back(wrap(std::move(part), placeables));
  return out;
}

WrappedMeshes wrap_all(MeshSet set) {
  PlaceableCache placeables;
  return wrap_all(std::move(set), placeables);
}

py::list to_list(const WrappedMeshes& meshes) {
  py::list out(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) out[i] = py::cast(meshes[i]);
  return out;
}

void bind_mesh(py::module_& m) {
  // Both classes exist before either's methods, so their signatures name each other by Python name.
  py::class_<MeshArrays, std::shared_ptr<MeshArrays>> mesh_class(
      m, "Mesh",
      "A closed polygon mesh whose faces carry a tag (wall, roof, ...). The arrays are read-only views of procex's "
      "own storage where they can be (vertices, face_tags, source_edges, face_kinds) and hold the mesh alive.");
  py::class_<Placement> placement_class(m, "Placement",
                        "A mesh placed on a building (a window at an anchor, a chimney): the mesh, shared by every "
                        "placement of it, and the 4x4 matrix taking its coordinates to the building's. Unpacks as "
                        "(mesh, matrix).");
  placement_class.def_property_readonly("mesh", [](const Placement& p) { return p.mesh; })
      .def_property_readonly("matrix", [](const Placement& p) { return matrix(p.transform); },
                             "4x4 float64, row-major: world = matrix @ (x, y, z, 1).")
      .def_readonly("tag", &Placement::tag, "When not empty, the tag of every face of this placement.")
      .def_readonly("source_edge", &Placement::source_edge, "The footprint edge it stands on, -1 if none.")
      .def("__iter__", [](const Placement& p) { return py::iter(py::make_tuple(p.mesh, matrix(p.transform))); })
      .def("__repr__", [](const Placement& p) {
        return "<procex.Placement of " + std::to_string(p.mesh->mesh->n_faces()) + " faces" +
               (p.tag.empty() ? "" : ", tag " + p.tag) + ">";
      });

  mesh_class.def_property_readonly(
          "vertices",
          [](py::object self) {
            const Mesh& mesh = *self_of(self).mesh;
            static_assert(sizeof(Mesh::Point) == 3 * sizeof(double));
            return view(mesh.points()->data(), {static_cast<py::ssize_t>(mesh.n_vertices()), 3}, self);
          },
          "(n_vertices, 3) float64, a view without a copy.")
      .def_property_readonly(
          "face_offsets", [](py::object self) { return view(self_of(self).face_offsets, self); },
          "(n_faces + 1,) int32: face f's vertex indices are face_indices[face_offsets[f]:face_offsets[f + 1]], "
          "counter-clockwise seen from outside.")
      .def_property_readonly(
          "face_indices", [](py::object self) { return view(self_of(self).face_indices, self); },
          "int32 vertex indices of every face, face after face.")
      .def_property_readonly(
          "face_tags", [](py::object self) { return view(self_of(self).face_tags, self); },
          "(n_faces,) uint32: index into tags of each face's tag.")
      .def_property_readonly("tags", [](const MeshArrays& a) { return a.tags; }, "The distinct tag names.")
      .def_property_readonly(
          "uvs", [](py::object self) { return rows(surface_of(self).corner_uvs, self); },
          "(len(face_indices), 2) float64: each face corner's texture coordinates in metres, in face_indices' order "
          "(as OBJ vt): on a face swept by a footprint edge u runs along the edge round the footprint and v up the "
          "face from its lowest point (on a wall, the height); horizontal faces take plan coordinates (mirrored on "
          "faces seen from below). Made on first read, then a view.")
      .def_property_readonly(
          "normals", [](py::object self) { return rows(surface_of(self).face_normals, self); },
          "(n_faces, 3) float64: each face's outward unit normal (flat shading, as OBJ vn); (0, 0, 1) for a face "
          "without area. Made on first read, then a view.")
      .def_property_readonly(
          "source_edges",
          [](py::object self) {
            const Mesh& mesh = *self_of(self).mesh;
            const auto h = source_edge_property(mesh);
            if (!h.is_valid()) return view(static_cast<const std::int32_t*>(nullptr), {0}, self);
            return view(mesh.property(h).data_vector(), self);
          },
          "(n_faces,) int32: the footprint edge id that swept each face, -1 for base and cap faces; empty for a "
          "mesh read from a file.")
      .def_property_readonly(
          "face_kinds",
          [](py::object self) {
            const Mesh& mesh = *self_of(self).mesh;
            const auto h = face_kind_property(mesh);
            if (!h.is_valid()) return view(static_cast<const std::uint8_t*>(nullptr), {0}, self);
            static_assert(sizeof(FaceKind) == 1);
            return view(reinterpret_cast<const std::uint8_t*>(mesh.property(h).data_vector().data()),
                        {static_cast<py::ssize_t>(mesh.n_faces())}, self);
          },
          "(n_faces,) uint8: 0 base (the footprint, facing down), 1 side, 2 cap; empty for a mesh read from a file.")
      .def_readonly("name", &MeshArrays::name, "A placed mesh's name (its file's stem); empty for a building's mesh.")
      .def_readonly("building", &MeshArrays::building, "The building (GeoJSON feature) id, empty when none is bound.")
      .def_readonly("feature", &MeshArrays::feature, "The feature's index in its GeoJSON file, -1 when none.")
      .def_property_readonly(
          "materials",
          [](const MeshArrays& a) {
            py::dict out;
            for (const auto& [tag, material] : materials_of(a.materials))
              out[py::str(tag)] = py::dict(
                  py::arg("colour") = py::make_tuple(material.colour[0], material.colour[1], material.colour[2]),
                  py::arg("roughness") = material.roughness, py::arg("metallic") = material.metallic,
                  py::arg("texture") = material.texture.empty() ? py::object(py::none()) : py::str(material.texture.string()),
                  py::arg("tile_size") = material.tile_size);
            return out;
          },
          "The mesh's materials by tag (a Material node's, or a placed mesh's own from its OBJ's .mtl): {tag: "
          "{'colour': (r, g, b) linear, 'roughness': 0..1, 'metallic': 0..1, 'texture': the absolute path of its "
          "image, or None, 'tile_size': the texture coordinates one repeat of the image covers (metres on a "
          "building's faces)}}; tags without one are absent (they show their tag colour).")
      .def_property_readonly("placed", [](const MeshArrays& a) { return a.placed; },
                             "The meshes placed on this one, as a list of Placement (mesh, matrix).")
      .def_property_readonly("n_vertices", [](const MeshArrays& a) { return a.mesh->n_vertices(); })
      .def_property_readonly("n_faces", [](const MeshArrays& a) { return a.mesh->n_faces(); })
      .def("__repr__", [](const MeshArrays& a) {
        return "<procex.Mesh " + (a.building.empty() ? "" : a.building + " ") + std::to_string(a.mesh->n_vertices()) +
               " vertices, " + std::to_string(a.mesh->n_faces()) + " faces, " + std::to_string(a.placed.size()) +
               " placed>";
      });
}

}  // namespace procex::python

#include "core/io/gltf_write.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include <tiny_gltf.h>

#include "core/geom/convex_partition.h"
#include "core/geom/polygon3.h"
#include "core/io/atomic_write.h"
#include "core/io/io_error.h"
#include "core/placement/placement.h"
#include "core/placement/trs_split.h"

namespace procex {
namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUint = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// The buffer holds three views, each tightly packed: every position, then every
// normal (both vertex attributes), then every index; accessors point into them.
// Three views instead of three per primitive keep the JSON small for whole cities.
struct Layout {
  std::size_t positions = 0, normals = 0, indices = 0;  // byte offsets of the views
  std::size_t end = 0;
};

Layout layout_of(const std::vector<GltfMeshData>& meshes, const std::vector<const GltfMeshData*>& prototypes) {
  std::size_t floats = 0, indices = 0;
  const auto count = [&](const GltfMeshData& mesh) {
    for (const GltfPrimitiveData& p : mesh.primitives)
      if (!p.indices.empty()) floats += p.positions.size(), indices += p.indices.size();
  };
  for (const GltfMeshData* p : prototypes) count(*p);
  for (const GltfMeshData& mesh : meshes) count(mesh);
  Layout l;
  l.normals = floats * sizeof(float);
  l.indices = 2 * l.normals;
  l.end = l.indices + indices * sizeof(std::uint32_t);
  return l;
}

template <class T>
std::size_t append(std::vector<unsigned char>& buffer, std::size_t at, const std::vector<T>& data) {
  std::memcpy(buffer.data() + at, data.data(), data.size() * sizeof(T));
  return at + data.size() * sizeof(T);
}

int add_accessor(tinygltf::Model& m, int view, std::size_t offset, int component, int type, std::size_t count) {
  tinygltf::Accessor& a = m.accessors.emplace_back();
  a.bufferView = view;
  a.byteOffset = offset;
  a.componentType = component;
  a.type = type;
  a.count = count;
  return static_cast<int>(m.accessors.size() - 1);
}

void add_material(tinygltf::Model& m, const std::string& tag) {
  tinygltf::Material& mat = m.materials.emplace_back();
  mat.name = tag;
  const auto c = tag_colour(tag);
  mat.pbrMetallicRoughness.baseColorFactor = {c[0], c[1], c[2], 1.0};
  mat.pbrMetallicRoughness.metallicFactor = 0.0;
  mat.pbrMetallicRoughness.roughnessFactor = 0.9;
}

// Where the next primitive's data goes in the buffer, and the materials made so far.
struct Writing {
  tinygltf::Model& m;
  std::size_t starts[3], at[3];
  std::map<std::string, int> materials;
};

// Adds data's primitives as a glTF mesh named `name`; returns its index, or
// -1 when it has no triangles (glTF meshes need a primitive).
int add_mesh(Writing& w, const GltfMeshData& data, const std::string& name) {
  tinygltf::Model& m = w.m;
  tinygltf::Mesh mesh;
  mesh.name = name;
  std::vector<unsigned char>& buffer = m.buffers[0].data;
  for (const GltfPrimitiveData& p : data.primitives) {
    if (p.indices.empty()) continue;
    auto [it, added] = w.materials.try_emplace(p.tag, static_cast<int>(w.materials.size()));
    if (added) add_material(m, p.tag);
    tinygltf::Primitive& prim = mesh.primitives.emplace_back();
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = it->second;
    prim.extras = tinygltf::Value(tinygltf::Value::Object{{"tag", tinygltf::Value(p.tag)}});
    const std::size_t n = p.positions.size() / 3;
    const int pos = add_accessor(m, 0, w.at[0] - w.starts[0], kFloat, TINYGLTF_TYPE_VEC3, n);
    std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
      lo[i % 3] = std::min<double>(lo[i % 3], p.positions[i]);
      hi[i % 3] = std::max<double>(hi[i % 3], p.positions[i]);
    }
    m.accessors[static_cast<std::size_t>(pos)].minValues = std::move(lo);
    m.accessors[static_cast<std::size_t>(pos)].maxValues = std::move(hi);
    prim.attributes["POSITION"] = pos;
    prim.attributes["NORMAL"] = add_accessor(m, 1, w.at[1] - w.starts[1], kFloat, TINYGLTF_TYPE_VEC3, n);
    prim.indices = add_accessor(m, 2, w.at[2] - w.starts[2], kUint, TINYGLTF_TYPE_SCALAR, p.indices.size());
    w.at[0] = append(buffer, w.at[0], p.positions);
    w.at[1] = append(buffer, w.at[1], p.normals);
    w.at[2] = append(buffer, w.at[2], p.indices);
  }
  if (mesh.primitives.empty()) return -1;
  m.meshes.push_back(std::move(mesh));
  return static_cast<int>(m.meshes.size() - 1);
}

int add_node(tinygltf::Model& m, tinygltf::Node node) {
  m.nodes.push_back(std::move(node));
  return static_cast<int>(m.nodes.size() - 1);
}

std::vector<double> matrix_values(const glm::dmat4& t) {
  if (t == glm::dmat4(1.0)) return {};  // glTF's default: left out
  std::vector<double> out;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out.push_back(t[c][r]);
  return out;
}

// An instance's node (two when its matrix is not translation * rotation *
// scale); returns the outer one's index.
int add_instance_node(tinygltf::Model& m, const GltfInstanceData& in, const std::string& name, int mesh) {
  tinygltf::Node node;
  node.name = name;
  node.extras = tinygltf::Value(tinygltf::Value::Object{{"tag", tinygltf::Value(in.tag)}});
  if (is_trs(in.transform)) {
    node.matrix = matrix_values(in.transform);
    node.mesh = mesh;
    return add_node(m, std::move(node));
  }
  const TrsSplit split = split_trs(in.transform);
  tinygltf::Node inner;
  inner.name = name;
  inner.matrix = matrix_values(split.inner);
  inner.mesh = mesh;
  node.matrix = matrix_values(split.outer);
  // outer * inner is the transform only to rounding: the exact one rides
  // along, so reading and writing again gives the same bytes.
  tinygltf::Value::Array exact;
  for (double v : matrix_values(in.transform)) exact.emplace_back(v);
  node.extras.Get<tinygltf::Value::Object>()["transform"] = tinygltf::Value(std::move(exact));
  node.children = {add_node(m, std::move(inner))};
  return add_node(m, std::move(node));
}

bool has_triangles(const GltfMeshData& mesh) {
  return std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                     [](const GltfPrimitiveData& p) { return !p.indices.empty(); });
}

void check_instances(const std::filesystem::path& path, const GltfMeshData& building,
                     const std::vector<GltfMeshData>& prototypes) {
  for (std::size_t i = 0; i < building.instances.size(); ++i) {
    const GltfInstanceData& in = building.instances[i];
    const std::string where = "cannot write '" + path.string() + "': instance " + std::to_string(i) + " of building '" +
                              building.building + "'";
    if (in.prototype >= prototypes.size())
      throw IoError(where + " names placed mesh " + std::to_string(in.prototype) + " but there are " +
                        std::to_string(prototypes.size()),
                    path.string());
    if (!has_triangles(prototypes[in.prototype]))
      throw IoError(where + " places a mesh without triangles ('" + prototypes[in.prototype].building + "')",
                    path.string());
    if (const std::string problem = transform_problem(in.transform); !problem.empty())
      throw IoError(where + " has " + problem, path.string());
  }
}

// The placed meshes as written: in order of first use by the buildings'
// instances, equal ones (same name and triangles) once, unused ones left
// out. So the file depends only on what is placed where: a scene merged
// from shards (append_scene) writes the bytes a single run writes.
struct WrittenPrototypes {
  std::vector<const GltfMeshData*> meshes;
  std::vector<std::size_t> slot;  // per given prototype: its position in meshes (if used)
};

WrittenPrototypes written_prototypes(const std::vector<GltfMeshData>& buildings,
                                     const std::vector<GltfMeshData>& prototypes) {
  constexpr std::size_t kUnused = static_cast<std::size_t>(-1);
  WrittenPrototypes out;
  out.slot.assign(prototypes.size(), kUnused);
  for (const GltfMeshData& b : buildings)
    for (const GltfInstanceData& in : b.instances) {
      std::size_t& slot = out.slot[in.prototype];
      if (slot != kUnused) continue;
      const GltfMeshData& p = prototypes[in.prototype];
      const auto same = std::find_if(out.meshes.begin(), out.meshes.end(), [&](const GltfMeshData* q) {
        return q->building == p.building && q->primitives == p.primitives;
      });
      slot = static_cast<std::size_t>(same - out.meshes.begin());
      if (same == out.meshes.end()) out.meshes.push_back(&p);
    }
  return out;
}

tinygltf::Model to_model(const std::filesystem::path& path, const std::vector<GltfMeshData>& meshes,
                         const std::vector<GltfMeshData>& prototypes) {
  for (const GltfMeshData& data : meshes) check_instances(path, data, prototypes);
  const WrittenPrototypes written = written_prototypes(meshes, prototypes);
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = "procex";
  const Layout layout = layout_of(meshes, written.meshes);
  m.scenes.emplace_back();
  m.defaultScene = 0;
  if (layout.end == 0) return m;
  tinygltf::Buffer& buffer = m.buffers.emplace_back();
  buffer.data.resize(layout.end);
  Writing w{m, {layout.positions, layout.normals, layout.indices}, {layout.positions, layout.normals, layout.indices}, {}};
  const std::size_t ends[3] = {layout.normals, layout.indices, layout.end};
  for (int v = 0; v < 3; ++v) {
    tinygltf::BufferView& view = m.bufferViews.emplace_back();
    view.buffer = 0;
    view.byteOffset = w.starts[v];
    view.byteLength = ends[v] - w.starts[v];
    view.target = v < 2 ? TINYGLTF_TARGET_ARRAY_BUFFER : TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
    if (v < 2) view.byteStride = 3 * sizeof(float);  // required once several accessors share a vertex view
  }
  // Placed meshes first, so instance nodes know their mesh.
  std::vector<int> written_mesh;
  for (const GltfMeshData* p : written.meshes) {
    const int mesh = written_mesh.emplace_back(add_mesh(w, *p, p->building));  // >= 0: check_instances saw triangles
    m.meshes[static_cast<std::size_t>(mesh)].extras =
        tinygltf::Value(tinygltf::Value::Object{{"placed", tinygltf::Value(p->building)}});
  }
  for (const GltfMeshData& data : meshes) {
    const int mesh = add_mesh(w, data, data.building);
    if (mesh < 0 && data.instances.empty()) continue;
    tinygltf::Node node;
    node.name = data.building;
    node.mesh = mesh;
    node.extras = tinygltf::Value(tinygltf::Value::Object{{"building", tinygltf::Value(data.building)},
                                                          {"feature", tinygltf::Value(static_cast<int>(data.feature))}});
    for (const GltfInstanceData& in : data.instances) {
      const std::size_t slot = written.slot[in.prototype];
      node.children.push_back(add_instance_node(m, in, written.meshes[slot]->building, written_mesh[slot]));
    }
    m.scenes[0].nodes.push_back(add_node(m, std::move(node)));
  }
  return m;
}

[[noreturn]] void bad(const std::filesystem::path& path, const std::string& what) {
  throw IoError("'" + path.string() + "' is not a .glb as procex writes it: " + what, path.string());
}

template <class T>
std::vector<T> read_accessor(const tinygltf::Model& m, int index, int component, int type,
                             const std::filesystem::path& path) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size()) bad(path, "accessor " + std::to_string(index) + " is missing");
  const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(index)];
  const std::string where = "accessor " + std::to_string(index);
  if (a.componentType != component || a.type != type) bad(path, where + " has an unexpected component type");
  if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= m.bufferViews.size()) bad(path, where + " has no buffer view");
  const tinygltf::BufferView& v = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::size_t per = (type == TINYGLTF_TYPE_VEC3 ? 3 : 1);
  if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= m.buffers.size() ||
      (v.byteStride != 0 && v.byteStride != per * sizeof(T)))
    bad(path, where + ": unexpected buffer or stride");
  const std::size_t bytes = a.count * per * sizeof(T);
  const auto& data = m.buffers[static_cast<std::size_t>(v.buffer)].data;
  if (a.byteOffset + bytes > v.byteLength || v.byteOffset + v.byteLength > data.size()) bad(path, where + " runs past its buffer");
  std::vector<T> out(a.count * per);
  std::memcpy(out.data(), data.data() + v.byteOffset + a.byteOffset, bytes);
  return out;
}

const tinygltf::Node& node_at(const tinygltf::Model& m, int index, const std::filesystem::path& path) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.nodes.size()) bad(path, "node " + std::to_string(index) + " is missing");
  return m.nodes[static_cast<std::size_t>(index)];
}

glm::dmat4 node_matrix(const tinygltf::Node& node, int index, const std::filesystem::path& path) {
  if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
    bad(path, "node " + std::to_string(index) + " has translation, rotation or scale instead of a matrix");
  glm::dmat4 t(1.0);
  if (node.matrix.empty()) return t;
  if (node.matrix.size() != 16) bad(path, "node " + std::to_string(index) + " has a matrix of " + std::to_string(node.matrix.size()) + " numbers");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) t[c][r] = node.matrix[static_cast<std::size_t>(4 * c + r)];
  return t;
}

double max_abs(const glm::dmat4& t) {
  double out = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out = std::max(out, std::abs(t[c][r]));
  return out;
}

double max_difference(const glm::dmat4& a, const glm::dmat4& b) { return max_abs(a - b); }

// The transform a split instance node carries in extras (see
// add_instance_node), else `otherwise`.
glm::dmat4 exact_transform(const tinygltf::Node& node, int index, const std::filesystem::path& path,
                           const glm::dmat4& otherwise) {
  if (!node.extras.Has("transform")) return otherwise;
  const tinygltf::Value& v = node.extras.Get("transform");
  if (!v.IsArray() || v.ArrayLen() != 16) bad(path, "node " + std::to_string(index) + "'s transform extras are not 16 numbers");
  glm::dmat4 t;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      const tinygltf::Value& x = v.Get(4 * c + r);
      if (!x.IsNumber()) bad(path, "node " + std::to_string(index) + "'s transform extras are not 16 numbers");
      t[c][r] = x.GetNumberAsDouble();
    }
  return t;
}

std::vector<GltfPrimitiveData> read_primitives(const tinygltf::Model& m, int mesh, const std::filesystem::path& path) {
  if (mesh < 0 || static_cast<std::size_t>(mesh) >= m.meshes.size()) bad(path, "mesh " + std::to_string(mesh) + " is missing");
  std::vector<GltfPrimitiveData> out;
  for (const tinygltf::Primitive& p : m.meshes[static_cast<std::size_t>(mesh)].primitives) {
    GltfPrimitiveData& prim = out.emplace_back();
    if (p.extras.Has("tag")) prim.tag = p.extras.Get("tag").Get<std::string>();
    const auto pos = p.attributes.find("POSITION"), nor = p.attributes.find("NORMAL");
    if (pos == p.attributes.end() || nor == p.attributes.end()) bad(path, "a primitive lacks POSITION or NORMAL");
    prim.positions = read_accessor<float>(m, pos->second, kFloat, TINYGLTF_TYPE_VEC3, path);
    prim.normals = read_accessor<float>(m, nor->second, kFloat, TINYGLTF_TYPE_VEC3, path);
    prim.indices = read_accessor<std::uint32_t>(m, p.indices, kUint, TINYGLTF_TYPE_SCALAR, path);
  }
  return out;
}

void write_model(const std::filesystem::path& path, const tinygltf::Model& model) {
  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, /*prettyPrint=*/false, /*writeBinary=*/true))
    throw IoError("cannot encode '" + path.string() + "' as glTF", path.string());
  write_file_atomically(path, std::move(bytes).str());
}

}  // namespace

std::array<double, 3> tag_colour(const std::string& tag) {
  static const std::map<std::string, std::array<double, 3>> kKnown = {
      {"wall", {0.82, 0.78, 0.70}}, {"roof", {0.62, 0.22, 0.16}}, {"gable", {0.78, 0.72, 0.62}},
      {"soffit", {0.45, 0.42, 0.40}}, {"base", {0.30, 0.30, 0.30}}, {"cap", {0.55, 0.55, 0.58}}};
  if (auto it = kKnown.find(tag); it != kKnown.end()) return it->second;
  std::uint32_t h = 2166136261u;  // FNV-1a: the same grey in every run
  for (unsigned char c : tag) h = (h ^ c) * 16777619u;
  const double g = 0.35 + 0.5 * (h % 1000) / 1000.0;
  return {g, g, g};
}

void append_to_gltf_mesh(GltfMeshData& out, const TaggedMeshView& view) {
  const Mesh& mesh = *view.mesh;
  // The primitive of each of the view's tags, found by name among those already there.
  std::vector<int> primitive_of_tag(view.tags.size(), -1);
  for (std::size_t t = 0; t < view.tags.size(); ++t)
    for (std::size_t p = 0; p < out.primitives.size(); ++p)
      if (out.primitives[p].tag == view.tags[t]) primitive_of_tag[t] = static_cast<int>(p);
  std::vector<glm::dvec3> pts;
  for (const auto f : mesh.faces()) {
    pts.clear();
    for (const auto v : mesh.fv_range(f)) {
      const Mesh::Point& p = mesh.point(v);
      pts.push_back({p[0], p[1], p[2]});
    }
    const glm::dvec3 n = newell_normal(pts);
    const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(len > 0)) continue;
    const std::uint32_t tag = view.face_tags[static_cast<std::size_t>(f.idx())];
    int& slot = primitive_of_tag[tag];
    if (slot < 0) {
      slot = static_cast<int>(out.primitives.size());
      out.primitives.push_back({view.tags[tag], {}, {}, {}});
    }
    GltfPrimitiveData& prim = out.primitives[static_cast<std::size_t>(slot)];
    const auto base = static_cast<std::uint32_t>(prim.positions.size() / 3);
    for (const glm::dvec3& p : pts) {
      prim.positions.insert(prim.positions.end(), {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
      prim.normals.insert(prim.normals.end(), {static_cast<float>(n.x / len), static_cast<float>(n.y / len),
                                               static_cast<float>(n.z / len)});
    }
    for (const auto& piece : convex_partition({drop_axis(pts, n)}))
      for (std::size_t k = 1; k + 1 < piece.size(); ++k)
        prim.indices.insert(prim.indices.end(), {base + piece[0], base + piece[k], base + piece[k + 1]});
  }
}

GltfMeshData to_gltf_mesh(const TaggedMeshView& view) {
  GltfMeshData out;
  out.building = view.building;
  out.feature = view.feature;
  append_to_gltf_mesh(out, view);
  return out;
}

void write_glb(const std::filesystem::path& path, const GltfScene& scene) {
  write_model(path, to_model(path, scene.meshes, scene.prototypes));
}

void write_glb(const std::filesystem::path& path, const std::vector<GltfMeshData>& meshes) {
  write_model(path, to_model(path, meshes, {}));
}

GltfScene read_glb_scene(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw IoError("cannot open '" + path.string() + "'", path.string());
  std::string bytes(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw IoError("cannot read '" + path.string() + "'", path.string());
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  if (!loader.LoadBinaryFromMemory(&m, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                   static_cast<unsigned int>(bytes.size())))
    throw IoError("cannot read '" + path.string() + "' as glTF binary: " + err, path.string());
  GltfScene out;
  // Placed meshes carry their name in extras; the others are buildings'.
  std::map<int, std::size_t> prototype_of_mesh;
  for (std::size_t i = 0; i < m.meshes.size(); ++i) {
    if (!m.meshes[i].extras.Has("placed")) continue;
    prototype_of_mesh[static_cast<int>(i)] = out.prototypes.size();
    GltfMeshData& p = out.prototypes.emplace_back();
    p.building = m.meshes[i].extras.Get("placed").Get<std::string>();
    p.primitives = read_primitives(m, static_cast<int>(i), path);
  }
  if (m.scenes.empty()) return out;
  for (int ni : m.scenes[0].nodes) {
    const tinygltf::Node& node = node_at(m, ni, path);
    if (node.mesh < 0 && node.children.empty()) bad(path, "node " + std::to_string(ni) + " has no mesh");
    GltfMeshData& data = out.meshes.emplace_back();
    if (node.extras.Has("building")) data.building = node.extras.Get("building").Get<std::string>();
    if (node.extras.Has("feature")) data.feature = node.extras.Get("feature").GetNumberAsInt();
    if (node.mesh >= 0) data.primitives = read_primitives(m, node.mesh, path);
    for (int ci : node.children) {
      GltfInstanceData& instance = data.instances.emplace_back();
      const tinygltf::Node* at = &node_at(m, ci, path);
      if (at->extras.Has("tag")) instance.tag = at->extras.Get("tag").Get<std::string>();
      instance.transform = node_matrix(*at, ci, path);
      const glm::dmat4 exact = exact_transform(*at, ci, path, instance.transform);
      for (int depth = 0; at->mesh < 0; ++depth) {  // the inner node of a split matrix
        if (at->children.size() != 1 || depth > 1) bad(path, "instance node " + std::to_string(ci) + " leads to no mesh");
        const int next = at->children[0];
        at = &node_at(m, next, path);
        instance.transform = instance.transform * node_matrix(*at, next, path);
      }
      if (exact != instance.transform) {
        if (max_difference(exact, instance.transform) > 1e-6 * (1.0 + max_abs(exact)))
          bad(path, "instance node " + std::to_string(ci) + "'s transform in extras disagrees with its node matrices");
        instance.transform = exact;
      }
      const auto it = prototype_of_mesh.find(at->mesh);
      if (it == prototype_of_mesh.end()) bad(path, "instance node " + std::to_string(ci) + " shows a mesh that is not a placed mesh");
      instance.prototype = it->second;
    }
  }
  return out;
}

void append_scene(GltfScene& into, GltfScene part) {
  const std::size_t shift = into.prototypes.size();
  for (GltfMeshData& b : part.meshes) {
    for (GltfInstanceData& in : b.instances) in.prototype += shift;
    into.meshes.push_back(std::move(b));
  }
  std::move(part.prototypes.begin(), part.prototypes.end(), std::back_inserter(into.prototypes));
}

std::vector<GltfMeshData> read_glb(const std::filesystem::path& path) {
  GltfScene scene = read_glb_scene(path);
  if (!scene.prototypes.empty())
    throw IoError("'" + path.string() + "' holds placed meshes (" + std::to_string(scene.prototypes.size()) +
                      "), which need read_glb_scene",
                  path.string());
  return std::move(scene.meshes);
}

}  // namespace procex

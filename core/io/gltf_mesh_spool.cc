#include "core/io/gltf_mesh_spool.h"

#include <cstring>
#include <type_traits>

namespace procex {
namespace {

// A building as bytes: numbers as they lie in memory (the spool is read back
// by the same process), a string or array as its length, then its bytes.
class Writer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void put_array(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void put_text(const std::string& s) {
    put<std::uint64_t>(s.size());
    out += s;
  }
  void put_map(const std::map<std::string, std::string>& m) {
    put<std::uint64_t>(m.size());
    for (const auto& [key, value] : m) put_text(key), put_text(value);
  }
  std::string out;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : at_(bytes.data()) {}
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  template <class T>
  std::vector<T> get_array() {
    std::vector<T> v(get<std::uint64_t>());
    // An empty vector's data() may be null, which memcpy must never be given.
    if (!v.empty()) std::memcpy(v.data(), at_, v.size() * sizeof(T));
    at_ += v.size() * sizeof(T);
    return v;
  }
  std::string get_text() {
    const auto n = get<std::uint64_t>();
    std::string s(at_, n);
    at_ += n;
    return s;
  }
  std::map<std::string, std::string> get_map() {
    std::map<std::string, std::string> m;
    for (auto n = get<std::uint64_t>(); n > 0; --n) {
      std::string key = get_text();
      m.emplace_hint(m.end(), std::move(key), get_text());
    }
    return m;
  }

 private:
  const char* at_;
};

constexpr std::uint64_t kNoImage = static_cast<std::uint64_t>(-1);

}  // namespace

GltfMeshSpool::Place GltfMeshSpool::add(const GltfMeshData& mesh) {
  Writer w;
  w.put_text(mesh.building);
  w.put(mesh.feature);
  w.put(mesh.origin);
  w.put_map(mesh.properties);
  w.put_map(mesh.parameters);
  w.put<std::uint64_t>(mesh.primitives.size());
  for (const GltfPrimitiveData& p : mesh.primitives) {
    w.put_text(p.tag);
    w.put_array(p.positions), w.put_array(p.normals), w.put_array(p.indices), w.put_array(p.uvs);
    w.put<bool>(p.material.has_value());
    if (!p.material) continue;
    const GltfMaterialData& m = *p.material;
    w.put(m.colour), w.put(m.roughness), w.put(m.metallic), w.put(m.tile_size);
    std::uint64_t image = kNoImage;
    if (m.image) {
      for (std::size_t i = 0; i < images_.size() && image == kNoImage; ++i)
        if (images_[i] == m.image || *images_[i] == *m.image) image = i;
      if (image == kNoImage) image = images_.size(), images_.push_back(m.image);
    }
    w.put(image);
  }
  w.put<std::uint64_t>(mesh.instances.size());
  for (const GltfInstanceData& in : mesh.instances) w.put(in.prototype), w.put(in.transform), w.put_text(in.tag);
  const Place at{spool_.size(), w.out.size()};
  spool_.append(w.out);
  return at;
}

GltfMeshData GltfMeshSpool::get(Place at) const {
  const std::string bytes = spool_.read_at(at.offset, static_cast<std::size_t>(at.length));
  Reader r(bytes);
  GltfMeshData mesh;
  mesh.building = r.get_text();
  mesh.feature = r.get<std::int64_t>();
  mesh.origin = r.get<std::array<double, 3>>();
  mesh.properties = r.get_map();
  mesh.parameters = r.get_map();
  mesh.primitives.resize(r.get<std::uint64_t>());
  for (GltfPrimitiveData& p : mesh.primitives) {
    p.tag = r.get_text();
    p.positions = r.get_array<float>(), p.normals = r.get_array<float>();
    p.indices = r.get_array<std::uint32_t>(), p.uvs = r.get_array<float>();
    if (!r.get<bool>()) continue;
    GltfMaterialData& m = p.material.emplace();
    m.colour = r.get<std::array<double, 3>>();
    m.roughness = r.get<double>(), m.metallic = r.get<double>(), m.tile_size = r.get<double>();
    if (const auto image = r.get<std::uint64_t>(); image != kNoImage) m.image = images_[image];
  }
  mesh.instances.resize(r.get<std::uint64_t>());
  for (GltfInstanceData& in : mesh.instances) {
    in.prototype = r.get<std::size_t>();
    in.transform = r.get<glm::dmat4>();
    in.tag = r.get_text();
  }
  return mesh;
}

}  // namespace procex

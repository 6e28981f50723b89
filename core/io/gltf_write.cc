#include "core/io/gltf_write.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <deque>
#include <iterator>
#include <map>
#include <string_view>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include "core/geom/convex_partition.h"
#include "core/geom/polygon3.h"
#include "base/spool_file.h"
#include "core/io/atomic_write.h"
#include "core/io/io_error.h"
#include "core/io/texture_image.h"
#include "core/io/up_axis.h"
#include "core/mesh/material.h"
#include "core/mesh/uv_frames.h"
#include "core/placement/placement.h"
#include "core/placement/trs_split.h"

namespace procex {
namespace {

// glTF's component types: float, unsigned int.
constexpr int kFloat = 5126;
constexpr int kUint = 5125;

// The file is written without an in-memory glTF model: each building's (and
// placed mesh's) JSON is rendered on its own, in parallel, once counting has
// told it its first index in every array; the pieces are joined in file
// order, and the binary chunk goes to the file straight from the primitives'
// arrays. So the bytes do not depend on threads, and nothing is copied twice.

// JSON numbers in their shortest round-trip form: reading the file gives back
// the same doubles, so a merged file has the bytes of one run. -0 is written
// as 0 (+ 0.0 makes it so), as a reader gives it back.
void put_number(std::string& out, double v) {
  char buf[32];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v + 0.0).ptr);
}

template <std::integral T>
void put_index(std::string& out, T v) {
  char buf[24];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// Whether s is UTF-8, as JSON text must be.
bool is_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return false;
    i += n;
  }
  return true;
}

void put_string(std::string& out, std::string_view s) {
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\u00";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += ch;
    }
  }
  out += '"';
}

// {"name":value,...} from values held as JSON text (checked by are_json_members).
void put_members(std::string& out, const std::map<std::string, std::string>& values) {
  out += '{';
  bool first = true;
  for (const auto& [name, json] : values) {
    if (!first) out += ',';
    first = false;
    put_string(out, name);
    out += ':';
    out += json;
  }
  out += '}';
}

// A float in its shortest round-trip text: 7 to 9 digits where a double's
// takes up to 17. Read as a double (as JSON is) and rounded to float, the
// text gives v back, so a file read and written again (procex merge) has the
// same bytes: true of every finite float but +-7.038531e-26 (each of the 2^32
// checked once, BENCHMARKS.md), so values that small are read back here and,
// where they do not come back, written as the double v is. Into buf (32
// chars); returns the text's end.
char* float_text(char* buf, float v) {
  char* end = std::to_chars(buf, buf + 32, v).ptr;
  if (std::abs(v) < 1e-20f) {
    double back = 0.0;
    std::from_chars(buf, end, back);
    if (static_cast<float>(back) != v) end = std::to_chars(buf, buf + 32, static_cast<double>(v)).ptr;
  }
  return end;
}

// The texts of the floats one building's placed matrices hold (float_text),
// each formatted once: a wall's windows share their rotation and scale, so
// five in six of the entries other than 0 and 1 repeat one the building wrote
// already, and formatting them was 8 % of a city batch's instructions (issue
// 18). A slot keeps the last float whose bits hash to it.
class FloatTexts {
 public:
  void put(std::string& out, float v) {
    if (v == 0.0f || v == 1.0f) {  // most of a placement's entries: to_chars's own text, without a look-up
      out += v == 0.0f ? '0' : '1';
      return;
    }
    const auto bits = std::bit_cast<std::uint32_t>(v);
    Slot& slot = slots_[(bits * 0x9E3779B1u) >> (32 - kSlotBits)];
    if (slot.size == 0 || slot.bits != bits) {
      char buf[32];
      const char* end = float_text(buf, v);
      slot.bits = bits;
      slot.size = static_cast<std::uint8_t>(end - buf);
      std::memcpy(slot.text, buf, slot.size);
    }
    out.append(slot.text, slot.size);
  }

  // t as float32 (as_written).
  void put_matrix(std::string& out, const glm::dmat4& t) {
    out += '[';
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        if (c + r > 0) out += ',';
        put(out, static_cast<float>(t[c][r]));
      }
    out += ']';
  }

 private:
  static constexpr int kSlotBits = 7;  // 128 slots: a house's walls hold about 60 distinct entries
  struct Slot {
    std::uint32_t bits = 0;
    std::uint8_t size = 0;  // 0: empty
    char text[32];
  };
  std::array<Slot, std::size_t{1} << kSlotBits> slots_{};
};

// A placed mesh's transform as the file holds it: in float32, the precision
// glTF readers hold node matrices in (the Khronos validator, a GPU), which is
// finer than a window needs, since the matrix is local to its building (whose
// node carries its translation in double). The matrices were most of a city's
// JSON and formatting them in double a tenth of a batch's CPU time (issue 18).
// Whether an instance is one node or two (is_trs) is decided on these values,
// so a file read back decides the same.
glm::dmat4 as_written(const glm::dmat4& transform) { return glm::dmat4(glm::mat4(transform)); }

// Whether an instance's node matrix is translation * rotation * scale as
// written, so it needs one node, not two (core/placement/trs_split.h).
bool one_node(const GltfInstanceData& in) { return is_trs(as_written(in.transform)); }

bool has_triangles(const GltfMeshData& mesh) {
  return std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                     [](const GltfPrimitiveData& p) { return !p.indices.empty(); });
}

// What write_glb needs of a building (or placed mesh) to be written as procex
// Whether each name is UTF-8 and each value JSON text: what put_members writes.
bool are_json_members(const std::map<std::string, std::string>& values) {
  return std::all_of(values.begin(), values.end(),
                     [](const auto& v) { return is_utf8(v.first) && nlohmann::json::accept(v.second); });
}

// reads it: names that JSON can hold, as many normals as positions, whole
// vertices, indices that name one of them. Throws IoError naming the building.
void check_mesh(const std::filesystem::path& path, const GltfMeshData& mesh) {
  const auto refuse = [&](const std::string& what) {
    throw IoError("cannot write '" + path.string() + "': mesh '" + mesh.building + "' " + what, path.string());
  };
  if (!is_utf8(mesh.building)) refuse("has a name that is not UTF-8");
  if (!std::all_of(mesh.origin.begin(), mesh.origin.end(), [](double x) { return std::isfinite(x); }))
    refuse("has an origin that is not finite");
  for (const auto* values : {&mesh.properties, &mesh.parameters})
    if (!are_json_members(*values)) refuse("has an attribute whose name is not UTF-8 or whose value is not JSON");
  for (const GltfPrimitiveData& p : mesh.primitives) {
    if (!is_utf8(p.tag)) refuse("has a tag that is not UTF-8");
    if (p.positions.size() % 3 != 0 || p.normals.size() != p.positions.size())
      refuse("has " + std::to_string(p.normals.size()) + " normal and " + std::to_string(p.positions.size()) +
             " position coordinates in primitive '" + p.tag + "'");
    const std::size_t vertices = p.positions.size() / 3;
    if (!p.uvs.empty() && p.uvs.size() != 2 * vertices)
      refuse("has " + std::to_string(p.uvs.size()) + " texture coordinates for " + std::to_string(vertices) +
             " vertices in primitive '" + p.tag + "'");
    if (!std::all_of(p.uvs.begin(), p.uvs.end(), [](float x) { return std::isfinite(x); }))
      refuse("has texture coordinates that are not finite in primitive '" + p.tag + "'");
    if (p.indices.size() % 3 != 0 ||
        std::any_of(p.indices.begin(), p.indices.end(), [&](std::uint32_t i) { return i >= vertices; }))
      refuse("has indices that are not triangles of its " + std::to_string(vertices) + " vertices in primitive '" +
             p.tag + "'");
    if (!std::all_of(p.positions.begin(), p.positions.end(), [](float x) { return std::isfinite(x); }))
      refuse("has a vertex that is not finite in primitive '" + p.tag + "'");
    if (p.material) {
      if (!std::all_of(p.material->colour.begin(), p.material->colour.end(), [](double c) { return c >= 0.0 && c <= 1.0; }))
        refuse("has a material colour outside 0 to 1 in primitive '" + p.tag + "'");
      if (!(p.material->roughness >= 0.0 && p.material->roughness <= 1.0 && p.material->metallic >= 0.0 &&
            p.material->metallic <= 1.0))
        refuse("has a material roughness or metalness outside 0 to 1 in primitive '" + p.tag + "'");
      if (!(p.material->tile_size > 0.0 && std::isfinite(1.0 / p.material->tile_size)))
        refuse("has a texture tile size that is not a positive number in primitive '" + p.tag + "'");
      if (p.material->image && image_mime_type(*p.material->image).empty())
        refuse("has a texture that is not a PNG or JPEG image in primitive '" + p.tag + "'");
      if (p.material->image && p.uvs.empty()) refuse("has a texture but no texture coordinates in primitive '" + p.tag + "'");
    }
  }
}

void check_instances(const std::filesystem::path& path, const GltfMeshData& building,
                     const std::vector<GltfMeshData>& prototypes) {
  for (std::size_t i = 0; i < building.instances.size(); ++i) {
    const GltfInstanceData& in = building.instances[i];
    const auto refuse = [&](const std::string& what) {  // the message made only then: a city has 40 instances a building
      throw IoError("cannot write '" + path.string() + "': instance " + std::to_string(i) + " of building '" +
                        building.building + "' " + what,
                    path.string());
    };
    if (in.prototype >= prototypes.size())
      refuse("names placed mesh " + std::to_string(in.prototype) + " but there are " + std::to_string(prototypes.size()));
    if (!has_triangles(prototypes[in.prototype]))
      refuse("places a mesh without triangles ('" + prototypes[in.prototype].building + "')");
    // As written: past float32's range a transform is not finite there, and a tiny one singular.
    if (const std::string problem = transform_problem(as_written(in.transform)); !problem.empty()) refuse("has " + problem);
    if (!is_utf8(in.tag)) refuse("has a tag that is not UTF-8");
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

// One thing written with its own glTF mesh and nodes: a placed mesh (written
// first, so its mesh index is its slot) or a building.
struct Item {
  const GltfMeshData* data = nullptr;
  bool placed = false;
  bool deferred = false;  // a streamed building: numbers that depend on the placed meshes as markers (Ref)
  // Its first index in each array, and its first float in the position and
  // normal views, in the texture coordinate view, and first index in the index view.
  std::size_t accessor = 0, mesh = 0, node = 0, floats = 0, uv_floats = 0, indices = 0;
  bool has_mesh = false, has_node = false;
  // Its JSON, each a comma-separated run of array elements ("" if none).
  std::string nodes_json, mesh_json, accessors_json;
  // The _TAG attribute's values, primitive after primitive.
  std::vector<float> tag_values;
};

// Counts every item's share of each array: its first indices follow.
struct Totals {
  std::size_t accessors = 0, meshes = 0, nodes = 0, floats = 0, uv_floats = 0, indices = 0;
};

// `t`: what the items before these hold.
Totals place_items(std::vector<Item>& items, Totals t = {}) {
  for (Item& item : items) {
    const GltfMeshData& d = *item.data;
    item.accessor = t.accessors, item.mesh = t.meshes, item.node = t.nodes;
    item.floats = t.floats, item.uv_floats = t.uv_floats, item.indices = t.indices;
    for (const GltfPrimitiveData& p : d.primitives) {
      if (p.indices.empty()) continue;
      t.accessors += p.uvs.empty() ? 4 : 5;
      t.floats += p.positions.size(), t.uv_floats += p.uvs.size(), t.indices += p.indices.size();
    }
    item.has_mesh = t.accessors > item.accessor;
    t.meshes += item.has_mesh;
    item.has_node = !item.placed && (item.has_mesh || !d.instances.empty());
    if (!item.has_node) continue;
    t.nodes += 1;
    for (const GltfInstanceData& in : d.instances) t.nodes += one_node(in) ? 1 : 2;
  }
  return t;
}

// Numbers in a building's JSON that depend on the placed meshes, which come
// first in the file. GlbStreamWriter renders buildings before it knows them
// all, so there they are markers counted from the first building, resolved
// when the file is put together (resolve_refs): \x01, the kind, the value (8
// bytes). JSON text holds no raw control character, so \x01 starts nothing else.
enum class Ref : char {
  kAccessor = 'a',
  kMesh = 'm',
  kMaterial = 'M',      // from the streamed buildings' own numbering of materials
  kVertexOffset = 'p',  // a byte offset in the position or normal view
  kIndexOffset = 'i',
  kUvOffset = 'u',
  kTagOffset = 't',
  kTagView = 'v',  // the _TAG view's index: 3, or 4 after a texture coordinate view
};
constexpr char kRefMarker = '\x01';
constexpr std::size_t kRefBytes = 2 + sizeof(std::uint64_t);

void put_ref(std::string& out, bool deferred, Ref kind, std::size_t value) {
  if (!deferred) return put_index(out, value);
  out += kRefMarker;
  out += static_cast<char>(kind);
  const std::uint64_t v = value;
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

void put_accessor(std::string& out, bool deferred, int view, Ref offset_kind, std::size_t byte_offset, int component,
                  const char* type, std::size_t count) {
  if (!out.empty()) out += ',';
  out += "{\"bufferView\":";
  if (offset_kind == Ref::kTagOffset) put_ref(out, deferred, Ref::kTagView, static_cast<std::size_t>(view));
  else put_index(out, view);
  out += ",\"byteOffset\":";
  put_ref(out, deferred, offset_kind, byte_offset);
  out += ",\"componentType\":";
  put_index(out, component);
  out += ",\"count\":";
  put_index(out, count);
  out += ",\"type\":\"";
  out += type;
  out += '"';
}

void put_material(std::string& out, const std::string& tag, const GltfMaterialData* own, std::size_t texture);

// The materials as written, in order of first use: a tag's colour, or a
// placed mesh's own material under its tag (two meshes' different materials
// of one name are two materials). Their images, each distinct one once,
// become the textures in the same order.
struct WrittenMaterials {
  std::vector<std::pair<std::string, const GltfMaterialData*>> keys;
  std::vector<const std::string*> images;
  std::string json, textures_json, images_json;

  static bool same(const GltfMaterialData* a, const GltfMaterialData* b) { return a == b || (a && b && *a == *b); }
  std::size_t index(const GltfPrimitiveData& p) const {
    const GltfMaterialData* own = p.material ? &*p.material : nullptr;
    const auto it = std::find_if(keys.begin(), keys.end(), [&](const auto& k) { return k.first == p.tag && same(k.second, own); });
    return static_cast<std::size_t>(it - keys.begin());
  }
  void add(const GltfPrimitiveData& p) {
    if (index(p) < keys.size()) return;
    const GltfMaterialData* own = p.material ? &*p.material : nullptr;
    keys.emplace_back(p.tag, own);
    std::size_t texture = 0;
    if (own && own->image) {
      const auto it = std::find_if(images.begin(), images.end(), [&](const std::string* i) { return *i == *own->image; });
      texture = static_cast<std::size_t>(it - images.begin());
      if (it == images.end()) images.push_back(own->image.get());
    }
    if (!json.empty()) json += ',';
    put_material(json, p.tag, own, texture);
  }
};

// The tags in order of first use: their numbers (the _TAG attribute) and
// their list in the asset's extras.
struct TagNumbers {
  std::map<std::string, std::size_t> ids;
  std::string json;

  void add(const std::string& tag) {
    if (!ids.try_emplace(tag, ids.size()).second) return;
    if (!json.empty()) json += ',';
    put_string(json, tag);
  }
};

// The item's mesh and accessors (the validator wants each position
// accessor's exact bounds).
void render_mesh(Item& item, const WrittenMaterials& materials, const std::map<std::string, std::size_t>& tag_ids,
                 int item_tag_view) {
  const GltfMeshData& d = *item.data;
  const bool deferred = item.deferred;
  std::string& mesh = item.mesh_json;
  std::string& acc = item.accessors_json;
  std::size_t a = item.accessor, floats = item.floats, uv_floats = item.uv_floats, indices = item.indices;
  mesh += "{\"name\":";
  put_string(mesh, d.building);
  mesh += ",\"primitives\":[";
  bool first = true;
  for (const GltfPrimitiveData& p : d.primitives) {
    if (p.indices.empty()) continue;
    if (!first) mesh += ',';
    first = false;
    mesh += "{\"attributes\":{\"NORMAL\":";
    put_ref(mesh, deferred, Ref::kAccessor, a + 1);
    mesh += ",\"POSITION\":";
    put_ref(mesh, deferred, Ref::kAccessor, a);
    if (!p.uvs.empty()) {
      mesh += ",\"TEXCOORD_0\":";
      put_ref(mesh, deferred, Ref::kAccessor, a + 3);
    }
    mesh += ",\"_TAG\":";
    put_ref(mesh, deferred, Ref::kAccessor, a + (p.uvs.empty() ? 3 : 4));
    mesh += "},\"indices\":";
    put_ref(mesh, deferred, Ref::kAccessor, a + 2);
    mesh += ",\"material\":";
    put_ref(mesh, deferred, Ref::kMaterial, materials.index(p));
    mesh += ",\"mode\":4,\"extras\":{\"tag\":";
    put_string(mesh, p.tag);
    mesh += "}}";
    a += p.uvs.empty() ? 4 : 5;

    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (std::size_t i = 0; i < p.positions.size(); i += 3)
      for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p.positions[i + k]), hi[k] = std::max(hi[k], p.positions[i + k]);
    const std::size_t n = p.positions.size() / 3;
    put_accessor(acc, deferred, 0, Ref::kVertexOffset, floats * sizeof(float), kFloat, "VEC3", n);
    for (const auto& [key, bound] : {std::pair{",\"min\":[", lo}, std::pair{",\"max\":[", hi}}) {
      acc += key;
      for (std::size_t k = 0; k < 3; ++k) {
        if (k > 0) acc += ',';
        put_number(acc, bound[k]);
      }
      acc += ']';
    }
    acc += '}';
    put_accessor(acc, deferred, 1, Ref::kVertexOffset, floats * sizeof(float), kFloat, "VEC3", n);
    acc += '}';
    put_accessor(acc, deferred, 2, Ref::kIndexOffset, indices * sizeof(std::uint32_t), kUint, "SCALAR", p.indices.size());
    acc += '}';
    if (!p.uvs.empty()) {
      put_accessor(acc, deferred, 3, Ref::kUvOffset, uv_floats * sizeof(float), kFloat, "VEC2", n);
      acc += '}';
    }
    // Every vertex its face's tag, numbered as the asset's extras list them.
    put_accessor(acc, deferred, item_tag_view, Ref::kTagOffset, floats / 3 * sizeof(float), kFloat, "SCALAR", n);
    acc += '}';
    item.tag_values.insert(item.tag_values.end(), n, static_cast<float>(tag_ids.at(p.tag)));
    floats += p.positions.size();
    uv_floats += p.uvs.size();
    indices += p.indices.size();
  }
  mesh += ']';
  if (item.placed) {
    mesh += ",\"extras\":{\"placed\":";
    put_string(mesh, d.building);
    mesh += '}';
  }
  mesh += '}';
}

// The building's node, then each instance's node (its outer node, then the
// inner one when its matrix is not translation * rotation * scale).
void render_nodes(Item& item, const WrittenPrototypes& written) {
  const GltfMeshData& d = *item.data;
  std::string& out = item.nodes_json;
  out += "{\"name\":";
  put_string(out, d.building);
  if (item.has_mesh) {
    out += ",\"mesh\":";
    put_ref(out, item.deferred, Ref::kMesh, item.mesh);
  }
  const bool moved = d.origin != std::array<double, 3>{0, 0, 0};
  if (moved) {
    out += ",\"translation\":[";
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out += ',';
      put_number(out, d.origin[static_cast<std::size_t>(k)]);
    }
    out += ']';
  }
  std::string children;
  std::size_t next = item.node + 1;
  for (const GltfInstanceData& in : d.instances) {
    if (!children.empty()) children += ',';
    put_index(children, next);
    next += one_node(in) ? 1 : 2;
  }
  if (!children.empty()) out += ",\"children\":[" + children + "]";
  out += ",\"extras\":{\"building\":";
  put_string(out, d.building);
  out += ",\"feature\":";
  put_index(out, d.feature);
  if (moved) {
    out += ",\"origin\":[";  // procex's frame: east, north, up
    const glm::dvec3 o = from_file_axes({d.origin[0], d.origin[1], d.origin[2]}, UpAxis::Y);
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out += ',';
      put_number(out, o[k] + 0.0);  // + 0.0: no "-0"
    }
    out += ']';
  }
  for (const auto& [key, values] : {std::pair{",\"properties\":", &d.properties}, std::pair{",\"parameters\":", &d.parameters}}) {
    if (values->empty()) continue;
    out += key;
    put_members(out, *values);
  }
  out += "}}";

  next = item.node + 1;
  FloatTexts texts;
  for (const GltfInstanceData& in : d.instances) {
    const std::size_t slot = written.slot[in.prototype];  // also the placed mesh's glTF mesh
    const std::string& name = written.meshes[slot]->building;
    const glm::dmat4 transform = as_written(in.transform);
    const bool trs = is_trs(transform);
    const TrsSplit split = trs ? TrsSplit{transform, glm::dmat4(1.0)} : split_trs(transform);
    out += ",{\"name\":";
    put_string(out, name);
    if (trs) {
      out += ",\"mesh\":";
      put_index(out, slot);
    } else {
      out += ",\"children\":[";
      put_index(out, next + 1);
      out += ']';
    }
    if (split.outer != glm::dmat4(1.0)) {  // the identity is glTF's default: left out
      out += ",\"matrix\":";
      texts.put_matrix(out, split.outer);
    }
    out += ",\"extras\":{\"tag\":";
    put_string(out, in.tag);
    if (!trs) {
      // outer * inner is the transform only to rounding: the exact one rides
      // along, so reading and writing again gives the same bytes.
      out += ",\"transform\":";
      texts.put_matrix(out, transform);
    }
    out += "}}";
    if (!trs) {
      out += ",{\"name\":";
      put_string(out, name);
      out += ",\"mesh\":";
      put_index(out, slot);
      if (split.inner != glm::dmat4(1.0)) {
        out += ",\"matrix\":";
        texts.put_matrix(out, split.inner);
      }
      out += '}';
    }
    next += trs ? 1 : 2;
  }
}

void put_material(std::string& out, const std::string& tag, const GltfMaterialData* own, std::size_t texture) {
  out += "{\"name\":";
  put_string(out, tag);
  out += ",\"pbrMetallicRoughness\":{\"baseColorFactor\":[";
  for (double c : own ? own->colour : tag_colour(tag)) put_number(out, c), out += ',';
  out += "1]";
  if (own && own->image) {
    out += ",\"baseColorTexture\":{\"index\":";
    put_index(out, texture);
    if (own->tile_size != 1.0) {
      out += ",\"extensions\":{\"KHR_texture_transform\":{\"scale\":[";
      put_number(out, 1.0 / own->tile_size);
      out += ',';
      put_number(out, 1.0 / own->tile_size);
      out += "]}}";
    }
    out += '}';
  }
  out += ",\"metallicFactor\":";
  put_number(out, own ? own->metallic : 0.0);
  out += ",\"roughnessFactor\":";
  put_number(out, own ? own->roughness : Material::kDefaultRoughness);
  out += "}}";
}

// Whether a material uses KHR_texture_transform (put_material writes it).
bool transforms_texture(const GltfMaterialData* m) { return m && m->image && m->tile_size != 1.0; }

// A file as views of the text it is made of, in order, for
// write_file_atomically: the items' JSON is never joined into one string.
// Text made on the way is held here (a deque: its strings do not move).
class Pieces {
 public:
  void add(std::string_view text) {
    if (text.empty()) return;
    pieces_.push_back({text});
    size_ += text.size();
  }
  void add_own(std::string text) { add(owned_.emplace_back(std::move(text))); }
  void add_spool(const SpoolFile& spool) {
    pieces_.push_back({{}, &spool});
    size_ += spool.size();
  }
  // `,"key":[` + the items' non-empty runs, then the elements in `more`
  // (streamed buildings'), joined by commas + `]`, nothing if all are empty.
  void add_array(std::string_view key, const std::vector<Item>& items, std::string Item::*run,
                 const SpoolFile* more = nullptr) {
    bool first = true;
    const auto next = [&] {
      if (first) add_own(",\"" + std::string(key) + "\":[");
      else add(",");
      first = false;
    };
    for (const Item& item : items) {
      if ((item.*run).empty()) continue;
      next();
      add(item.*run);
    }
    if (more && more->size() > 0) next(), add_spool(*more);
    if (!first) add("]");
  }
  std::size_t size() const { return size_; }
  const std::vector<FilePiece>& pieces() const { return pieces_; }

 private:
  std::vector<FilePiece> pieces_;
  std::deque<std::string> owned_;
  std::size_t size_ = 0;
};

void append_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xFF);  // little-endian, as GLB wants
}

// The JSON up to the scene's list of nodes.
std::string scene_head(const std::string& tags_json, const WrittenMaterials& materials) {
  std::string scene = "{\"asset\":{";
  if (!tags_json.empty()) scene += "\"extras\":{\"tags\":[" + tags_json + "]},";
  scene += "\"generator\":\"procex\",\"version\":\"2.0\"},";
  // Optional: a viewer without it shows the texture one tile per metre.
  if (std::any_of(materials.keys.begin(), materials.keys.end(), [](const auto& k) { return transforms_texture(k.second); }))
    scene += "\"extensionsUsed\":[\"KHR_texture_transform\"],";
  scene += "\"scene\":0,\"scenes\":[{";
  return scene;
}

// The scene after its list of nodes (had_nodes: whether there was one).
std::string scene_end(bool had_nodes, const std::map<std::string, std::string>& extras) {
  std::string out = had_nodes ? "]" : "";
  if (!extras.empty()) {
    out += had_nodes ? ",\"extras\":" : "\"extras\":";
    put_members(out, extras);
  }
  return out + "}]";
}

// The binary chunk: five views of all items' arrays, then the images.
struct BinLayout {
  std::size_t vertex_bytes = 0, index_bytes = 0, uv_bytes = 0, tag_bytes = 0, bytes = 0;
  std::vector<std::size_t> image_offsets;
};

BinLayout bin_layout(const Totals& totals, const WrittenMaterials& materials) {
  BinLayout l;
  l.vertex_bytes = totals.floats * sizeof(float), l.index_bytes = totals.indices * sizeof(std::uint32_t);
  l.uv_bytes = totals.uv_floats * sizeof(float);
  l.tag_bytes = totals.floats / 3 * sizeof(float);
  l.bytes = 2 * l.vertex_bytes + l.index_bytes + l.uv_bytes + l.tag_bytes;
  // Each image in a view of its own after the arrays, 4-byte aligned.
  for (const std::string* image : materials.images) {
    l.image_offsets.push_back(l.bytes);
    l.bytes += (image->size() + 3) / 4 * 4;
  }
  return l;
}

// The JSON after the accessors (textures, images, buffer views, the buffer),
// padded so that the JSON chunk, json_before bytes before it, ends 4-byte aligned.
std::string render_tail(const BinLayout& bin, const WrittenMaterials& materials, int tag_view, std::size_t json_before) {
  std::string tail;
  if (!materials.images.empty()) {
    const int first_image_view = tag_view + 1;
    tail += ",\"textures\":[";
    for (std::size_t i = 0; i < materials.images.size(); ++i) {
      tail += i > 0 ? ",{\"sampler\":0,\"source\":" : "{\"sampler\":0,\"source\":";
      put_index(tail, i);
      tail += '}';
    }
    tail += "],\"samplers\":[{\"wrapS\":10497,\"wrapT\":10497}],\"images\":[";
    for (std::size_t i = 0; i < materials.images.size(); ++i) {
      tail += i > 0 ? ",{\"bufferView\":" : "{\"bufferView\":";
      put_index(tail, first_image_view + i);
      tail += ",\"mimeType\":";
      put_string(tail, image_mime_type(*materials.images[i]));
      tail += '}';
    }
    tail += ']';
  }
  if (bin.bytes > 0) {
    // Four or five views, each tightly packed: every position, then every
    // normal (vertex attributes, so a stride), every index, every texture
    // coordinate pair (if any), and every vertex's tag number. Views shared by
    // all primitives keep the JSON small for whole cities.
    const std::size_t offsets[5] = {0, bin.vertex_bytes, 2 * bin.vertex_bytes, 2 * bin.vertex_bytes + bin.index_bytes,
                                    2 * bin.vertex_bytes + bin.index_bytes + bin.uv_bytes};
    const std::size_t lengths[5] = {bin.vertex_bytes, bin.vertex_bytes, bin.index_bytes, bin.uv_bytes, bin.tag_bytes};
    static constexpr const char* kViewTails[5] = {
        ",\"byteStride\":12,\"target\":34962}", ",\"byteStride\":12,\"target\":34962}", ",\"target\":34963}",
        ",\"byteStride\":8,\"target\":34962}", ",\"byteStride\":4,\"target\":34962}"};
    tail += ",\"bufferViews\":[";
    for (int v = 0; v < 5; ++v) {
      if (v == 3 && bin.uv_bytes == 0) continue;
      if (v > 0) tail += ',';
      tail += "{\"buffer\":0,\"byteOffset\":";
      put_index(tail, offsets[v]);
      tail += ",\"byteLength\":";
      put_index(tail, lengths[v]);
      tail += kViewTails[v];
    }
    for (std::size_t i = 0; i < materials.images.size(); ++i) {
      tail += ",{\"buffer\":0,\"byteOffset\":";
      put_index(tail, bin.image_offsets[i]);
      tail += ",\"byteLength\":";
      put_index(tail, materials.images[i]->size());
      tail += '}';
    }
    tail += "],\"buffers\":[{\"byteLength\":";
    put_index(tail, bin.bytes);
    tail += "}]";
  }
  tail += '}';
  tail.append((4 - (json_before + tail.size()) % 4) % 4, ' ');  // chunks are 4-byte aligned; JSON pads with spaces
  return tail;
}

// The file's header with the JSON chunk's, and the binary chunk's header.
// Throws GlbTooLarge past max_bytes.
std::pair<std::string, std::string> chunk_headers(const std::filesystem::path& path, std::size_t json_bytes,
                                                  std::size_t bin_bytes, std::uint64_t max_bytes = kGlbMaxBytes) {
  const std::size_t total = 12 + 8 + json_bytes + (bin_bytes > 0 ? 8 + bin_bytes : 0);  // bin_bytes: 4-byte multiple
  if (total > max_bytes) throw GlbTooLarge(path, total, max_bytes);
  std::string header = "glTF";
  append_u32(header, 2);
  append_u32(header, static_cast<std::uint32_t>(total));
  append_u32(header, static_cast<std::uint32_t>(json_bytes));
  header += "JSON";
  std::string bin_header;
  append_u32(bin_header, static_cast<std::uint32_t>(bin_bytes));
  bin_header += std::string_view("BIN\0", 4);
  return {header, bin_header};
}

void add_images(std::vector<FilePiece>& pieces, const WrittenMaterials& materials) {
  static constexpr char kZeros[3] = {0, 0, 0};
  for (const std::string* image : materials.images) {
    pieces.push_back({*image});
    pieces.push_back({std::string_view(kZeros, (4 - image->size() % 4) % 4)});
  }
}

template <class T>
std::string_view bytes_of(const std::vector<T>& data) {
  return {reinterpret_cast<const char*>(data.data()), data.size() * sizeof(T)};
}

void write_scene(const std::filesystem::path& path, const std::vector<GltfMeshData>& meshes,
                 const std::vector<GltfMeshData>& prototypes, const std::map<std::string, std::string>& extras) {
  if (!are_json_members(extras))
    throw IoError("cannot write '" + path.string() + "': a scene extra's name is not UTF-8 or its value not JSON",
                  path.string());
  for (const GltfMeshData& data : meshes) check_instances(path, data, prototypes);
  const WrittenPrototypes written = written_prototypes(meshes, prototypes);
  std::vector<Item> items;
  items.reserve(written.meshes.size() + meshes.size());
  for (const GltfMeshData* p : written.meshes) items.emplace_back().data = p, items.back().placed = true;
  for (const GltfMeshData& b : meshes) items.emplace_back().data = &b;
  const Totals totals = place_items(items);
  WrittenMaterials materials;
  // The tags, numbered in order of first use for the _TAG attribute, and listed in the asset's extras.
  TagNumbers tags;
  for (const Item& item : items)
    for (const GltfPrimitiveData& p : item.data->primitives) {
      if (p.indices.empty()) continue;
      materials.add(p);
      tags.add(p.tag);
    }
  const int tag_view = totals.uv_floats > 0 ? 4 : 3;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, items.size(), 64), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      Item& item = items[i];
      check_mesh(path, *item.data);
      if (item.has_mesh) render_mesh(item, materials, tags.ids, tag_view);
      if (item.has_node) render_nodes(item, written);
    }
  });

  Pieces json;
  std::string scene = scene_head(tags.json, materials);
  bool first = true;
  for (const Item& item : items) {
    if (!item.has_node) continue;
    scene += first ? "\"nodes\":[" : ",";
    put_index(scene, item.node);
    first = false;
  }
  scene += scene_end(!first, extras);
  json.add(scene);
  json.add_array("nodes", items, &Item::nodes_json);
  json.add_array("meshes", items, &Item::mesh_json);
  if (!materials.json.empty()) json.add_own(",\"materials\":[" + materials.json + "]");
  json.add_array("accessors", items, &Item::accessors_json);
  const BinLayout bin = bin_layout(totals, materials);
  json.add_own(render_tail(bin, materials, tag_view, json.size()));
  const auto [header, bin_header] = chunk_headers(path, json.size(), bin.bytes);

  std::vector<FilePiece> pieces = {{header}};
  pieces.insert(pieces.end(), json.pieces().begin(), json.pieces().end());
  if (bin.bytes > 0) {
    pieces.push_back({bin_header});
    for (const auto member : {&GltfPrimitiveData::positions, &GltfPrimitiveData::normals})
      for (const Item& item : items)
        for (const GltfPrimitiveData& p : item.data->primitives)
          if (!p.indices.empty()) pieces.push_back({bytes_of(p.*member)});
    for (const Item& item : items)
      for (const GltfPrimitiveData& p : item.data->primitives)
        if (!p.indices.empty()) pieces.push_back({bytes_of(p.indices)});
    for (const Item& item : items)
      for (const GltfPrimitiveData& p : item.data->primitives)
        if (!p.indices.empty()) pieces.push_back({bytes_of(p.uvs)});
    for (const Item& item : items) pieces.push_back({bytes_of(item.tag_values)});
    add_images(pieces, materials);
  }
  write_file_atomically(path, pieces);
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

glm::dvec3 local_origin(const Mesh& mesh) {
  if (mesh.n_vertices() == 0) return {0, 0, 0};
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto v : mesh.vertices())
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], mesh.point(v)[k]), hi[k] = std::max(hi[k], mesh.point(v)[k]);
  return {std::round(0.5 * (lo[0] + hi[0])), std::round(0.5 * (lo[1] + hi[1])), 0.0};
}

void append_to_gltf_mesh(GltfMeshData& out, const TaggedMeshView& view) {
  const Mesh& mesh = *view.mesh;
  const glm::dvec3 origin = from_file_axes({out.origin[0], out.origin[1], out.origin[2]}, UpAxis::Y);
  // The primitive of each of the view's tags, found by name among those already there.
  std::vector<int> primitive_of_tag(view.tags.size(), -1);
  for (std::size_t t = 0; t < view.tags.size(); ++t)
    for (std::size_t p = 0; p < out.primitives.size(); ++p)
      if (out.primitives[p].tag == view.tags[t]) primitive_of_tag[t] = static_cast<int>(p);
  const std::vector<UvFrame> frames = face_uv_frames(mesh, origin);
  const auto own_uv = corner_uv_property(mesh);
  const auto own_normal = corner_normal_property(mesh);
  const Materials& materials = materials_of(view.materials);
  std::vector<glm::dvec3> pts;
  std::vector<Mesh::HalfedgeHandle> corners;
  for (const auto f : mesh.faces()) {
    pts.clear();
    corners.clear();
    for (const auto h : mesh.fh_range(f)) {
      const Mesh::Point& p = mesh.point(mesh.to_vertex_handle(h));
      pts.push_back(glm::dvec3(p[0], p[1], p[2]) - origin);
      corners.push_back(h);
    }
    const glm::dvec3 n = newell_normal(pts);
    const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(len > 0)) continue;
    const std::uint32_t tag = view.face_tags[static_cast<std::size_t>(f.idx())];
    int& slot = primitive_of_tag[tag];
    if (slot < 0) {
      slot = static_cast<int>(out.primitives.size());
      GltfPrimitiveData& added = out.primitives.emplace_back();
      added.tag = view.tags[tag];
      if (const auto m = materials.find(added.tag); m != materials.end()) {
        GltfMaterialData& material = added.material.emplace();
        material.colour = m->second.colour;
        material.roughness = m->second.roughness;
        material.metallic = m->second.metallic;
        material.tile_size = m->second.tile_size;
        material.image = m->second.image;
      }
    }
    GltfPrimitiveData& prim = out.primitives[static_cast<std::size_t>(slot)];
    const auto base = static_cast<std::uint32_t>(prim.positions.size() / 3);
    const UvFrame& frame = frames[static_cast<std::size_t>(f.idx())];
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const CornerAttribute own = corner_attribute(mesh, own_uv, own_normal, corners[k]);
      const glm::dvec3 q = to_file_axes(pts[k], UpAxis::Y);
      // Metres run on past 1 (v negated: a repeating texture stands upright);
      // a placed mesh's own coordinates address its image, so 1 - v.
      const glm::dvec2 uv = own.uv ? glm::dvec2(own.uv->x, 1.0 - own.uv->y) : frame.at(pts[k]) * glm::dvec2(1, -1);
      const glm::dvec3 file_n = to_file_axes(own.normal ? *own.normal : n / len, UpAxis::Y);
      prim.positions.insert(prim.positions.end(), {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z)});
      prim.normals.insert(prim.normals.end(), {static_cast<float>(file_n.x), static_cast<float>(file_n.y),
                                               static_cast<float>(file_n.z)});
      prim.uvs.insert(prim.uvs.end(), {static_cast<float>(uv.x), static_cast<float>(uv.y)});
    }
    for (const auto& piece : convex_partition({drop_axis(pts, n)}))
      for (std::size_t k = 1; k + 1 < piece.size(); ++k)
        prim.indices.insert(prim.indices.end(), {base + piece[0], base + piece[k], base + piece[k + 1]});
  }
}

GltfMeshData to_gltf_mesh(const TaggedMeshView& view, const glm::dvec3& origin) {
  GltfMeshData out;
  out.building = view.building;
  out.feature = view.feature;
  const glm::dvec3 o = to_file_axes(origin, UpAxis::Y);
  out.origin = {o.x, o.y, o.z};
  append_to_gltf_mesh(out, view);
  return out;
}

void write_glb(const std::filesystem::path& path, const GltfScene& scene) {
  write_scene(path, scene.meshes, scene.prototypes, scene.extras);
}

void write_glb(const std::filesystem::path& path, const std::vector<GltfMeshData>& meshes) {
  write_scene(path, meshes, {}, {});
}

namespace {

// The bases that turn a streamed building's markers (Ref) into the file's numbers.
struct RefBases {
  std::size_t accessor = 0, mesh = 0, vertex_bytes = 0, index_bytes = 0, uv_bytes = 0, tag_bytes = 0, tag_view = 0;
  std::vector<std::size_t> material;  // the file's number of each of the buildings' own materials

  std::size_t value(char kind, std::size_t v) const {
    switch (static_cast<Ref>(kind)) {
      case Ref::kAccessor: return accessor + v;
      case Ref::kMesh: return mesh + v;
      case Ref::kMaterial: return material.at(v);
      case Ref::kVertexOffset: return vertex_bytes + v;
      case Ref::kIndexOffset: return index_bytes + v;
      case Ref::kUvOffset: return uv_bytes + v;
      case Ref::kTagOffset: return tag_bytes + v;
      case Ref::kTagView: return tag_view;
    }
    throw std::logic_error("a streamed .glb's JSON holds an unknown marker");
  }
};

// Copies `from` into `to` a chunk at a time, each chunk's last `keep(chunk)`
// bytes held back for the next (a marker or value cut by the chunk's end).
template <class Convert>
void convert_spool(const SpoolFile& from, SpoolFile& to, Convert convert) {
  std::string carry, out;
  from.read([&](std::string_view chunk) {
    carry += chunk;
    out.clear();
    const std::size_t used = convert(std::string_view(carry), out);
    to.append(out);
    carry.erase(0, used);
  });
  if (!carry.empty()) throw std::logic_error("a streamed .glb's temporary file ends inside a value");
}

void resolve_refs(const SpoolFile& from, SpoolFile& to, const RefBases& bases) {
  convert_spool(from, to, [&](std::string_view text, std::string& out) {
    std::size_t from_at = 0;
    for (std::size_t at; (at = text.find(kRefMarker, from_at)) != std::string_view::npos;) {
      out.append(text.substr(from_at, at - from_at));
      if (at + kRefBytes > text.size()) return at;
      std::uint64_t v = 0;
      std::memcpy(&v, text.data() + at + 2, sizeof v);
      put_index(out, bases.value(text[at + 1], static_cast<std::size_t>(v)));
      from_at = at + kRefBytes;
    }
    out.append(text.substr(from_at));
    return text.size();
  });
}

// Each vertex's tag number, from the buildings' own numbering to the file's.
void renumber_tags(const SpoolFile& from, SpoolFile& to, const std::vector<float>& tag_of) {
  convert_spool(from, to, [&](std::string_view bytes, std::string& out) {
    const std::size_t whole = bytes.size() / sizeof(float) * sizeof(float);
    out.resize(whole);
    for (std::size_t i = 0; i < whole; i += sizeof(float)) {
      float own = 0;
      std::memcpy(&own, bytes.data() + i, sizeof own);
      std::memcpy(out.data() + i, &tag_of.at(static_cast<std::size_t>(own)), sizeof(float));
    }
    return whole;
  });
}

// Appends an element's JSON to an array's elements, comma-separated.
void append_element(SpoolFile& spool, std::string_view json) {
  if (spool.size() > 0) spool.append(",");
  spool.append(json);
}

}  // namespace

std::string glb_limit_text(std::uint64_t max_bytes) {
  return max_bytes == kGlbMaxBytes ? "a .glb holds (4 GiB)" : "the " + std::to_string(max_bytes) + " bytes allowed";
}

GlbTooLarge::GlbTooLarge(const std::filesystem::path& path, std::uint64_t bytes, std::uint64_t max_bytes)
    : IoError("cannot write '" + path.string() + "': " + std::to_string(bytes) + " bytes or more, more than " +
                  glb_limit_text(max_bytes),
              path.string()) {}

struct GlbStreamWriter::State {
  // The spools go beside the output: on the disk that is to hold it.
  explicit State(std::filesystem::path output)
      : path(std::move(output)), folder(folder_beside(path)), scene_nodes(folder), nodes(folder), meshes(folder),
        accessors(folder), positions(folder), normals(folder), indices(folder), uvs(folder), tag_values(folder) {}
  std::filesystem::path path;
  std::string folder;
  std::uint64_t max_bytes;
  std::map<std::string, std::string> extras;
  std::deque<GltfMeshData> placed;  // the placed meshes in order of first use, equal ones once
  // The buildings' materials and tags, numbered in order of first use among
  // the buildings: the file numbers the placed meshes' first.
  std::deque<GltfPrimitiveData> material_keys;  // a tag and material each, what `materials` points at
  WrittenMaterials materials;
  TagNumbers tags;
  Totals totals;  // the buildings' so far
  std::uint64_t markers = 0;  // in the spooled JSON
  SpoolFile scene_nodes, nodes, meshes, accessors, positions, normals, indices, uvs, tag_values;

  // The placed mesh's slot, given it once more (a part's prototype).
  std::size_t slot_of(const GltfMeshData& p) {
    const auto same = std::find_if(placed.begin(), placed.end(), [&](const GltfMeshData& q) {
      return q.building == p.building && q.primitives == p.primitives;
    });
    if (same != placed.end()) return static_cast<std::size_t>(same - placed.begin());
    check_mesh(path, p);
    placed.push_back(p);
    return placed.size() - 1;
  }
};

GlbStreamWriter::GlbStreamWriter(std::filesystem::path path, std::map<std::string, std::string> extras,
                                 std::uint64_t max_bytes)
{
  if (!are_json_members(extras))
    throw IoError("cannot write '" + path.string() + "': a scene extra's name is not UTF-8 or its value not JSON",
                  path.string());
  state_ = std::make_unique<State>(std::move(path));
  state_->extras = std::move(extras), state_->max_bytes = max_bytes;
}

GlbStreamWriter::~GlbStreamWriter() = default;

void GlbStreamWriter::add(std::vector<GltfScene> parts) {
  State& s = *state_;
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<Item> items;
  for (GltfScene& part : parts) {
    std::vector<std::size_t> slot(part.prototypes.size(), kNone);  // compared with the written ones once each
    for (GltfMeshData& b : part.meshes) {
      check_instances(s.path, b, part.prototypes);
      for (GltfInstanceData& in : b.instances) {
        if (slot[in.prototype] == kNone) slot[in.prototype] = s.slot_of(part.prototypes[in.prototype]);
        in.prototype = slot[in.prototype];
      }
      Item& item = items.emplace_back();
      item.data = &b, item.deferred = true;
    }
  }
  s.totals = place_items(items, s.totals);
  for (const Item& item : items)
    for (const GltfPrimitiveData& p : item.data->primitives) {
      if (p.indices.empty()) continue;
      if (s.materials.index(p) == s.materials.keys.size()) {
        GltfPrimitiveData& key = s.material_keys.emplace_back();
        key.tag = p.tag, key.material = p.material;
        s.materials.add(key);
      }
      s.tags.add(p.tag);
    }
  WrittenPrototypes written;
  for (const GltfMeshData& p : s.placed) written.slot.push_back(written.meshes.size()), written.meshes.push_back(&p);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, items.size(), 16), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      Item& item = items[i];
      check_mesh(s.path, *item.data);
      if (item.has_mesh) render_mesh(item, s.materials, s.tags.ids, 0);  // the tag view: a marker
      if (item.has_node) render_nodes(item, written);
    }
  });
  for (const Item& item : items) {
    if (item.has_node) {
      std::string node;
      put_index(node, item.node);
      append_element(s.scene_nodes, node);
      append_element(s.nodes, item.nodes_json);
    }
    if (item.has_mesh) append_element(s.meshes, item.mesh_json), append_element(s.accessors, item.accessors_json);
    for (const std::string* json : {&item.nodes_json, &item.mesh_json, &item.accessors_json})
      s.markers += static_cast<std::uint64_t>(std::count(json->begin(), json->end(), kRefMarker));
    for (const GltfPrimitiveData& p : item.data->primitives) {
      if (p.indices.empty()) continue;
      s.positions.append(bytes_of(p.positions)), s.normals.append(bytes_of(p.normals));
      s.indices.append(bytes_of(p.indices)), s.uvs.append(bytes_of(p.uvs));
    }
    s.tag_values.append(bytes_of(item.tag_values));
  }
  // Stop now, not after every building has run, when the file cannot hold them.
  if (const std::uint64_t at_least = bytes(); at_least > s.max_bytes) throw GlbTooLarge(s.path, at_least, s.max_bytes);
}

std::uint64_t GlbStreamWriter::bytes() const {
  const State& s = *state_;
  // The spools' bytes, with each marker one digit.
  std::uint64_t bytes = 0;
  for (const SpoolFile* spool : {&s.scene_nodes, &s.nodes, &s.meshes, &s.accessors, &s.positions, &s.normals,
                                 &s.indices, &s.uvs, &s.tag_values})
    bytes += spool->size();
  return bytes - s.markers * (kRefBytes - 1);
}

void GlbStreamWriter::finish() {
  State& s = *state_;
  // The placed meshes come first: their numbers are final, and the buildings' follow them.
  std::vector<Item> placed(s.placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) placed[i].data = &s.placed[i], placed[i].placed = true;
  const Totals before = place_items(placed);
  WrittenMaterials materials;
  TagNumbers tags;
  for (const Item& item : placed)
    for (const GltfPrimitiveData& p : item.data->primitives)
      if (!p.indices.empty()) materials.add(p), tags.add(p.tag);
  RefBases bases;
  for (const GltfPrimitiveData& key : s.material_keys) materials.add(key), bases.material.push_back(materials.index(key));
  std::vector<const std::string*> own_tags(s.tags.ids.size());
  for (const auto& [tag, id] : s.tags.ids) own_tags[id] = &tag;
  std::vector<float> tag_of;
  for (const std::string* tag : own_tags) tags.add(*tag), tag_of.push_back(static_cast<float>(tags.ids.at(*tag)));
  Totals all = s.totals;
  all.accessors += before.accessors, all.meshes += before.meshes, all.floats += before.floats;
  all.uv_floats += before.uv_floats, all.indices += before.indices;
  const int tag_view = all.uv_floats > 0 ? 4 : 3;
  for (Item& item : placed) render_mesh(item, materials, tags.ids, tag_view);
  bases.accessor = before.accessors, bases.mesh = before.meshes, bases.vertex_bytes = before.floats * sizeof(float);
  bases.index_bytes = before.indices * sizeof(std::uint32_t), bases.uv_bytes = before.uv_floats * sizeof(float);
  bases.tag_bytes = before.floats / 3 * sizeof(float), bases.tag_view = static_cast<std::size_t>(tag_view);
  SpoolFile nodes(s.folder), meshes(s.folder), accessors(s.folder), tag_values(s.folder);
  resolve_refs(s.nodes, nodes, bases);
  resolve_refs(s.meshes, meshes, bases);
  resolve_refs(s.accessors, accessors, bases);
  renumber_tags(s.tag_values, tag_values, tag_of);

  Pieces json;
  const bool has_nodes = s.scene_nodes.size() > 0;
  json.add_own(scene_head(tags.json, materials) + (has_nodes ? "\"nodes\":[" : ""));
  json.add_spool(s.scene_nodes);
  json.add_own(scene_end(has_nodes, s.extras));
  json.add_array("nodes", placed, &Item::nodes_json, &nodes);
  json.add_array("meshes", placed, &Item::mesh_json, &meshes);
  if (!materials.json.empty()) json.add_own(",\"materials\":[" + materials.json + "]");
  json.add_array("accessors", placed, &Item::accessors_json, &accessors);
  const BinLayout bin = bin_layout(all, materials);
  json.add_own(render_tail(bin, materials, tag_view, json.size()));
  const auto [header, bin_header] = chunk_headers(s.path, json.size(), bin.bytes, s.max_bytes);

  std::vector<FilePiece> pieces = {{header}};
  pieces.insert(pieces.end(), json.pieces().begin(), json.pieces().end());
  if (bin.bytes > 0) {
    pieces.push_back({bin_header});
    const auto add_view = [&](auto member, const SpoolFile& buildings) {
      for (const Item& item : placed)
        for (const GltfPrimitiveData& p : item.data->primitives)
          if (!p.indices.empty()) pieces.push_back({bytes_of(p.*member)});
      pieces.push_back({{}, &buildings});
    };
    add_view(&GltfPrimitiveData::positions, s.positions);
    add_view(&GltfPrimitiveData::normals, s.normals);
    add_view(&GltfPrimitiveData::indices, s.indices);
    add_view(&GltfPrimitiveData::uvs, s.uvs);
    for (const Item& item : placed) pieces.push_back({bytes_of(item.tag_values)});
    pieces.push_back({{}, &tag_values});
    add_images(pieces, materials);
  }
  write_file_atomically(s.path, pieces);
}

void append_scene(GltfScene& into, GltfScene part) {
  const std::size_t shift = into.prototypes.size();
  for (GltfMeshData& b : part.meshes) {
    for (GltfInstanceData& in : b.instances) in.prototype += shift;
    into.meshes.push_back(std::move(b));
  }
  std::move(part.prototypes.begin(), part.prototypes.end(), std::back_inserter(into.prototypes));
}

}  // namespace procex

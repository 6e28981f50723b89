#include "core/io/glb_read.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <span>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "base/json_depth.h"
#include "base/read_file.h"
#include "core/io/byte_range.h"
#include "core/io/io_error.h"
#include "core/io/texture_image.h"
#include "core/mesh/material.h"

namespace procex {
namespace {

// Not ordered_json: a building's attributes and the scene's extras are given
// back as the compact text nlohmann renders them in, members sorted, which is
// how write_glb renders them: reading and writing again gives the same bytes.
using json = nlohmann::json;

[[noreturn]] void bad(const std::filesystem::path& path, const std::string& what) {
  throw IoError("'" + path.string() + "' is not a .glb as procex writes it: " + what, path.string());
}

// Where the file's bytes come from: memory, or the file read by ranges.
struct Source {
  std::string_view memory;
  std::unique_ptr<RangedFile> file;

  std::uint64_t size() const { return file ? file->size() : memory.size(); }
  // The caller has checked that the range lies in the file.
  void read(std::uint64_t offset, std::span<char> out) const {
    if (out.empty()) return;
    if (file) file->read_at(offset, out);
    else std::memcpy(out.data(), memory.data() + offset, out.size());
  }
};

std::uint32_t u32_at(const char* p) {
  std::uint32_t v = 0;
  std::memcpy(&v, p, 4);  // little-endian, as glTF and every machine procex runs on
  return v;
}

// The JSON chunk handed to nlohmann's parser a block at a time, counting the
// bytes handed over: the parser reads no further than the token it reports,
// so the count says where an element it opens or closes lies.
class JsonCursor {
 public:
  JsonCursor(const Source& source, std::uint64_t begin, std::uint64_t length)
      : source_(source), begin_(begin), length_(length) {}
  std::uint64_t consumed() const { return consumed_; }
  bool at_end() const { return consumed_ == length_; }
  const char& current() {
    if (at_ == block_.size()) {
      block_.resize(static_cast<std::size_t>(std::min<std::uint64_t>(kBlock, length_ - consumed_)));
      source_.read(begin_ + consumed_, block_);
      at_ = 0;
    }
    return block_[at_];
  }
  void advance() { ++at_, ++consumed_; }

 private:
  static constexpr std::size_t kBlock = std::size_t{1} << 16;
  const Source& source_;
  std::uint64_t begin_, length_, consumed_ = 0;
  std::vector<char> block_;
  std::size_t at_ = 0;
};

// JsonCursor as the input iterator nlohmann reads; a null cursor is the end.
struct CursorIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  JsonCursor* cursor = nullptr;

  reference operator*() const { return cursor->current(); }
  CursorIterator& operator++() {
    cursor->advance();
    return *this;
  }
  CursorIterator operator++(int) {
    CursorIterator was = *this;
    cursor->advance();
    return was;
  }
  bool ended() const { return cursor == nullptr || cursor->at_end(); }
  friend bool operator==(const CursorIterator& a, const CursorIterator& b) { return a.ended() == b.ended(); }
};

// The top-level arrays a building or placed mesh is read from.
enum Array { kScenes, kNodes, kMeshes, kAccessors, kBufferViews, kBuffers, kMaterials, kTextures, kImages, kArrayCount };
constexpr std::array<std::string_view, kArrayCount> kArrayKeys = {
    "scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers", "materials", "textures", "images"};
constexpr std::array<const char*, kArrayCount> kElementNames = {
    "scene", "node", "mesh", "accessor", "buffer view", "buffer", "material", "texture", "image"};

// An element's bytes within the JSON chunk (a .glb is under 4 GiB).
struct Span {
  std::uint32_t offset = 0, length = 0;
};
using Index = std::array<std::vector<Span>, kArrayCount>;

// The one pass over the JSON: each element of the arrays above noted where
// it lies, nothing else kept; nesting bounded as every JSON procex reads.
class Indexer : public nlohmann::json_sax<json> {
 public:
  Indexer(const JsonCursor& cursor, Index& index) : cursor_(cursor), index_(index) {}
  const std::string& problem() const { return problem_; }

  bool null() override { return scalar(); }
  bool boolean(bool) override { return scalar(); }
  bool number_integer(number_integer_t) override { return scalar(); }
  bool number_unsigned(number_unsigned_t) override { return scalar(); }
  bool number_float(number_float_t, const string_t&) override { return scalar(); }
  bool string(string_t&) override { return scalar(); }
  bool binary(binary_t&) override { return scalar(); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    if (depth_ == 1) {
      const auto it = std::find(kArrayKeys.begin(), kArrayKeys.end(), k);
      key_ = it == kArrayKeys.end() ? -1 : static_cast<int>(it - kArrayKeys.begin());
    }
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::json::exception& e) override {
    return fail("its JSON is not valid at byte " + std::to_string(position) + ": " + e.what());
  }

 private:
  bool fail(std::string what) {
    if (problem_.empty()) problem_ = std::move(what);
    return false;
  }
  std::string element() const {
    return std::string(kArrayKeys[static_cast<std::size_t>(array_)]) + "[" +
           std::to_string(index_[static_cast<std::size_t>(array_)].size()) + "]";
  }
  bool scalar() {
    if (depth_ == 0) return fail("its JSON is not an object");
    if (depth_ == 1 && key_ >= 0) return fail(std::string(kArrayKeys[static_cast<std::size_t>(key_)]) + " is not an array");
    if (depth_ == 2 && array_ >= 0) return fail(element() + " is not an object");
    return true;
  }
  bool open(bool object) {
    if (depth_ == 0 && !object) return fail("its JSON is not an object");
    if (depth_ == 1 && key_ >= 0) {
      if (object) return fail(std::string(kArrayKeys[static_cast<std::size_t>(key_)]) + " is not an array");
      array_ = key_;
      index_[static_cast<std::size_t>(array_)].clear();  // a repeated key: the last one counts, as for a parser
    }
    if (depth_ == 2 && array_ >= 0) {
      if (!object) return fail(element() + " is not an object");
      start_ = cursor_.consumed() - 1;  // the '{' just read
    }
    if (++depth_ > kMaxJsonDepth) return fail("its JSON is nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  }
  bool close() {
    --depth_;
    if (depth_ == 2 && array_ >= 0)
      index_[static_cast<std::size_t>(array_)].push_back(
          {static_cast<std::uint32_t>(start_), static_cast<std::uint32_t>(cursor_.consumed() - start_)});
    else if (depth_ == 1) array_ = -1;
    return true;
  }

  const JsonCursor& cursor_;
  Index& index_;
  std::size_t depth_ = 0;  // containers open
  int key_ = -1;           // the array the last top-level key names, if one of ours
  int array_ = -1;         // the array of ours open at depth 2
  std::uint64_t start_ = 0;
  std::string problem_;
};

// A member of an object, or null if it has none.
const json* member(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// A buffer view as its accessors and images need it, checked to lie in the
// binary chunk.
struct View {
  std::uint64_t offset = 0, length = 0, stride = 0;
};

// A material as written: the base colour, roughness and metalness, the
// texture (-1: none) and its repeat (KHR_texture_transform's scale).
struct MaterialRead {
  std::array<double, 3> colour{1, 1, 1};
  double roughness = 1.0, metallic = 1.0;  // glTF's defaults
  std::int64_t texture = -1;
  std::optional<double> scale;
};

// The accessor types procex writes: float positions, normals and texture
// coordinates, unsigned int indices.
constexpr int kFloat = 5126, kUint = 5125;

}  // namespace

struct GlbReader::State {
  std::filesystem::path path;
  Source source;
  std::uint64_t json_begin = 0, json_length = 0, bin_begin = 0, bin_length = 0;
  Index index;
  std::vector<View> views;
  std::vector<std::shared_ptr<const std::string>> images;
  std::vector<std::int64_t> texture_images;  // per texture, its image (-1: none)
  std::vector<MaterialRead> materials;
  std::vector<std::uint64_t> scene_nodes;
  std::map<std::string, std::string> extras;
  std::vector<GltfMeshData> prototypes;
  std::map<std::uint64_t, std::size_t> prototype_of_mesh;
  std::uint64_t buffer_length = 0;

  [[noreturn]] void refuse(const std::string& what) const { bad(path, what); }

  // Checks the headers, indexes the JSON, reads what every building may use.
  void open();
  void read_header();
  json element(Array array, std::uint64_t i) const;
  std::size_t count(Array array) const { return index[array].size(); }

  // Typed members, each refused with its element's name when it is not what write_glb writes.
  std::uint64_t index_value(const json& v, const std::string& where) const {
    if (!v.is_number_unsigned()) refuse(where + " is not an index (a whole number from 0)");
    return v.get<std::uint64_t>();
  }
  std::optional<std::uint64_t> optional_index(const json& object, const char* key, const std::string& where) const {
    const json* v = member(object, key);
    if (!v) return std::nullopt;
    return index_value(*v, where + "'s " + key);
  }
  std::uint64_t required_index(const json& object, const char* key, const std::string& where) const {
    const auto v = optional_index(object, key, where);
    if (!v) refuse(where + " has no " + key);
    return *v;
  }
  double number(const json& v, const std::string& where) const {
    if (!v.is_number()) refuse(where + " is not a number");
    return v.get<double>();
  }
  std::string text(const json& object, const char* key, const std::string& where) const {
    const json* v = member(object, key);
    if (!v) return {};
    if (!v->is_string()) refuse(where + "'s " + key + " is not a string");
    return v->get<std::string>();
  }
  const json* object_member(const json& object, const char* key, const std::string& where) const {
    const json* v = member(object, key);
    if (v && !v->is_object()) refuse(where + "'s " + key + " is not an object");
    return v;
  }
  std::vector<std::uint64_t> index_list(const json& object, const char* key, const std::string& where) const {
    std::vector<std::uint64_t> out;
    const json* v = member(object, key);
    if (!v) return out;
    if (!v->is_array()) refuse(where + "'s " + key + " is not an array");
    for (const json& i : *v) out.push_back(index_value(i, where + "'s " + key));
    return out;
  }
  // Each member of an object as compact JSON text.
  std::map<std::string, std::string> members(const json* object) const {
    std::map<std::string, std::string> out;
    if (object)
      for (const auto& [name, value] : object->items()) out[name] = value.dump();
    return out;
  }

  void read_buffers_and_views();
  void read_images_textures_materials();
  template <class T>
  std::vector<T> read_accessor(std::uint64_t index, int component, const char* type, std::size_t per) const;
  std::optional<GltfMaterialData> read_material(std::uint64_t index, const std::string& tag) const;
  std::vector<GltfPrimitiveData> read_primitives(std::uint64_t mesh) const;
  glm::dmat4 node_matrix(const json& node, const std::string& where) const;
  GltfInstanceData read_instance(std::uint64_t node) const;
};

void GlbReader::State::read_header() {
  const std::uint64_t size = source.size();
  if (size > std::numeric_limits<std::uint32_t>::max())
    throw IoError("cannot read '" + path.string() + "': too large for a glTF binary", path.string());
  if (size < 20) refuse("it is " + std::to_string(size) + " bytes, too short for a glTF binary's headers");
  char head[20];
  source.read(0, head);
  if (std::memcmp(head, "glTF", 4) != 0) refuse("it does not start with glTF's magic bytes");
  if (u32_at(head + 4) != 2) refuse("it is glTF binary version " + std::to_string(u32_at(head + 4)) + ", not 2");
  if (u32_at(head + 8) != size)
    refuse("its header gives its length as " + std::to_string(u32_at(head + 8)) + " bytes but it has " +
           std::to_string(size) + (u32_at(head + 8) > size ? " (cut short?)" : ""));
  if (std::memcmp(head + 16, "JSON", 4) != 0) refuse("its first chunk is not JSON");
  json_begin = 20, json_length = u32_at(head + 12);
  if (json_length > size - json_begin)
    refuse("its JSON chunk of " + std::to_string(json_length) + " bytes runs past the file's end");
  const std::uint64_t rest = size - json_begin - json_length;
  if (rest == 0) return;  // no binary chunk
  if (rest < 8) refuse("it has " + std::to_string(rest) + " bytes after its JSON chunk, too few for a chunk");
  char bin_head[8];
  source.read(json_begin + json_length, bin_head);
  if (std::memcmp(bin_head + 4, "BIN\0", 4) != 0) refuse("its second chunk is not BIN");
  bin_begin = json_begin + json_length + 8, bin_length = u32_at(bin_head);
  if (bin_length > rest - 8)
    refuse("its binary chunk of " + std::to_string(bin_length) + " bytes runs past the file's end (" +
           std::to_string(rest - 8) + " bytes are left; cut short?)");
}

json GlbReader::State::element(Array array, std::uint64_t i) const {
  if (i >= index[array].size()) refuse(std::string(kElementNames[array]) + " " + std::to_string(i) + " is missing");
  const Span span = index[array][static_cast<std::size_t>(i)];
  std::string bytes(span.length, '\0');
  source.read(json_begin + span.offset, bytes);
  // The indexing pass parsed these bytes already: they are one valid object,
  // unless the file was rewritten since.
  json out = json::parse(bytes, nullptr, false);
  if (out.is_discarded())
    refuse(std::string(kElementNames[array]) + " " + std::to_string(i) +
           " is no longer where its JSON put it (the file changed while read)");
  return out;
}

void GlbReader::State::read_buffers_and_views() {
  // In a .glb, buffer 0 without a URI is the binary chunk; procex writes no other.
  if (count(kBuffers) > 1) refuse("it has " + std::to_string(count(kBuffers)) + " buffers; procex writes one, its binary chunk");
  if (count(kBuffers) == 1) {
    const json buffer = element(kBuffers, 0);
    if (const json* uri = member(buffer, "uri"))
      refuse("buffer 0 refers to the external file " + uri->dump() + ": a .glb from procex holds everything in itself");
    buffer_length = required_index(buffer, "byteLength", "buffer 0");
    if (buffer_length > bin_length)
      refuse("buffer 0 is " + std::to_string(buffer_length) + " bytes but its binary chunk holds " +
             std::to_string(bin_length) + " (cut short?)");
  }
  for (std::uint64_t i = 0; i < count(kBufferViews); ++i) {
    const json v = element(kBufferViews, i);
    const std::string where = "buffer view " + std::to_string(i);
    if (required_index(v, "buffer", where) >= count(kBuffers)) refuse(where + "'s buffer is missing");
    View view;
    view.offset = optional_index(v, "byteOffset", where).value_or(0);
    view.length = required_index(v, "byteLength", where);
    view.stride = optional_index(v, "byteStride", where).value_or(0);
    // Compared without a sum, which a maker's numbers near 2^64 could wrap.
    if (view.offset > buffer_length || view.length > buffer_length - view.offset)
      refuse(where + " (bytes " + std::to_string(view.offset) + " to " + std::to_string(view.offset) + " + " +
             std::to_string(view.length) + ") runs past its buffer of " + std::to_string(buffer_length) + " bytes");
    views.push_back(view);
  }
}

void GlbReader::State::read_images_textures_materials() {
  for (std::uint64_t i = 0; i < count(kImages); ++i) {
    const json image = element(kImages, i);
    const std::string where = "image " + std::to_string(i);
    if (const json* uri = member(image, "uri"))
      refuse(where + " refers to the external file " + uri->dump() + ": a .glb from procex holds everything in itself");
    const std::uint64_t v = required_index(image, "bufferView", where);
    if (v >= views.size()) refuse(where + "'s buffer view " + std::to_string(v) + " is missing");
    auto bytes = std::make_shared<std::string>(static_cast<std::size_t>(views[v].length), '\0');
    source.read(bin_begin + views[v].offset, *bytes);
    if (image_mime_type(*bytes).empty()) refuse(where + " is not a PNG or JPEG image");
    images.push_back(std::move(bytes));
  }
  for (std::uint64_t i = 0; i < count(kTextures); ++i) {
    const auto source_image = optional_index(element(kTextures, i), "source", "texture " + std::to_string(i));
    texture_images.push_back(source_image && *source_image < images.size() ? static_cast<std::int64_t>(*source_image) : -1);
  }
  for (std::uint64_t i = 0; i < count(kMaterials); ++i) {
    const json m = element(kMaterials, i);
    const std::string where = "material " + std::to_string(i);
    MaterialRead& out = materials.emplace_back();
    const json* pbr = object_member(m, "pbrMetallicRoughness", where);
    if (!pbr) continue;
    if (const json* colour = member(*pbr, "baseColorFactor")) {
      if (!colour->is_array() || colour->size() != 4) refuse(where + "'s base colour is not 4 numbers");
      for (std::size_t k = 0; k < 3; ++k) out.colour[k] = number((*colour)[k], where + "'s base colour");
    }
    if (const json* r = member(*pbr, "roughnessFactor")) out.roughness = number(*r, where + "'s roughness");
    if (const json* r = member(*pbr, "metallicFactor")) out.metallic = number(*r, where + "'s metalness");
    const json* texture = object_member(*pbr, "baseColorTexture", where);
    if (!texture) continue;
    out.texture = static_cast<std::int64_t>(required_index(*texture, "index", where + "'s base colour texture"));
    const json* extensions = object_member(*texture, "extensions", where + "'s base colour texture");
    const json* transform = extensions ? object_member(*extensions, "KHR_texture_transform", where) : nullptr;
    if (!transform) continue;
    const json* scale = member(*transform, "scale");
    if (!scale || !scale->is_array() || scale->size() != 2 || !(*scale)[0].is_number() || (*scale)[0] != (*scale)[1] ||
        !((*scale)[0].get<double>() > 0))
      refuse(where + "'s texture transform is not one positive scale for u and v");
    out.scale = (*scale)[0].get<double>();
  }
}

template <class T>
std::vector<T> GlbReader::State::read_accessor(std::uint64_t index, int component, const char* type, std::size_t per) const {
  const json a = element(kAccessors, index);
  const std::string where = "accessor " + std::to_string(index);
  if (!a.contains("componentType") || a["componentType"] != component || text(a, "type", where) != type)
    refuse(where + " has an unexpected component type");
  if (member(a, "sparse")) refuse(where + " is sparse");
  const auto view_index = optional_index(a, "bufferView", where);
  if (!view_index || *view_index >= views.size()) refuse(where + " has no buffer view");
  const View& view = views[static_cast<std::size_t>(*view_index)];
  if (view.stride != 0 && view.stride != per * sizeof(T)) refuse(where + ": unexpected buffer or stride");
  const std::uint64_t offset = optional_index(a, "byteOffset", where).value_or(0);
  const auto bytes = checked_product(required_index(a, "count", where), per * sizeof(T));
  if (!bytes || offset > view.length || *bytes > view.length - offset)
    refuse(where + " runs past its buffer view " + std::to_string(*view_index) + " of " + std::to_string(view.length) +
           " bytes");
  std::vector<T> out(static_cast<std::size_t>(*bytes / sizeof(T)));
  source.read(bin_begin + view.offset + offset,
              std::span<char>(reinterpret_cast<char*>(out.data()), static_cast<std::size_t>(*bytes)));
  return out;
}

std::optional<GltfMaterialData> GlbReader::State::read_material(std::uint64_t index, const std::string& tag) const {
  if (index >= materials.size()) refuse("material " + std::to_string(index) + " is missing");
  const MaterialRead& m = materials[static_cast<std::size_t>(index)];
  GltfMaterialData out;
  out.colour = m.colour, out.roughness = m.roughness, out.metallic = m.metallic;
  if (m.texture >= 0) {
    const auto t = static_cast<std::size_t>(m.texture);
    if (t >= texture_images.size()) refuse("texture " + std::to_string(t) + " is missing");
    if (texture_images[t] < 0) refuse("texture " + std::to_string(t) + " has no image");
    out.image = images[static_cast<std::size_t>(texture_images[t])];
    if (m.scale) out.tile_size = 1.0 / *m.scale;
  }
  GltfMaterialData plain;  // what a tag without a material of its own is written with
  plain.colour = tag_colour(tag);
  if (out == plain) return std::nullopt;
  return out;
}

std::vector<GltfPrimitiveData> GlbReader::State::read_primitives(std::uint64_t mesh) const {
  const json m = element(kMeshes, mesh);
  const std::string where = "mesh " + std::to_string(mesh);
  const json* list = member(m, "primitives");
  if (!list || !list->is_array()) refuse(where + " has no list of primitives");
  std::vector<GltfPrimitiveData> out;
  for (const json& p : *list) {
    const std::string at = where + "'s primitive " + std::to_string(out.size());
    if (!p.is_object()) refuse(at + " is not an object");
    GltfPrimitiveData& prim = out.emplace_back();
    if (const json* extras = object_member(p, "extras", at)) prim.tag = text(*extras, "tag", at + "'s extras");
    if (const json* mode = member(p, "mode"); mode && *mode != 4) refuse(at + " is not of triangles (mode 4)");
    if (const auto material = optional_index(p, "material", at)) prim.material = read_material(*material, prim.tag);
    const json* attributes = object_member(p, "attributes", at);
    const auto pos = attributes ? optional_index(*attributes, "POSITION", at) : std::nullopt;
    const auto nor = attributes ? optional_index(*attributes, "NORMAL", at) : std::nullopt;
    if (!pos || !nor) refuse("a primitive lacks POSITION or NORMAL (" + at + ")");
    prim.positions = read_accessor<float>(*pos, kFloat, "VEC3", 3);
    prim.normals = read_accessor<float>(*nor, kFloat, "VEC3", 3);
    prim.indices = read_accessor<std::uint32_t>(required_index(p, "indices", at), kUint, "SCALAR", 1);
    if (const auto uv = optional_index(*attributes, "TEXCOORD_0", at)) prim.uvs = read_accessor<float>(*uv, kFloat, "VEC2", 2);
    // Writers index normals and texture coordinates by the position's index, so counts that differ or
    // an index past the vertices would read or write past an array.
    if (prim.normals.size() != prim.positions.size())
      refuse("a primitive has " + std::to_string(prim.positions.size() / 3) + " positions but " +
             std::to_string(prim.normals.size() / 3) + " normals (" + at + ")");
    const std::size_t vertices = prim.positions.size() / 3;
    for (const std::uint32_t i : prim.indices)
      if (i >= vertices)
        refuse("a primitive's index " + std::to_string(i) + " is past its " + std::to_string(vertices) + " vertices (" + at + ")");
    if (!prim.uvs.empty() && prim.uvs.size() != 2 * vertices)
      refuse("a primitive has " + std::to_string(vertices) + " positions but " + std::to_string(prim.uvs.size() / 2) +
             " texture coordinates (" + at + ")");
  }
  return out;
}

glm::dmat4 GlbReader::State::node_matrix(const json& node, const std::string& where) const {
  if (member(node, "translation") || member(node, "rotation") || member(node, "scale"))
    refuse(where + " has translation, rotation or scale instead of a matrix");
  glm::dmat4 t(1.0);
  const json* matrix = member(node, "matrix");
  if (!matrix) return t;
  if (!matrix->is_array() || matrix->size() != 16) refuse(where + "'s matrix is not 16 numbers");
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) t[c][r] = number((*matrix)[static_cast<std::size_t>(4 * c + r)], where + "'s matrix");
  return t;
}

namespace {

double max_abs(const glm::dmat4& t) {
  double out = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out = std::max(out, std::abs(t[c][r]));
  return out;
}

}  // namespace

// An instance: its node, and the inner node a matrix that is not
// translation * rotation * scale was split into (core/placement/trs_split.h).
GltfInstanceData GlbReader::State::read_instance(std::uint64_t index) const {
  GltfInstanceData instance;
  std::string where = "instance node " + std::to_string(index);
  json at = element(kNodes, index);
  const json* extras = object_member(at, "extras", where);
  if (extras) instance.tag = text(*extras, "tag", where + "'s extras");
  instance.transform = node_matrix(at, where);
  // The exact transform rides along in extras: outer * inner is it only to rounding.
  std::optional<glm::dmat4> exact;
  if (const json* t = extras ? member(*extras, "transform") : nullptr) {
    if (!t->is_array() || t->size() != 16) refuse(where + "'s transform extras are not 16 numbers");
    glm::dmat4& e = exact.emplace();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) e[c][r] = number((*t)[static_cast<std::size_t>(4 * c + r)], where + "'s transform extras");
  }
  for (int depth = 0; !member(at, "mesh"); ++depth) {
    const std::vector<std::uint64_t> children = index_list(at, "children", where);
    if (children.size() != 1 || depth > 1) refuse(where + " leads to no mesh");
    where = "node " + std::to_string(children[0]);
    at = element(kNodes, children[0]);
    instance.transform = instance.transform * node_matrix(at, where);
  }
  if (exact && *exact != instance.transform) {
    if (max_abs(*exact - instance.transform) > 1e-6 * (1.0 + max_abs(*exact)))
      refuse("instance node " + std::to_string(index) + "'s transform in extras disagrees with its node matrices");
    instance.transform = *exact;
  }
  const auto mesh = required_index(at, "mesh", where);
  const auto it = prototype_of_mesh.find(mesh);
  if (it == prototype_of_mesh.end()) refuse("instance node " + std::to_string(index) + " shows a mesh that is not a placed mesh");
  instance.prototype = it->second;
  return instance;
}

void GlbReader::State::open() {
  read_header();
  JsonCursor cursor(source, json_begin, json_length);
  Indexer indexer(cursor, index);
  if (!json::sax_parse(CursorIterator{&cursor}, CursorIterator{}, &indexer) || !indexer.problem().empty())
    refuse(indexer.problem().empty() ? "its JSON is not valid" : indexer.problem());
  read_buffers_and_views();
  read_images_textures_materials();
  // Placed meshes carry their name in extras; the others are buildings'.
  for (std::uint64_t i = 0; i < count(kMeshes); ++i) {
    const json m = element(kMeshes, i);
    const std::string where = "mesh " + std::to_string(i);
    const json* extras = object_member(m, "extras", where);
    if (!extras || !member(*extras, "placed")) continue;
    prototype_of_mesh[i] = prototypes.size();
    GltfMeshData& p = prototypes.emplace_back();
    p.building = text(*extras, "placed", where + "'s extras");
    p.primitives = read_primitives(i);
  }
  if (count(kScenes) == 0) return;
  const json scene = element(kScenes, 0);
  scene_nodes = index_list(scene, "nodes", "scene 0");
  extras = members(object_member(scene, "extras", "scene 0"));
}

GlbReader::GlbReader(const std::filesystem::path& path) : state_(std::make_unique<State>()) {
  state_->path = path;
  state_->source.file = std::make_unique<RangedFile>(path, std::numeric_limits<std::uint32_t>::max());
  state_->open();
}

GlbReader::GlbReader(std::string_view bytes, const std::filesystem::path& path) : state_(std::make_unique<State>()) {
  state_->path = path;
  state_->source.memory = bytes;
  state_->open();
}

GlbReader::~GlbReader() = default;

std::uint64_t GlbReader::length(const std::filesystem::path& path) {
  State s;
  s.path = path;
  s.source.file = std::make_unique<RangedFile>(path, std::numeric_limits<std::uint32_t>::max());
  s.read_header();
  return s.source.size();
}

const std::map<std::string, std::string>& GlbReader::extras() const { return state_->extras; }
const std::vector<GltfMeshData>& GlbReader::prototypes() const { return state_->prototypes; }
std::size_t GlbReader::buildings() const { return state_->scene_nodes.size(); }

std::uint64_t GlbReader::building_bytes() const {
  const State& s = *state_;
  std::uint64_t json = 0;
  // Every node is a building's or an instance a building places.
  for (const Span& node : s.index[kNodes]) json += node.length;
  for (std::uint64_t i = 0; i < s.count(kMeshes); ++i)
    if (!s.prototype_of_mesh.count(i)) json += s.index[kMeshes][static_cast<std::size_t>(i)].length;
  // At most what the placed meshes' arrays (a tag value a vertex too) and
  // the images (each padded to 4 bytes) take of the buffer.
  std::uint64_t shared = 0;
  for (const GltfMeshData& p : s.prototypes)
    for (const GltfPrimitiveData& prim : p.primitives)
      shared += sizeof(float) * (prim.positions.size() + prim.normals.size() + prim.uvs.size() + prim.positions.size() / 3) +
                sizeof(std::uint32_t) * prim.indices.size();
  for (const auto& image : s.images) shared += image->size() + 3;
  return json + (s.buffer_length > shared ? s.buffer_length - shared : 0);
}

GltfMeshData GlbReader::building(std::size_t i) const {
  const State& s = *state_;
  const std::uint64_t index = s.scene_nodes.at(i);
  const std::string where = "node " + std::to_string(index);
  const json node = s.element(kNodes, index);
  const auto mesh = s.optional_index(node, "mesh", where);
  const std::vector<std::uint64_t> children = s.index_list(node, "children", where);
  if (!mesh && children.empty()) s.refuse(where + " has no mesh");
  if (member(node, "matrix") || member(node, "rotation") || member(node, "scale"))
    s.refuse("building " + where + " has a matrix, rotation or scale (only a translation)");
  GltfMeshData data;
  if (const json* t = member(node, "translation")) {
    if (!t->is_array() || t->size() != 3) s.refuse("building " + where + "'s translation is not 3 numbers");
    for (std::size_t k = 0; k < 3; ++k) data.origin[k] = s.number((*t)[k], "building " + where + "'s translation");
  }
  if (const json* extras = s.object_member(node, "extras", where)) {
    data.building = s.text(*extras, "building", where + "'s extras");
    if (const json* feature = member(*extras, "feature")) {
      if (!feature->is_number_integer()) s.refuse(where + "'s extras.feature is not a whole number");
      data.feature = feature->get<std::int64_t>();
    }
    data.properties = s.members(s.object_member(*extras, "properties", where + "'s extras"));
    data.parameters = s.members(s.object_member(*extras, "parameters", where + "'s extras"));
  }
  if (mesh) data.primitives = s.read_primitives(*mesh);
  for (const std::uint64_t child : children) data.instances.push_back(s.read_instance(child));
  return data;
}

namespace {

GltfScene whole_scene(const GlbReader& reader) {
  GltfScene out;
  out.prototypes = reader.prototypes();
  out.extras = reader.extras();
  for (std::size_t i = 0; i < reader.buildings(); ++i) out.meshes.push_back(reader.building(i));
  return out;
}

}  // namespace

GltfScene read_glb_scene(const std::filesystem::path& path) { return whole_scene(GlbReader(path)); }

GltfScene parse_glb_scene(std::string_view bytes, const std::filesystem::path& path) {
  return whole_scene(GlbReader(bytes, path));
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

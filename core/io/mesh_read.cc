#include "core/io/mesh_read.h"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <string_view>

#include "base/confined_path.h"
#include "base/read_file.h"
#include "core/io/io_error.h"
#include "core/io/texture_image.h"
#include "core/mesh/material.h"

namespace procex {
namespace {

using Path = std::filesystem::path;

[[noreturn]] void fail(const Path& path, const std::string& what) {
  throw IoError("'" + path.string() + "': " + what, path.string());
}

[[noreturn]] void fail_at(const Path& path, std::size_t line, std::string_view text, const std::string& what) {
  throw IoError("'" + path.string() + "' line " + std::to_string(line) + ": " + what + ": '" + std::string(text) + "'",
                path.string());
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// Calls fn(line number, line, its content before any '#', the content's
// words) for every line of an OBJ or MTL text that has words, CR LF or LF.
template <class Fn>
void for_each_statement(std::string_view text, Fn&& fn) {
  std::size_t line_no = 0;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t eol = std::min(text.find('\n', at), text.size());
    std::string_view line = text.substr(at, eol - at);
    at = eol + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view content = line.substr(0, line.find('#'));
    const std::vector<std::string_view> words = split_words(content);
    if (!words.empty()) fn(line_no, line, content, words);
  }
}

// A whole word as a finite number ("+1" allowed, as some exporters write it).
bool parse_coordinate(std::string_view word, double& value) {
  if (!word.empty() && word[0] == '+') word.remove_prefix(1);
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  return ec == std::errc() && end == word.data() + word.size() && std::isfinite(value);
}

// What the line-by-line check learns: the vertices at full precision, each
// face's tag, and the file reduced to its 'v' and 'f' lines with absolute
// vertex numbers, which is what OpenMesh reads: it then has nothing to warn
// about (material libraries, texture corners) on the terminal.
struct ObjScan {
  std::vector<Mesh::Point> vertices;
  std::vector<std::string> face_tags;
  std::string plain;
  // Texture coordinates and normals ('vt', 'vn'), and per face its corners
  // as (vertex, texture coordinate, normal), -1 where a corner names none.
  std::vector<OpenMesh::Vec2d> uvs;
  std::vector<OpenMesh::Vec3d> normals;
  std::vector<std::vector<std::array<long long, 3>>> corners;
  std::vector<std::pair<std::size_t, std::string>> libraries;  // 'mtllib' file names, with their line
};

// One number of a face corner ("v", "v/vt", "v//vn" or "v/vt/vn"), 0-based:
// OBJ counts from 1, and negative numbers count back from the last one so
// far. -1 for a texture coordinate or normal the corner leaves out.
long long corner_index(const Path& path, std::size_t line_no, std::string_view line, std::string_view corner, int part,
                       std::size_t count) {
  static constexpr const char* kWhat[] = {"vertex", "texture coordinate", "normal"};
  static constexpr const char* kWhats[] = {"vertices", "texture coordinates", "normals"};
  std::string_view number = corner;
  for (int k = 0; k < part; ++k) {
    const std::size_t slash = number.find('/');
    if (slash == std::string_view::npos) return -1;
    number.remove_prefix(slash + 1);
  }
  number = number.substr(0, number.find('/'));
  if (part > 0 && number.empty()) return -1;
  long long index = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), index);
  if (ec != std::errc() || end != number.data() + number.size() || index == 0)
    fail_at(path, line_no, line, "face corner '" + std::string(corner) + "' has no " + kWhat[part] +
                                     " number (1, 2, ... or -1, -2, ...) where one belongs");
  const long long n = static_cast<long long>(count);
  const long long resolved = index > 0 ? index - 1 : n + index;
  if (resolved < 0 || resolved >= n)
    fail_at(path, line_no, line, "face corner '" + std::string(corner) + "' names a " + kWhat[part] + " that does not exist (" +
                                     std::to_string(count) + " " + kWhats[part] + " so far)");
  return resolved;
}

// The finite numbers of words[1..], at least `least` and at most `most` of them.
template <std::size_t N>
std::array<double, N> numbers(const Path& path, std::size_t line_no, std::string_view line,
                              const std::vector<std::string_view>& words, std::size_t least, const char* what) {
  if (words.size() < least + 1) fail_at(path, line_no, line, std::string(what) + " needs " + std::to_string(least) + " numbers");
  std::array<double, N> out{};
  for (std::size_t k = 1; k < words.size() && k <= N; ++k)
    if (!parse_coordinate(words[k], out[k - 1]))
      fail_at(path, line_no, line, std::string(what) + " '" + std::string(words[k]) + "' is not a finite number");
  return out;
}

// The rest of the line after its first word, trimmed: a name or file name
// that may hold spaces.
std::string rest_of_line(std::string_view content, const std::vector<std::string_view>& words) {
  if (words.size() < 2) return "";
  std::string out(content.substr(static_cast<std::size_t>(words[1].data() - content.data())));
  while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
  return out;
}

ObjScan scan_obj(const Path& path, std::string_view text) {
  if (text.find('\0') != std::string_view::npos) fail(path, "is not a text OBJ file (it contains NUL bytes)");
  ObjScan scan;
  std::string tag;
  std::vector<std::size_t> corners;
  for_each_statement(text, [&](std::size_t line_no, std::string_view line, std::string_view content,
                               const std::vector<std::string_view>& words) {
    if (words[0] == "v") {
      if (words.size() < 4) fail_at(path, line_no, line, "a vertex needs three coordinates");
      Mesh::Point& p = scan.vertices.emplace_back();
      scan.plain += 'v';
      for (std::size_t k = 1; k < 4; ++k) {
        if (!parse_coordinate(words[k], p[static_cast<int>(k) - 1]))
          fail_at(path, line_no, line, "vertex coordinate '" + std::string(words[k]) + "' is not a finite number");
        scan.plain += ' ';
        scan.plain += words[k];
      }
      scan.plain += '\n';
    } else if (words[0] == "vt") {
      const auto uv = numbers<2>(path, line_no, line, words, 1, "a texture coordinate");
      scan.uvs.emplace_back(uv[0], uv[1]);
    } else if (words[0] == "vn") {
      const auto n = numbers<3>(path, line_no, line, words, 3, "a normal");
      scan.normals.emplace_back(n[0], n[1], n[2]);
    } else if (words[0] == "f") {
      if (words.size() < 4) fail_at(path, line_no, line, "a face needs at least three corners");
      corners.clear();
      auto& face = scan.corners.emplace_back();
      scan.plain += 'f';
      for (std::size_t k = 1; k < words.size(); ++k) {
        const long long v = corner_index(path, line_no, line, words[k], 0, scan.vertices.size());
        face.push_back({v, corner_index(path, line_no, line, words[k], 1, scan.uvs.size()),
                        corner_index(path, line_no, line, words[k], 2, scan.normals.size())});
        corners.push_back(static_cast<std::size_t>(v));
        scan.plain += ' ' + std::to_string(corners.back() + 1);
      }
      scan.plain += '\n';
      std::sort(corners.begin(), corners.end());
      if (const auto dup = std::adjacent_find(corners.begin(), corners.end()); dup != corners.end())
        fail_at(path, line_no, line, "the face visits vertex " + std::to_string(*dup + 1) + " twice");
      scan.face_tags.push_back(tag);
    } else if (words[0] == "usemtl") {
      tag = rest_of_line(content, words);
    } else if (words[0] == "mtllib") {
      for (std::size_t k = 1; k < words.size(); ++k) scan.libraries.emplace_back(line_no, std::string(words[k]));
    }
  });
  if (scan.face_tags.empty())
    fail(path, "has no faces (a mesh to place needs 'v' lines and at least one 'f' line), " +
                   std::to_string(scan.vertices.size()) + " vertices");
  return scan;
}

// OpenMesh's OBJ reader keeps single-precision coordinates. Its vertices are
// the file's, in order, followed by the copies it made for non-manifold faces
// (copies of already rounded points): all get the file's exact values back.
void restore_precision(Mesh& mesh, const std::vector<Mesh::Point>& exact) {
  std::map<std::array<float, 3>, std::size_t> original;
  const auto key = [](const Mesh::Point& p) {
    return std::array<float, 3>{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
  };
  for (std::size_t i = 0; i < exact.size(); ++i) original.try_emplace(key(exact[i]), i);
  for (const auto v : mesh.vertices()) {
    const auto i = static_cast<std::size_t>(v.idx());
    if (i < exact.size()) {
      mesh.set_point(v, exact[i]);
    } else if (const auto it = original.find(key(mesh.point(v))); it != original.end()) {
      mesh.set_point(v, exact[it->second]);
    }
  }
}

// The names the file's `keyword` statements give (their words, or the rest of
// the line), joined to its folder; none if it is no regular file or cannot be read.
std::vector<Path> named_files(const Path& path, std::string_view keyword, bool words_are_names) {
  std::vector<Path> out;
  try {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return out;
    const std::string text = read_file(path, kMaxDataFileBytes);
    for_each_statement(text, [&](std::size_t, std::string_view, std::string_view content,
                                 const std::vector<std::string_view>& words) {
      if (words[0] != keyword) return;
      if (words_are_names) {
        for (std::size_t k = 1; k < words.size(); ++k) out.push_back(path.parent_path() / std::string(words[k]));
      } else if (const std::string name = rest_of_line(content, words); !name.empty()) {
        out.push_back(path.parent_path() / name);
      }
    });
  } catch (const std::exception&) {
    // Reading the file for the mesh says what is wrong.
  }
  return out;
}

// A material library (MTL): per 'newmtl' its 'Kd' colour and 'map_Kd'
// texture, the texture resolved against the library's folder. Other
// statements (Ka, Ks, Ns, d, illum, other maps) are left out: glTF's base
// colour is what every consumer shows.
Materials read_material_library(const Path& path, const ReferencedFileResolver& resolve) {
  const std::string text = read_file(path, kMaxDataFileBytes);
  if (text.find('\0') != std::string::npos) fail(path, "is not a text material library (it contains NUL bytes)");
  Materials out;
  Material* current = nullptr;
  for_each_statement(text, [&](std::size_t line_no, std::string_view line, std::string_view content,
                               const std::vector<std::string_view>& words) {
    if (words[0] == "newmtl") {
      const std::string name = rest_of_line(content, words);
      if (name.empty()) fail_at(path, line_no, line, "a material needs a name");
      current = &out[name];
      *current = Material{};
      return;
    }
    if (words[0] != "Kd" && words[0] != "map_Kd") return;
    if (!current) fail_at(path, line_no, line, "'" + std::string(words[0]) + "' comes before any 'newmtl'");
    if (words[0] == "Kd") {
      const auto kd = numbers<3>(path, line_no, line, words, 3, "a colour (Kd)");
      for (double c : kd)
        if (c < 0.0 || c > 1.0) fail_at(path, line_no, line, "a colour (Kd) needs three numbers from 0 to 1");
      current->colour = kd;
    } else {
      const std::string name = rest_of_line(content, words);
      if (name.empty() || name[0] == '-')
        fail_at(path, line_no, line, "a texture (map_Kd) needs a file name and no options (procex does not apply -s, -o, ...)");
      current->texture = resolve(path.parent_path() / name);
      current->image = shared_texture_image(current->texture);
    }
  });
  return out;
}

// Each face's corners in OpenMesh's mesh (fh_range order) take the texture
// coordinates and normals of the file's corner at the same vertex: OpenMesh
// may start a face at another corner, and gives a vertex it duplicated a
// new number (the copy stands at the original's exact point).
void set_corner_attributes(Mesh& mesh, const ObjScan& scan) {
  const bool any_uv = !scan.uvs.empty(), any_normal = !scan.normals.empty();
  if (!any_uv && !any_normal) return;
  OpenMesh::HPropHandleT<OpenMesh::Vec2d> uv;
  OpenMesh::HPropHandleT<OpenMesh::Vec3d> normal;
  if (any_uv) uv = add_corner_uvs(mesh);
  if (any_normal) normal = add_corner_normals(mesh);
  const auto all_have = [](const std::vector<std::array<long long, 3>>& face, int part) {
    return std::all_of(face.begin(), face.end(), [&](const auto& c) { return c[static_cast<std::size_t>(part)] >= 0; });
  };
  for (const auto f : mesh.faces()) {
    const auto& face = scan.corners[static_cast<std::size_t>(f.idx())];
    const bool has_uv = any_uv && all_have(face, 1), has_normal = any_normal && all_have(face, 2);
    if (!has_uv && !has_normal) continue;
    for (const auto h : mesh.fh_range(f)) {
      const auto v = mesh.to_vertex_handle(h);
      const auto corner = std::find_if(face.begin(), face.end(), [&](const auto& c) {
        const auto i = static_cast<std::size_t>(c[0]);
        return static_cast<std::size_t>(v.idx()) < scan.vertices.size() ? i == static_cast<std::size_t>(v.idx())
                                                                          : scan.vertices[i] == mesh.point(v);
      });
      if (corner == face.end()) continue;  // (cannot happen: every corner of the face is in the file's face)
      if (has_uv) mesh.property(uv, h) = scan.uvs[static_cast<std::size_t>((*corner)[1])];
      if (has_normal) {
        const OpenMesh::Vec3d n = scan.normals[static_cast<std::size_t>((*corner)[2])];
        const double length = n.norm();
        mesh.property(normal, h) = length > 0 ? OpenMesh::Vec3d(n / length) : OpenMesh::Vec3d(NAN, NAN, NAN);
      }
    }
  }
}

}  // namespace

Mesh read_mesh_file(const Path& path, std::vector<std::string>* warnings, const ReferencedFileResolver& resolve,
                    Materials* materials) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj") fail(path, "cannot read meshes in '" + ext + "' files to place: use a Wavefront .obj file");
  const std::string text = read_file(path, kMaxDataFileBytes);
  if (text.empty()) fail(path, "is empty (a mesh to place needs 'v' and 'f' lines)");
  if (resolve) return parse_obj_mesh(text, path, warnings, resolve, materials);
  const Path folder = path.parent_path();
  return parse_obj_mesh(text, path, warnings, [&](const Path& name) { return confined_path(folder, name.string()); },
                        materials);
}

Mesh parse_obj_mesh(std::string_view text, const Path& path, std::vector<std::string>* warnings,
                    const ReferencedFileResolver& resolve, Materials* materials) {
  const ObjScan scan = scan_obj(path, text);

  Mesh mesh;
  {
    // OpenMesh's OBJ reader is one shared object with state of its own
    // (materials, path): one read at a time, whatever thread asks.
    static std::mutex reader;
    const std::lock_guard<std::mutex> lock(reader);
    std::istringstream stream(scan.plain);
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::read_mesh(mesh, stream, ".obj", options)) fail(path, "OpenMesh could not read it");
  }
  if (mesh.n_faces() != scan.face_tags.size())
    fail(path, "OpenMesh added " + std::to_string(mesh.n_faces()) + " of its " + std::to_string(scan.face_tags.size()) +
                   " faces");
  restore_precision(mesh, scan.vertices);
  if (warnings && mesh.n_vertices() > scan.vertices.size())
    // (Built with append: g++ 12 warns falsely on "'" + path.string() here.)
    warnings->push_back(std::string("'").append(path.string()).append("': ") + std::to_string(mesh.n_vertices() - scan.vertices.size()) +
                        " vertices were duplicated to add faces that meet in a non-manifold way (an edge with "
                        "more than two faces, or neighbours facing opposite ways)");
  add_face_properties(mesh);
  const auto tags = face_tag_property(mesh);
  for (const auto f : mesh.faces()) mesh.property(tags, f) = scan.face_tags[static_cast<std::size_t>(f.idx())];
  set_corner_attributes(mesh, scan);
  if (!resolve) return mesh;
  Materials read;
  for (const auto& [line, name] : scan.libraries) {
    const Path library = resolve(path.parent_path() / name);  // outside the folder: refused, as every file
    std::error_code error;
    if (!std::filesystem::is_regular_file(library, error)) {
      if (warnings)
        warnings->push_back(std::string("'").append(path.string()).append("' line ") + std::to_string(line) +
                            ": material library '" + name + "' is not there: its faces keep their tags' colours");
      continue;
    }
    read.merge(read_material_library(library, resolve));  // the first library to define a name wins
  }
  if (materials) *materials = std::move(read);
  return mesh;
}

std::vector<Path> obj_material_libraries(const Path& obj) { return named_files(obj, "mtllib", true); }

std::vector<Path> material_library_textures(const Path& library) { return named_files(library, "map_Kd", false); }

}  // namespace procex

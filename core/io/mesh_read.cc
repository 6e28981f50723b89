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

#include "base/read_file.h"
#include "core/io/io_error.h"

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
};

// The vertex a face corner names (its part before any '/'), 0-based; OBJ
// counts from 1, and negative numbers count back from the last vertex so far.
std::size_t corner_vertex(const Path& path, std::size_t line_no, std::string_view line, std::string_view corner,
                          std::size_t vertices) {
  const std::string_view number = corner.substr(0, corner.find('/'));
  long long index = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), index);
  if (ec != std::errc() || end != number.data() + number.size() || index == 0)
    fail_at(path, line_no, line, "face corner '" + std::string(corner) + "' does not start with a vertex number (1, 2, ... or -1, -2, ...)");
  const long long n = static_cast<long long>(vertices);
  const long long resolved = index > 0 ? index - 1 : n + index;
  if (resolved < 0 || resolved >= n)
    fail_at(path, line_no, line, "face corner '" + std::string(corner) + "' names a vertex that does not exist (" +
                                     std::to_string(vertices) + " vertices so far)");
  return static_cast<std::size_t>(resolved);
}

ObjScan scan_obj(const Path& path, std::string_view text) {
  if (text.find('\0') != std::string_view::npos) fail(path, "is not a text OBJ file (it contains NUL bytes)");
  ObjScan scan;
  std::string tag;
  std::vector<std::size_t> corners;
  std::size_t line_no = 0;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t eol = std::min(text.find('\n', at), text.size());
    std::string_view line = text.substr(at, eol - at);
    at = eol + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string_view content = line.substr(0, line.find('#'));
    const std::vector<std::string_view> words = split_words(content);
    if (words.empty()) continue;
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
    } else if (words[0] == "f") {
      if (words.size() < 4) fail_at(path, line_no, line, "a face needs at least three corners");
      corners.clear();
      scan.plain += 'f';
      for (std::size_t k = 1; k < words.size(); ++k) {
        corners.push_back(corner_vertex(path, line_no, line, words[k], scan.vertices.size()));
        scan.plain += ' ' + std::to_string(corners.back() + 1);
      }
      scan.plain += '\n';
      std::sort(corners.begin(), corners.end());
      if (const auto dup = std::adjacent_find(corners.begin(), corners.end()); dup != corners.end())
        fail_at(path, line_no, line, "the face visits vertex " + std::to_string(*dup + 1) + " twice");
      scan.face_tags.push_back(tag);
    } else if (words[0] == "usemtl") {
      tag = words.size() > 1 ? std::string(content.substr(static_cast<std::size_t>(words[1].data() - content.data()))) : "";
      while (!tag.empty() && (tag.back() == ' ' || tag.back() == '\t')) tag.pop_back();
    }
  }
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

}  // namespace

Mesh read_mesh_file(const Path& path, std::vector<std::string>* warnings) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj") fail(path, "cannot read meshes in '" + ext + "' files to place: use a Wavefront .obj file");
  const std::string text = read_file(path, kMaxDataFileBytes);
  if (text.empty()) fail(path, "is empty (a mesh to place needs 'v' and 'f' lines)");
  return parse_obj_mesh(text, path, warnings);
}

Mesh parse_obj_mesh(std::string_view text, const Path& path, std::vector<std::string>* warnings) {
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
  return mesh;
}

}  // namespace procex

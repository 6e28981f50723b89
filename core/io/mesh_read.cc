#include "core/io/mesh_read.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <string_view>

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

// What the line-by-line check learns: the vertices at full precision and each face's tag.
struct ObjScan {
  std::vector<Mesh::Point> vertices;
  std::vector<std::string> face_tags;
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
      for (int k = 0; k < 3; ++k)
        if (!parse_coordinate(words[static_cast<std::size_t>(k) + 1], p[k]))
          fail_at(path, line_no, line, "vertex coordinate '" + std::string(words[static_cast<std::size_t>(k) + 1]) + "' is not a finite number");
    } else if (words[0] == "f") {
      if (words.size() < 4) fail_at(path, line_no, line, "a face needs at least three corners");
      corners.clear();
      for (std::size_t k = 1; k < words.size(); ++k)
        corners.push_back(corner_vertex(path, line_no, line, words[k], scan.vertices.size()));
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

// OpenMesh reports through three global streams (omlog, omout, omerr). While
// a file is read they go to a string instead of the terminal, so what OpenMesh
// says ends up in the error or the warnings; reads are serialised because the
// streams are shared by every thread.
class OpenMeshMessages {
 public:
  OpenMeshMessages() : lock_(mutex()) {
    for (OpenMesh::mostream* s : streams()) {
      s->flush();
      s->connect(text_);
      Restore& r = restore_.emplace_back();
      r.cerr = s->disconnect(std::cerr);
      r.cout = s->disconnect(std::cout);
      r.clog = s->disconnect(std::clog);
    }
  }
  ~OpenMeshMessages() {
    std::size_t i = 0;
    for (OpenMesh::mostream* s : streams()) {
      s->flush();
      s->disconnect(text_);
      const Restore& r = restore_[i++];
      if (r.cerr) s->connect(std::cerr);
      if (r.cout) s->connect(std::cout);
      if (r.clog) s->connect(std::clog);
    }
  }
  OpenMeshMessages(const OpenMeshMessages&) = delete;
  OpenMeshMessages& operator=(const OpenMeshMessages&) = delete;

  // Each distinct line once, in order of first appearance.
  std::vector<std::string> lines() {
    for (OpenMesh::mostream* s : streams()) s->flush();
    std::vector<std::string> out;
    std::istringstream in(text_.str());
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && std::find(out.begin(), out.end(), line) == out.end()) out.push_back(line);
    return out;
  }

 private:
  struct Restore {
    bool cerr = false, cout = false, clog = false;
  };
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::vector<OpenMesh::mostream*> streams() { return {&omlog(), &omout(), &omerr()}; }
  std::lock_guard<std::mutex> lock_;
  std::ostringstream text_;
  std::vector<Restore> restore_;
};

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

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += (out.empty() ? "" : "; ") + l;
  return out;
}

}  // namespace

Mesh read_mesh_file(const Path& path, std::vector<std::string>* warnings) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".obj") fail(path, "cannot read meshes in '" + ext + "' files to place: use a Wavefront .obj file");
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "is not a regular file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  if (!in || !(bytes << in.rdbuf())) {
    if (std::filesystem::file_size(path, ec) == 0 && !ec) fail(path, "is empty (a mesh to place needs 'v' and 'f' lines)");
    fail(path, "cannot read it");
  }
  const std::string text = std::move(bytes).str();
  const ObjScan scan = scan_obj(path, text);

  Mesh mesh;
  std::vector<std::string> said;
  {
    OpenMeshMessages messages;
    std::istringstream stream(text);
    OpenMesh::IO::Options options;
    const bool ok = OpenMesh::IO::read_mesh(mesh, stream, ".obj", options);
    said = messages.lines();
    if (!ok) fail(path, "OpenMesh could not read it" + (said.empty() ? std::string() : ": " + joined(said)));
  }
  if (mesh.n_faces() != scan.face_tags.size())
    fail(path, "OpenMesh added " + std::to_string(mesh.n_faces()) + " of its " + std::to_string(scan.face_tags.size()) +
                   " faces" + (said.empty() ? std::string() : ": " + joined(said)));
  restore_precision(mesh, scan.vertices);
  if (warnings) {
    if (mesh.n_vertices() > scan.vertices.size())
      warnings->push_back("'" + path.string() + "': " + std::to_string(mesh.n_vertices() - scan.vertices.size()) +
                          " vertices were duplicated to add faces that meet in a non-manifold way (an edge with "
                          "more than two faces, or neighbours facing opposite ways)");
    // Material complaints are noise: tags come from 'usemtl' here, and no material library is read.
    for (const std::string& line : said)
      if (line.find("Material") == std::string::npos) warnings->push_back("'" + path.string() + "': OpenMesh: " + line);
  }
  add_face_properties(mesh);
  const auto tags = face_tag_property(mesh);
  for (const auto f : mesh.faces()) mesh.property(tags, f) = scan.face_tags[static_cast<std::size_t>(f.idx())];
  return mesh;
}

}  // namespace procex

#include "core/io/mesh_write.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>

#include "core/io/atomic_write.h"
#include "core/io/io_error.h"

namespace procex {

namespace {

void append_double(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  out.append(buf, res.ptr);
}

void append_point(std::string& out, const Mesh::Point& p, UpAxis up) {
  const glm::dvec3 q = to_file_axes(glm::dvec3(p[0], p[1], p[2]), up);
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    append_double(out, q[k]);
  }
}

std::string group_name(const std::string& name, std::size_t index) {
  std::string out = name.empty() ? "mesh_" + std::to_string(index) : name;
  std::replace_if(out.begin(), out.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  return out;
}

void check_meshes(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes) {
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (!meshes[i].mesh) throw IoError("cannot write '" + path.string() + "': mesh " + std::to_string(i) + " is null", path.string());
}

}  // namespace

void write_obj(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes, UpAxis up) {
  check_meshes(path, meshes);
  std::string out = "# procex\n";
  std::size_t base = 1;  // OBJ numbers vertices from 1 across the whole file
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const Mesh& mesh = *meshes[i].mesh;
    out += "g " + group_name(meshes[i].name, i) + "\n";
    for (const auto v : mesh.vertices()) {
      out += 'v';
      append_point(out, mesh.point(v), up);
      out += '\n';
    }
    for (const auto f : mesh.faces()) {
      out += 'f';
      for (const auto v : mesh.fv_range(f)) out += ' ' + std::to_string(base + v.idx());
      out += '\n';
    }
    base += mesh.n_vertices();
  }
  write_file_atomically(path, out);
}

void write_obj(const std::filesystem::path& path, const Mesh& mesh, UpAxis up) { write_obj(path, {{"mesh", &mesh}}, up); }

void write_ply(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes, UpAxis up) {
  check_meshes(path, meshes);
  std::size_t n_vertices = 0, n_faces = 0;
  for (const NamedMesh& m : meshes) {
    n_vertices += m.mesh->n_vertices();
    n_faces += m.mesh->n_faces();
  }
  // Face tags as numbers (PLY has no string property), named in comments.
  std::vector<std::string> tags;
  for (const NamedMesh& m : meshes)
    if (const auto tag_prop = face_tag_property(*m.mesh); tag_prop.is_valid())
      for (const auto f : m.mesh->faces())
        if (const std::string& tag = m.mesh->property(tag_prop, f);
            !tag.empty() && std::find(tags.begin(), tags.end(), tag) == tags.end())
          tags.push_back(tag);
  std::string out = "ply\nformat ascii 1.0\ncomment written by procex: metres, ";
  out += up == UpAxis::Y ? "+Y up (x east, -z north)\n" : "+Z up (x east, y north)\n";
  for (std::size_t i = 0; i < meshes.size(); ++i)
    out += "comment procex_group " + std::to_string(i) + " " + group_name(meshes[i].name, i) + "\n";
  for (std::size_t i = 0; i < tags.size(); ++i)
    out += "comment procex_tag " + std::to_string(i) + " " + group_name(tags[i], i) + "\n";
  out += "element vertex " + std::to_string(n_vertices) +
         "\nproperty double x\nproperty double y\nproperty double z\n"
         "element face " + std::to_string(n_faces) +
         "\nproperty list int int vertex_indices\nproperty int procex_source_edge\n"
         "property uchar procex_face_kind\nproperty int procex_group\nproperty int procex_tag\nend_header\n";
  for (const NamedMesh& m : meshes) {
    for (const auto v : m.mesh->vertices()) {
      append_point(out, m.mesh->point(v), up);
      out += '\n';
    }
  }
  std::size_t base = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const Mesh& mesh = *meshes[i].mesh;
    const auto edge_prop = source_edge_property(mesh);
    const auto kind_prop = face_kind_property(mesh);
    const auto tag_prop = face_tag_property(mesh);
    for (const auto f : mesh.faces()) {
      out += std::to_string(mesh.valence(f));
      for (const auto v : mesh.fv_range(f)) out += ' ' + std::to_string(base + v.idx());
      out += ' ' + std::to_string(edge_prop.is_valid() ? mesh.property(edge_prop, f) : -1);
      out += ' ' + std::to_string(kind_prop.is_valid() ? static_cast<int>(mesh.property(kind_prop, f)) : 255);
      out += ' ' + std::to_string(i);
      const auto tag = tag_prop.is_valid() ? std::find(tags.begin(), tags.end(), mesh.property(tag_prop, f)) : tags.end();
      out += ' ' + std::to_string(tag == tags.end() ? -1 : tag - tags.begin()) + '\n';
    }
    base += mesh.n_vertices();
  }
  write_file_atomically(path, out);
}

void write_ply(const std::filesystem::path& path, const Mesh& mesh, UpAxis up) { write_ply(path, {{"mesh", &mesh}}, up); }

void write_mesh_file(const std::filesystem::path& path, const std::vector<NamedMesh>& meshes, UpAxis up) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") {
    write_obj(path, meshes, up);
  } else if (ext == ".ply") {
    write_ply(path, meshes, up);
  } else {
    throw IoError("cannot write '" + path.string() + "': unknown mesh format '" + ext + "' (use .obj or .ply)",
                  path.string());
  }
}

}  // namespace procex

#include "core/io/mesh_write.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/io_error.h"
#include "tests/core/mesh_fixtures.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

class MeshWrite : public test::ScratchDirTest {
 protected:
  // Only the written file is left: the temporary one was renamed.
  void expect_only(const fs::path& file) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir_)) files.push_back(e.path());
    EXPECT_EQ(files, std::vector<fs::path>{file});
  }

};

// Coordinates that need all 17 significant digits to survive.
Surface awkward_box() { return test::box({0.1, 1.0 / 3.0, -2.0 / 7.0}, {1e-7 + 1.0, 12345.678901234567, 0.3}); }

// OpenMesh's OBJ reader parses coordinates as float, so its copy is compared
// to float precision; exact_points() checks the text itself.
void expect_same_geometry(const Mesh& a, const Mesh& b, double tolerance) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  for (const auto v : a.vertices()) {
    const auto d = a.point(v) - b.point(Mesh::VertexHandle(v.idx()));
    EXPECT_LE(d.norm(), tolerance * a.point(v).norm()) << v.idx();
  }
  for (const auto f : a.faces()) {
    std::vector<int> va, vb;
    for (const auto v : a.fv_range(f)) va.push_back(v.idx());
    for (const auto v : b.fv_range(Mesh::FaceHandle(f.idx()))) vb.push_back(v.idx());
    EXPECT_EQ(va, vb);
  }
}

// The "v" lines of an OBJ file, parsed at full precision.
std::vector<Mesh::Point> exact_points(const fs::path& file) {
  std::ifstream in(file);
  std::vector<Mesh::Point> out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    Mesh::Point p;
    s >> p[0] >> p[1] >> p[2];
    out.push_back(p);
  }
  return out;
}

// The first n vertex lines of an ASCII PLY file, parsed at full precision.
std::vector<Mesh::Point> ply_points(const fs::path& file, std::size_t n) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line != "end_header") {
  }
  std::vector<Mesh::Point> out(n);
  for (auto& p : out) in >> p[0] >> p[1] >> p[2];
  return out;
}

TEST_F(MeshWrite, ObjRoundTripsThroughOpenMesh) {
  const Mesh mesh = build_mesh(awkward_box());
  const fs::path file = dir_ / "box.obj";
  write_obj(file, mesh, UpAxis::Z);
  expect_only(file);
  Mesh back;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(back, file.string()));
  expect_same_geometry(mesh, back, 1e-7);
  const std::vector<Mesh::Point> exact = exact_points(file);
  ASSERT_EQ(exact.size(), mesh.n_vertices());
  for (const auto v : mesh.vertices()) EXPECT_EQ(exact[v.idx()], mesh.point(v));
}

TEST_F(MeshWrite, PlyRoundTripsThroughOpenMesh) {
  const Mesh mesh = build_mesh(test::combine(test::square_ring(), awkward_box()));
  const fs::path file = dir_ / "ring.ply";
  write_ply(file, mesh, UpAxis::Z);
  expect_only(file);
  Mesh back;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(back, file.string()));
  expect_same_geometry(mesh, back, 1e-7);
  const std::vector<Mesh::Point> exact = ply_points(file, mesh.n_vertices());
  for (const auto v : mesh.vertices()) EXPECT_EQ(exact[v.idx()], mesh.point(v));
  // The face properties are in the file, one line per face.
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("property int procex_source_edge"), std::string::npos);
  EXPECT_NE(text.find("\n4 0 1 9 8 0 1 0 -1\n"), std::string::npos) << text;  // (test boxes have no tags)
}

// By default the files are +Y up as Blender, Maya and Houdini read them: a
// quarter turn about x, (x, y, z) -> (x, z, -y), so nothing is mirrored.
TEST_F(MeshWrite, DefaultIsYUpWithoutMirroring) {
  const Mesh mesh = build_mesh(awkward_box());
  for (const char* name : {"box.obj", "box.ply"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir_ / name;
    write_mesh_file(file, {{"box", &mesh}});
    const std::vector<Mesh::Point> y_up =
        fs::path(name).extension() == ".obj" ? exact_points(file) : ply_points(file, mesh.n_vertices());
    ASSERT_EQ(y_up.size(), mesh.n_vertices());
    for (const auto v : mesh.vertices()) {
      const Mesh::Point& p = mesh.point(v);
      EXPECT_EQ(y_up[static_cast<std::size_t>(v.idx())], Mesh::Point(p[0], p[2], -p[1]));
    }
  }
}

TEST_F(MeshWrite, PlyNamesFaceTags) {
  Mesh mesh = build_mesh(test::box({0, 0, 0}, {1, 1, 1}));
  const auto tags = face_tag_property(mesh);
  for (const auto f : mesh.faces()) mesh.property(tags, f) = f.idx() == 0 ? "base" : "wall";
  const fs::path file = dir_ / "tags.ply";
  write_ply(file, mesh);
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("comment procex_tag 0 base\ncomment procex_tag 1 wall\n"), std::string::npos) << text;
  EXPECT_NE(text.find("property int procex_tag\n"), std::string::npos);
  Mesh back;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(back, file.string()));
  EXPECT_EQ(back.n_faces(), mesh.n_faces());
}

TEST_F(MeshWrite, SeveralMeshesBecomeGroups) {
  const Mesh a = build_mesh(test::box({0, 0, 0}, {1, 1, 1}));
  const Mesh b = build_mesh(test::square_ring());
  const fs::path file = dir_ / "two.obj";
  write_mesh_file(file, {{"w123", &a}, {"my building", &b}});
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("g w123\n"), std::string::npos);
  EXPECT_NE(text.str().find("g my_building\n"), std::string::npos);
  // b's faces point past a's 8 vertices.
  EXPECT_NE(text.str().find("\nf 9 "), std::string::npos);
  Mesh back;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(back, file.string()));
  EXPECT_EQ(back.n_vertices(), a.n_vertices() + b.n_vertices());
  EXPECT_EQ(back.n_faces(), a.n_faces() + b.n_faces());

  const fs::path ply = dir_ / "two.PLY";
  write_mesh_file(ply, {{"w123", &a}, {"my building", &b}});
  Mesh back_ply;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(back_ply, ply.string()));
  EXPECT_EQ(back_ply.n_faces(), a.n_faces() + b.n_faces());
}

TEST_F(MeshWrite, FailuresNameTheFile) {
  const Mesh mesh = build_mesh(test::box({0, 0, 0}, {1, 1, 1}));
  try {
    write_obj(dir_ / "no_such_dir" / "x.obj", mesh);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("x.obj"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_mesh_file(dir_ / "x.stl", {{"m", &mesh}}), IoError);
  // A directory in the way: the rename fails and the temporary file goes.
  fs::create_directory(dir_ / "taken.obj");
  fs::create_directory(dir_ / "taken.obj" / "inside");
  EXPECT_THROW(write_obj(dir_ / "taken.obj", mesh), IoError);
  expect_only(dir_ / "taken.obj");
}

}  // namespace
}  // namespace procex

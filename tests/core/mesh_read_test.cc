// Reading meshes to place: the fixtures in tests/data/mesh_*.obj, good and bad.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/io/io_error.h"
#include "core/io/mesh_read.h"
#include "core/mesh/uv_frames.h"
#include "core/mesh/validate.h"

namespace procex {
namespace {

std::filesystem::path data(const std::string& name) { return std::filesystem::path(PROCEX_TEST_DATA) / name; }

// The IoError's message, or "" if reading succeeded.
std::string read_error(const std::string& name) {
  try {
    read_mesh_file(data(name));
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), data(name).string());
    return e.what();
  }
  return {};
}

TEST(MeshRead, WindowFrameIsAClosedRing) {
  const Mesh m = read_mesh_file(data("mesh_window_frame.obj"));
  EXPECT_EQ(m.n_vertices(), 16u);
  EXPECT_EQ(m.n_faces(), 16u);
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.ok()) << testing::PrintToString(r.problems);
  EXPECT_NEAR(r.volume, (1.2 * 1.5 - 1.0 * 1.3) * 0.1, 1e-12);
  for (const auto f : m.faces()) {
    EXPECT_EQ(face_tag(m, f), "frame");
    EXPECT_EQ(source_edge(m, f), -1);
    EXPECT_EQ(face_kind(m, f), FaceKind::Side);
  }
}

TEST(MeshRead, UsemtlTagsTheFacesAfterIt) {
  const Mesh m = read_mesh_file(data("mesh_dormer_box.obj"));
  ASSERT_EQ(m.n_faces(), 7u);
  for (const auto f : m.faces()) EXPECT_EQ(face_tag(m, f), f.idx() < 5 ? "wall" : "roof") << f.idx();
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.ok()) << testing::PrintToString(r.problems);
  EXPECT_NEAR(r.volume, (1.6 * 1.0 + 0.5 * 1.6 * 0.6) * 1.2, 1e-12);
}

TEST(MeshRead, PillarKeepsItsCoordinates) {
  const Mesh m = read_mesh_file(data("mesh_pillar.obj"));
  ASSERT_EQ(m.n_vertices(), 8u);
  EXPECT_EQ(m.point(Mesh::VertexHandle(2)), Mesh::Point(0.2, 3.0, 0.0));
  EXPECT_EQ(m.point(Mesh::VertexHandle(4)), Mesh::Point(-0.2, 0.0, 0.4));
}

TEST(MeshRead, BadFilesNameTheFileAndLine) {
  EXPECT_NE(read_error("mesh_bad_coordinate.obj").find("line 4: vertex coordinate '1.0.0' is not a finite number"),
            std::string::npos) << read_error("mesh_bad_coordinate.obj");
  EXPECT_NE(read_error("mesh_infinite_coordinate.obj").find("line 4: vertex coordinate '1e999'"), std::string::npos);
  EXPECT_NE(read_error("mesh_face_index_out_of_range.obj").find("line 6: face corner '7' names a vertex that does not exist (4 vertices so far)"),
            std::string::npos) << read_error("mesh_face_index_out_of_range.obj");
  EXPECT_NE(read_error("mesh_face_repeats_vertex.obj").find("line 5: the face visits vertex 2 twice"), std::string::npos);
  EXPECT_NE(read_error("mesh_no_faces.obj").find("has no faces"), std::string::npos);
  EXPECT_NE(read_error("mesh_empty.obj").find("is empty"), std::string::npos) << read_error("mesh_empty.obj");
  EXPECT_NE(read_error("mesh_binary_not_text.obj").find("is not a text OBJ file"), std::string::npos);
  EXPECT_NE(read_error("mesh_that_does_not_exist.obj").find("No such file"), std::string::npos);
  EXPECT_NE(read_error("footprint_bowtie.json").find("use a Wavefront .obj file"), std::string::npos);
  for (const char* name : {"mesh_bad_coordinate.obj", "mesh_empty.obj", "mesh_that_does_not_exist.obj"})
    EXPECT_NE(read_error(name).find(data(name).string()), std::string::npos) << name;
}

TEST(MeshRead, NonManifoldFacesAreKeptWithAWarning) {
  std::vector<std::string> warnings;
  const Mesh m = read_mesh_file(data("mesh_three_faces_at_one_edge.obj"), &warnings);
  EXPECT_EQ(m.n_faces(), 3u);
  EXPECT_GT(m.n_vertices(), 5u);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("duplicated"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("mesh_three_faces_at_one_edge.obj"), std::string::npos);
}

TEST(MeshRead, LineEndingsCommentsAndCornerFormsOfOtherExporters) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "procex_mesh_read_crlf.obj";
  {
    std::ofstream out(file, std::ios::binary);
    out << "# exported elsewhere\r\nmtllib x.mtl\r\no quad\r\nv 0 0 0\r\nv +1 0 0 # a comment\r\nv 1 1 0 1.0\r\n"
           "v 0 1 0\r\nvt 0 0\r\nvn 0 0 1\r\nusemtl  glass pane \r\ns off\r\nf 1/1/1 2/1/1 -2/1/1 -1//1\r\n";
  }
  std::vector<std::string> warnings;
  const Mesh m = read_mesh_file(file, &warnings);
  std::filesystem::remove(file);
  ASSERT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(m.valence(*m.faces().begin()), 4u);
  EXPECT_EQ(face_tag(m, *m.faces().begin()), "glass pane");
  EXPECT_EQ(m.point(Mesh::VertexHandle(1)), Mesh::Point(1, 0, 0));
  // x.mtl is not there: said, and the face keeps its tag.
  ASSERT_EQ(warnings.size(), 1u) << testing::PrintToString(warnings);
  EXPECT_NE(warnings[0].find("line 2: material library 'x.mtl' is not there"), std::string::npos) << warnings[0];
  // The last corner names no texture coordinate: the face has none of its own; all name a normal.
  const auto h = *m.fh_range(*m.faces().begin()).begin();
  const CornerAttribute own = corner_attribute(m, corner_uv_property(m), corner_normal_property(m), h);
  EXPECT_FALSE(own.uv);
  ASSERT_TRUE(own.normal);
  EXPECT_EQ(*own.normal, glm::dvec3(0, 0, 1));
}

}  // namespace
}  // namespace procex

// A placed mesh's own look: its OBJ's texture coordinates and normals (vt,
// vn) and its .mtl materials (Kd, map_Kd) are read, confined like every file
// a recipe names, and kept through flattening (OBJ output) and into glTF
// primitives. The fixture is the sample door, samples/meshes/door_textured.obj.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "base/confined_path.h"
#include "base/read_file.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "core/io/mesh_read.h"
#include "core/mesh/material.h"
#include "tests/support/scratch_dir.h"
#include "core/mesh/uv_frames.h"
#include "core/placement/placement.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(PROCEX_SAMPLES) / "meshes";

class PlacedMaterials : public test::ScratchDirTest {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "meshes");
    for (const char* name : {"door_textured.obj", "door_textured.mtl", "door_planks.png"})
      fs::copy_file(kMeshes / name, dir_ / "meshes" / name);
  }
  void write(const fs::path& file, const std::string& text) { std::ofstream(dir_ / file, std::ios::binary) << text; }
  // The door read as Mesh Placement reads it: confined to dir_, its materials into `materials`.
  Mesh read_door(const std::string& name = "meshes/door_textured.obj", Materials* materials = nullptr) {
    return read_mesh_file(dir_ / name, nullptr, [&](const fs::path& p) { return confined_path(dir_, p.string()); },
                          materials);
  }
  std::string read_error(const std::string& name) {
    try {
      read_door(name);
    } catch (const IoError& e) {
      return e.what();
    }
    return {};
  }
};

TEST_F(PlacedMaterials, ReadsTheLibraryAndEachCornersOwnAttributes) {
  Materials materials;
  const Mesh door = read_door("meshes/door_textured.obj", &materials);
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials.at("door").colour, (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(materials.at("door").texture, fs::canonical(dir_ / "meshes" / "door_planks.png"));
  EXPECT_EQ(materials.at("door_frame").colour, (std::array<double, 3>{0.2, 0.25, 0.3}));
  EXPECT_TRUE(materials.at("door_frame").texture.empty());

  // The front face's corners take the file's vt at their vertices; the other faces have none.
  const auto uv = corner_uv_property(door);
  const auto normal = corner_normal_property(door);
  ASSERT_TRUE(uv.is_valid() && normal.is_valid());
  for (const auto f : door.faces()) {
    for (const auto h : door.fh_range(f)) {
      const CornerAttribute own = corner_attribute(door, uv, normal, h);
      ASSERT_EQ(own.uv.has_value(), f.idx() == 0);
      ASSERT_EQ(own.normal.has_value(), f.idx() == 0);
      if (f.idx() != 0) continue;
      const Mesh::Point& p = door.point(door.to_vertex_handle(h));
      EXPECT_EQ(*own.uv, glm::dvec2(p[0], p[1] / 2.1)) << p;  // the image spans the face
      EXPECT_EQ(*own.normal, glm::dvec3(0, 0, 1));
    }
  }
}

TEST_F(PlacedMaterials, FilesTheLibraryNamesAreConfinedAndChecked) {
  // A library outside the recipe's folder is refused, as every file is.
  write("meshes/out.obj", "mtllib ../../elsewhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(read_error("meshes/out.obj").find("elsewhere.mtl"), std::string::npos);
  // So is a texture outside it.
  write("meshes/far.mtl", "newmtl a\nmap_Kd ../../../etc/passwd\n");
  write("meshes/far.obj", "mtllib far.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
  EXPECT_NE(read_error("meshes/far.obj").find("passwd"), std::string::npos);
  // A texture that is not a PNG or JPEG image.
  write("meshes/text.png", "not an image");
  write("meshes/bad_image.mtl", "newmtl a\nmap_Kd text.png\n");
  write("meshes/bad_image.obj", "mtllib bad_image.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(read_error("meshes/bad_image.obj").find("is not a PNG or JPEG image"), std::string::npos);
  // Malformed statements name their line.
  write("meshes/kd.mtl", "newmtl a\nKd 1 2 0.5\n");
  write("meshes/kd.obj", "mtllib kd.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(read_error("meshes/kd.obj").find("line 2: a colour (Kd) needs three numbers from 0 to 1"), std::string::npos)
      << read_error("meshes/kd.obj");
  write("meshes/options.mtl", "newmtl a\nmap_Kd -s 2 2 1 door_planks.png\n");
  write("meshes/options.obj", "mtllib options.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(read_error("meshes/options.obj").find("no options"), std::string::npos);
  write("meshes/vt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n");
  EXPECT_NE(read_error("meshes/vt.obj").find("line 5: face corner '2/2' names a texture coordinate that does not exist "
                                             "(1 texture coordinates so far)"),
            std::string::npos)
      << read_error("meshes/vt.obj");
  write("meshes/vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 nan\nf 1 2 3\n");
  EXPECT_NE(read_error("meshes/vn.obj").find("line 4: a normal 'nan' is not a finite number"), std::string::npos)
      << read_error("meshes/vn.obj");
}

TEST_F(PlacedMaterials, FlatteningKeepsUvsMaterialsAndTurnsNormals) {
  PlacementResult r;
  Materials materials;
  const auto door = std::make_shared<const Mesh>(read_door("meshes/door_textured.obj", &materials));
  r.add_mesh({"door", door, material_table(materials)});
  // Stood up (a quarter turn about x: the door's z becomes -y) and moved,
  // and mirrored in x: the front's normal turns with the first.
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), M_PI / 2, glm::dvec3(1, 0, 0));
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1));
  r.add_instance({0, glm::translate(glm::dmat4(1.0), glm::dvec3(5, 0, 0)) * turn, "", -1});
  r.add_instance({0, mirror, "", -1});
  const Mesh flat = flatten(r);
  EXPECT_EQ(materials_of(flattened_materials(nullptr, r)), materials);
  const SurfaceAttributes s = surface_attributes(flat);
  ASSERT_EQ(s.corner_normals.size(), s.corner_uvs.size());
  // Instance 0's front face is face 0, instance 1's face 6 (its corners reversed by the mirror).
  std::size_t corner = 0;
  for (const auto f : flat.faces()) {
    for (const auto v : flat.fv_range(f)) {
      const Mesh::Point& p = flat.point(v);
      if (f.idx() == 0) {
        EXPECT_NEAR(glm::distance(s.corner_normals[corner], glm::dvec3(0, -1, 0)), 0, 1e-15);
        EXPECT_NEAR(s.corner_uvs[corner].x, p[0] - 5, 1e-15);
        EXPECT_NEAR(s.corner_uvs[corner].y, p[2] / 2.1, 1e-15);
      } else if (f.idx() == 6) {
        EXPECT_EQ(s.corner_normals[corner], glm::dvec3(0, 0, 1));
        EXPECT_EQ(s.corner_uvs[corner], glm::dvec2(-p[0], p[1] / 2.1));
      } else {
        EXPECT_EQ(s.corner_normals[corner], s.face_normals[static_cast<std::size_t>(f.idx())]);
      }
      ++corner;
    }
  }
}

TEST_F(PlacedMaterials, GltfPrimitivesCarryTheMaterialAndImage) {
  Materials materials;
  const Mesh door = read_door("meshes/door_textured.obj", &materials);
  const std::vector<std::uint32_t> tags = {0, 1, 1, 1, 1, 1};
  const std::vector<std::string> names = {"door", "door_frame"};
  GltfScene scene;
  scene.meshes.push_back(to_gltf_mesh({&door, tags, names, "door", -1, material_table(materials)}));
  const GltfPrimitiveData& front = scene.meshes[0].primitives[0];
  ASSERT_TRUE(front.material && front.material->image);
  EXPECT_EQ(*front.material->image, read_file(dir_ / "meshes" / "door_planks.png", 1 << 20));
  // The image's rows run down: the door's top (its y = 2.1, v = 1) is the
  // image's first row (v = 0). (glTF's -z is the mesh's own y here.)
  for (std::size_t i = 0; i < front.positions.size() / 3; ++i)
    EXPECT_NEAR(front.uvs[2 * i + 1], 1.0 + front.positions[3 * i + 2] / 2.1, 1e-6);
  ASSERT_TRUE(scene.meshes[0].primitives[1].material);
  EXPECT_FALSE(scene.meshes[0].primitives[1].material->image);

  // Written and read back: the same data (so shards merge), the image once.
  write_glb(dir_ / "door.glb", scene);
  const GltfScene back = read_glb_scene(dir_ / "door.glb");
  ASSERT_EQ(back.meshes.size(), 1u);
  EXPECT_EQ(back.meshes[0].primitives, scene.meshes[0].primitives);
}

}  // namespace
}  // namespace procex

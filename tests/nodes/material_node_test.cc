// The Material node: a tag's faces take a PBR look on the buildings and on
// the placed meshes that carry the tag, its texture confined to the recipe's
// folder like every file a recipe names, and an edited texture read again.
#include <array>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "base/read_file.h"
#include "core/io/gltf_write.h"
#include "core/io/mesh_read.h"
#include "core/io/texture_image.h"
#include "core/mesh/material.h"
#include "core/placement/placement.h"
#include "graph/pxg.h"
#include "nodes/support/mesh_export.h"
#include "nodes/values.h"
#include "tests/app/command_test.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::run_node;
const fs::path kSamples = PROCEX_SAMPLES;

using MaterialNode = test::CommandTest;

const MeshSet& mesh_of(const EvalResult& r) {
  const Value* v = r.output("mesh");
  if (!v) throw std::runtime_error("no mesh: " + (r.diagnostics.empty() ? std::string() : r.diagnostics[0].to_string()));
  return v->get<MeshSet>();
}

// The sample's house: every tag it names has its look, the tags it does not
// name (the base) have none, and the geometry is the house's own.
TEST_F(MaterialNode, TexturedHouseGivesEachTagItsLook) {
  const MeshSet set = mesh_of(test::evaluate_mesh(load_pxg(kSamples / "textured_house.pxg"), kSamples));
  ASSERT_EQ(set.parts.size(), 1u);
  const Materials& materials = materials_of(set.parts[0].materials);
  ASSERT_EQ(materials.size(), 4u);
  const Material& wall = materials.at("wall");
  EXPECT_EQ(wall.colour, (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(wall.roughness, 0.85);
  EXPECT_EQ(wall.metallic, 0.0);
  EXPECT_EQ(wall.tile_size, 0.8);
  EXPECT_EQ(wall.texture, fs::canonical(kSamples / "textures" / "brick.png"));
  EXPECT_EQ(materials.at("gable"), wall);
  EXPECT_EQ(materials.at("roof").texture, fs::canonical(kSamples / "textures" / "roof_tiles.png"));
  EXPECT_EQ(materials.at("roof").tile_size, 1.2);
  EXPECT_EQ(materials.at("soffit").colour, (std::array<double, 3>{0.9, 0.9, 0.85}));
  EXPECT_TRUE(materials.at("soffit").texture.empty());
  EXPECT_FALSE(materials.contains("base"));

  const MeshSet plain = mesh_of(test::evaluate_mesh(load_pxg(kSamples / "house.pxg"), kSamples));
  EXPECT_EQ(plain.parts[0].mesh->n_faces(), set.parts[0].mesh->n_faces());
  EXPECT_TRUE(materials_of(plain.parts[0].materials).empty());
}

// A texture saved after its material was made (a batch running while the
// artist paints) changes nothing made from it: the .glb embeds the image the
// material was made with, the one the building's key holds.
TEST_F(MaterialNode, AMeshKeepsTheImageItsMaterialWasMadeWith) {
  fs::create_directories(dir_ / "textures");
  fs::copy_file(kSamples / "textures" / "brick.png", dir_ / "textures" / "brick.png");
  fs::copy_file(kSamples / "textures" / "roof_tiles.png", dir_ / "textures" / "roof_tiles.png");
  const MeshSet set = mesh_of(test::evaluate_mesh(load_pxg(kSamples / "textured_house.pxg"), dir_));
  const std::string brick = read_file(kSamples / "textures" / "brick.png", kMaxTextureBytes);
  fs::copy_file(kSamples / "textures" / "roof_tiles.png", dir_ / "textures" / "brick.png",
                fs::copy_options::overwrite_existing);
  const GltfScene scene = to_gltf(set);
  ASSERT_EQ(scene.meshes.size(), 1u);
  int walls = 0;
  for (const GltfPrimitiveData& p : scene.meshes[0].primitives)
    if (p.tag == "wall") {
      ++walls;
      ASSERT_TRUE(p.material && p.material->image);
      EXPECT_TRUE(*p.material->image == brick) << "the .glb would embed the image saved since";
    }
  EXPECT_EQ(walls, 1);
}

// One part: the window frame's mesh, every face tagged wall.
MeshSet window_as_wall() {
  MeshSet set;
  TaggedMesh& part = set.parts.emplace_back();
  part.mesh = std::make_shared<const Mesh>(read_mesh_file(fs::path(PROCEX_TEST_DATA) / "mesh_window_frame.obj"));
  part.face_tags.assign(part.mesh->n_faces(), 0);
  part.tags = {"wall"};
  return set;
}

// A placed mesh's faces of the tag take the look, its own material of that
// name replaced; every instance still shares one mesh, the very mesh placed
// (the look is beside it, not in it), and the input is left as it was
// (values are immutable).
TEST_F(MaterialNode, PlacedMeshesOfTheTagTakeItAndStayShared) {
  MeshSet in = window_as_wall();
  TaggedMesh& part = in.parts[0];
  const std::size_t window = part.placed.add_mesh({"window", part.mesh});
  for (int i = 0; i < 3; ++i) part.placed.add_instance({window, glm::dmat4(1.0), "", -1});
  const auto r = run_node("Material", {{"tag", Value::make(std::string("frame"))}, {"metallic", Value::make(1.0)},
                                       {"roughness", Value::make(0.2)}},
                          {{"mesh", Value::make(in)}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const TaggedMesh& out = r.outputs.at(0).get<MeshSet>().parts.at(0);
  EXPECT_EQ(out.mesh, part.mesh);  // the building has no face tagged frame: not copied
  ASSERT_EQ(out.placed.meshes.size(), 1u);
  EXPECT_EQ(out.placed.meshes[0].mesh, part.mesh);
  const Material& frame = materials_of(out.placed.meshes[0].materials).at("frame");
  EXPECT_EQ(frame.metallic, 1.0);
  EXPECT_EQ(frame.roughness, 0.2);
  EXPECT_TRUE(materials_of(part.placed.meshes[0].materials).empty());
  EXPECT_TRUE(materials_of(out.materials).empty());

  const auto none = run_node("Material", {{"tag", Value::make(std::string("chimney"))}}, {{"mesh", Value::make(in)}});
  ASSERT_TRUE(none.ok()) << none.messages();
  EXPECT_NE(none.messages().find("no face is tagged 'chimney'"), std::string::npos) << none.messages();
}

// A building's faces take the look without a copy of the building: the part
// keeps the input's mesh and gets a new table beside it, and a second node
// adds to that table without touching the first's.
TEST_F(MaterialNode, ABuildingsLookIsATableBesideItsSharedMesh) {
  MeshSet in = window_as_wall();
  TaggedMesh& part = in.parts[0];
  const auto walls = run_node("Material", {{"tag", Value::make(std::string("wall"))}, {"roughness", Value::make(0.3)}},
                              {{"mesh", Value::make(in)}});
  ASSERT_TRUE(walls.ok()) << walls.messages();
  const TaggedMesh& walled = walls.outputs.at(0).get<MeshSet>().parts.at(0);
  EXPECT_EQ(walled.mesh, part.mesh);
  EXPECT_EQ(materials_of(walled.materials).at("wall").roughness, 0.3);
  EXPECT_EQ(part.materials, nullptr);

  const auto again = run_node("Material", {{"tag", Value::make(std::string("wall"))}, {"metallic", Value::make(1.0)}},
                              {{"mesh", walls.outputs.at(0)}});
  ASSERT_TRUE(again.ok()) << again.messages();
  const TaggedMesh& twice = again.outputs.at(0).get<MeshSet>().parts.at(0);
  EXPECT_EQ(twice.mesh, part.mesh);
  EXPECT_EQ(materials_of(twice.materials).at("wall").metallic, 1.0);
  EXPECT_EQ(materials_of(walled.materials).at("wall").metallic, 0.0);
}

// A batch runs each building through the same Material nodes: the second
// building gets the first one's table, not a copy of its own, and another
// look is another table.
TEST_F(MaterialNode, BuildingsThroughTheSameNodesShareOneTable) {
  const auto look = [](const MeshSet& in, double roughness) {
    const auto r = run_node("Material", {{"tag", Value::make(std::string("wall"))}, {"roughness", Value::make(roughness)}},
                            {{"mesh", Value::make(in)}});
    EXPECT_TRUE(r.ok()) << r.messages();
    return r.outputs.at(0).get<MeshSet>().parts.at(0).materials;
  };
  const MeshSet first = window_as_wall(), second = window_as_wall();
  ASSERT_NE(first.parts[0].mesh, second.parts[0].mesh);
  const MaterialTable table = look(first, 0.3);
  EXPECT_EQ(look(second, 0.3), table);
  const MaterialTable other = look(second, 0.4);
  EXPECT_NE(other, table);
  EXPECT_EQ(materials_of(other).at("wall").roughness, 0.4);
  EXPECT_EQ(materials_of(table).at("wall").roughness, 0.3);
}

TEST_F(MaterialNode, RefusesAColourOutsideZeroToOneAndAMissingTag) {
  MeshSet in;
  const auto bright = run_node("Material", {{"colour", Value::make(Vec3{1.5, 0, 0})}}, {{"mesh", Value::make(in)}});
  EXPECT_FALSE(bright.ok());
  EXPECT_NE(bright.messages().find("colour:"), std::string::npos) << bright.messages();
  const auto untagged = run_node("Material", {{"tag", Value::make(std::string())}}, {{"mesh", Value::make(in)}});
  EXPECT_FALSE(untagged.ok());
  EXPECT_NE(untagged.messages().find("tag:"), std::string::npos) << untagged.messages();
}

// A recipe whose texture leads out of its folder is refused, the error
// naming the node, the parameter and the file; a file that is not an image
// is refused too, inside the folder.
TEST_F(MaterialNode, TextureOutsideTheRecipesFolderIsRefused) {
  fs::create_directories(dir_ / "recipe");
  fs::copy(kSamples / "textures", dir_ / "recipe" / "textures");
  fs::copy_file(kSamples / "textures" / "brick.png", dir_ / "secret.png");
  std::ifstream in(kSamples / "textured_house.pxg");
  std::string recipe((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string brick = "\"textures/roof_tiles.png\"";
  recipe.replace(recipe.find(brick), brick.size(), "\"../secret.png\"");
  std::ofstream(dir_ / "recipe" / "escape.pxg") << recipe;
  const EvalResult r = test::evaluate_mesh(load_pxg(dir_ / "recipe" / "escape.pxg"), dir_ / "recipe");
  EXPECT_FALSE(r.ok());
  std::string messages;
  for (const Diagnostic& d : r.diagnostics) messages += d.to_string() + "\n";
  EXPECT_NE(messages.find("error: node 9 (Material): texture: '../secret.png' lies outside the recipe's folder"),
            std::string::npos)
      << messages;

  std::ofstream(dir_ / "recipe" / "notes.png") << "not an image";
  const auto fake = run_node("Material", {{"texture", Value::make(std::string("notes.png"))}},
                             {{"mesh", Value::make(MeshSet{})}}, dir_ / "recipe");
  EXPECT_FALSE(fake.ok());
  EXPECT_NE(fake.messages().find("is not a PNG or JPEG image"), std::string::npos) << fake.messages();
}

// The texture's size and time are in the node's key: an edited image is read
// again, an unchanged one is not.
TEST_F(MaterialNode, AnEditedTextureChangesTheKey) {
  fs::create_directories(dir_ / "textures");
  fs::copy_file(kSamples / "textures" / "brick.png", dir_ / "textures" / "brick.png");
  fs::copy_file(kSamples / "textures" / "roof_tiles.png", dir_ / "textures" / "roof_tiles.png");
  const Graph g = load_pxg(kSamples / "textured_house.pxg");
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "material test");
  EvalOptions options;
  options.folder = dir_;
  const auto key = [&] { return ev.hash_outputs(g, {}, {}, options).outputs.at(0).hash; };
  const Hash128 before = key();
  EXPECT_EQ(key(), before);
  std::ofstream(dir_ / "textures" / "brick.png", std::ios::app) << "x";  // one byte longer
  EXPECT_NE(key(), before);
}

// Two meshes whose materials share a name but not a look (two placed
// meshes' libraries each with a "frame") keep both looks in an OBJ's library:
// the second under frame_2.
TEST_F(MaterialNode, TwoLooksUnderOneNameAreTwoObjMaterials) {
  MeshSet set;
  for (const double red : {1.0, 0.0}) {
    Mesh mesh = read_mesh_file(fs::path(PROCEX_TEST_DATA) / "mesh_window_frame.obj");
    Material look;
    look.colour = {red, 0.0, 1.0 - red};
    TaggedMesh& part = set.parts.emplace_back();
    part.materials = material_table({{"frame", look}});
    part.face_tags.assign(mesh.n_faces(), 0);
    part.tags = {"frame"};
    part.building = red > 0 ? "a" : "b";
    part.mesh = std::make_shared<const Mesh>(std::move(mesh));
  }
  write_mesh_set(dir_ / "frames.obj", set);
  const std::string mtl = test::read_text(dir_ / "frames.mtl"), obj = test::read_text(dir_ / "frames.obj");
  EXPECT_NE(mtl.find("newmtl frame\nKd 1 0 0\n"), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl frame_2\nKd 0 0 1\n"), std::string::npos) << mtl;
  EXPECT_LT(obj.find("usemtl frame\n"), obj.find("o b\n"));
  EXPECT_GT(obj.find("usemtl frame_2\n"), obj.find("o b\n"));
}

// A placed mesh's material library and the texture it names are read again
// when edited, though the OBJ is not: the evaluation that follows (one cache,
// as the studio keeps) shows the library's new colour, and the .glb written
// from it embeds the new image. Each edit keeps the file's size.
TEST_F(MaterialNode, AnEditedLibraryOrItsTextureIsReadAgain) {
  fs::copy(kSamples / "meshes", dir_ / "meshes", fs::copy_options::recursive);
  std::ifstream in(kSamples / "windows_grid.pxg");
  std::string recipe((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string window = "\"file\": \"meshes/window_frame.obj\"";
  ASSERT_NE(recipe.find(window), std::string::npos);
  recipe.replace(recipe.find(window), window.size(), "\"file\": \"meshes/door_textured.obj\"");
  std::ofstream(dir_ / "doors.pxg") << recipe;
  const Graph g = load_pxg(dir_ / "doors.pxg");
  ResultCache cache(64 << 20);
  Evaluator ev(cache, "material test");
  EvalOptions options;
  options.folder = dir_;
  // The door's look of `tag` after an evaluation, and the .glb written from it.
  const auto door = [&](const std::string& tag) {
    const EvalResult r = ev.evaluate(g, {}, {"mesh"}, options);
    const MeshSet& set = mesh_of(r);
    write_mesh_set(dir_ / "doors.glb", set);
    for (const PlaceableMesh& m : set.parts.at(0).placed.meshes)
      if (const auto it = materials_of(m.materials).find(tag); it != materials_of(m.materials).end()) return it->second;
    ADD_FAILURE() << "no placed mesh has a material " << tag;
    return Material{};
  };
  const auto key = [&] { return ev.hash_outputs(g, {}, {"mesh"}, options).outputs.at(0).hash; };
  const Hash128 first = key();
  EXPECT_EQ(door("door_frame").colour, (std::array{0.2, 0.25, 0.3}));
  EXPECT_EQ(key(), first);
  const std::string planks = test::read_text(dir_ / "meshes" / "door_planks.png");
  EXPECT_NE(test::read_text(dir_ / "doors.glb").find(planks), std::string::npos);

  const fs::path library = dir_ / "meshes" / "door_textured.mtl";
  std::string text = test::read_text(library);
  ASSERT_NE(text.find("Kd 0.2 0.25 0.3"), std::string::npos);
  text.replace(text.find("Kd 0.2 0.25 0.3"), 15, "Kd 0.7 0.25 0.3");
  std::ofstream(library) << text;
  const Hash128 second = key();
  EXPECT_NE(second, first);
  EXPECT_EQ(door("door_frame").colour, (std::array{0.7, 0.25, 0.3}));

  std::string edited = planks;
  edited[edited.size() - 20] ^= 0x55;  // a byte of the last chunk, the PNG signature kept
  std::ofstream(dir_ / "meshes" / "door_planks.png", std::ios::binary) << edited;
  EXPECT_NE(key(), second);
  door("door");
  const std::string glb = test::read_text(dir_ / "doors.glb");
  EXPECT_NE(glb.find(edited), std::string::npos);
  EXPECT_EQ(glb.find(planks), std::string::npos);
}

}  // namespace
}  // namespace procex

// GltfMeshSpool: buildings set aside come back as they were, in any order,
// a material image shared by several shared again.
#include "core/io/gltf_mesh_spool.h"

#include <filesystem>

#include <gtest/gtest.h>

namespace procex {
namespace {

GltfMeshData building(int i, const std::shared_ptr<const std::string>& image) {
  GltfMeshData b;
  b.building = std::string("b").append(std::to_string(i));  // (append: g++ 12 warns falsely on "b" + ...)
  b.feature = 1000 + i;
  b.origin = {i + 0.25, -3.5, 1e7};
  b.properties = {{"height", std::to_string(i)}, {"name", "\"x\\u00e9\""}};
  b.parameters = {{"pitch", "40"}};
  for (int t = 0; t < i % 3 + 1; ++t) {
    GltfPrimitiveData& p = b.primitives.emplace_back();
    p.tag = t ? "roof" : "wall";
    p.positions = {0, 1, 2, 3.5f, 4, 5, 6, 7, static_cast<float>(i)};
    p.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    p.indices = {0, 1, 2};
    if (t == 1) p.uvs = {0, 0, 1, 0, 1, 1};
    if (t == 2) p.material = GltfMaterialData{{0.5, 0.25, 0.125}, 0.7, 0.1, 2.0, image};
  }
  b.instances.push_back({static_cast<std::size_t>(i % 2), glm::dmat4(1.0 + i), "shutter"});
  return b;
}

TEST(GltfMeshSpool, BuildingsComeBackAsTheyWere) {
  const auto image = std::make_shared<const std::string>("\x89PNG not really");
  GltfMeshSpool spool(std::filesystem::temp_directory_path().string());
  std::vector<GltfMeshSpool::Place> places;
  for (int i = 0; i < 40; ++i) places.push_back(spool.add(building(i, i % 4 ? image : std::make_shared<const std::string>(*image))));
  std::shared_ptr<const std::string> seen;
  for (int i = 39; i >= 0; --i) {
    const GltfMeshData want = building(i, image), got = spool.get(places[static_cast<std::size_t>(i)]);
    EXPECT_EQ(got.building, want.building);
    EXPECT_EQ(got.feature, want.feature);
    EXPECT_EQ(got.origin, want.origin);
    EXPECT_EQ(got.properties, want.properties);
    EXPECT_EQ(got.parameters, want.parameters);
    EXPECT_EQ(got.primitives, want.primitives);  // materials' images compared by their bytes
    ASSERT_EQ(got.instances.size(), 1u);
    EXPECT_EQ(got.instances[0].prototype, want.instances[0].prototype);
    EXPECT_EQ(got.instances[0].transform, want.instances[0].transform);
    EXPECT_EQ(got.instances[0].tag, "shutter");
    for (const GltfPrimitiveData& p : got.primitives) {
      if (!p.material) continue;
      if (seen) {
        EXPECT_EQ(p.material->image, seen);  // one image, however many buildings show it
      }
      seen = p.material->image;
    }
  }
  EXPECT_TRUE(seen);
}

}  // namespace
}  // namespace procex

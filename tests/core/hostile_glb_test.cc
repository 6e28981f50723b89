// What `procex merge` reads, crafted: accessor counts and offsets chosen to
// overflow the bounds check, and buffers that point at files outside the
// shard. Each is refused with an IoError naming the file; nothing outside
// the file's own bytes is ever read (the ASan build checks the copies).

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xff);
}

// A glTF binary container around json and bin, each padded as the format asks.
std::string glb(std::string json, std::string bin) {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string out = "glTF";
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  put_u32(out, static_cast<std::uint32_t>(json.size()));
  out += "JSON" + json;
  if (!bin.empty()) {
    put_u32(out, static_cast<std::uint32_t>(bin.size()));
    out += std::string("BIN\0", 4) + bin;
  }
  return out;
}

// One triangle: positions and normals at 0 and 36, indices at 72 (84 bytes),
// with the positions accessor's count and byteOffset given.
std::string triangle_json(const std::string& count, const std::string& offset, const std::string& buffer = R"({"byteLength": 84})") {
  return R"({"asset": {"version": "2.0"}, "buffers": [)" + buffer + R"(],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 72}, {"buffer": 0, "byteOffset": 72, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + count + R"(, "type": "VEC3", "byteOffset": )" + offset + R"(},
                  {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "byteOffset": 36},
                  {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

std::string triangle_bin() {
  std::string bin(84, '\0');
  const std::uint32_t indices[3] = {0, 1, 2};
  std::memcpy(bin.data() + 72, indices, sizeof indices);
  return bin;
}

std::string error_of(const std::string& bytes) {
  try {
    parse_glb_scene(bytes, "crafted.glb");
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), "crafted.glb");
    return e.what();
  }
  return "read without error";
}

TEST(HostileGlb, TheCraftedTriangleReadsWhenHonest) {
  const GltfScene scene = parse_glb_scene(glb(triangle_json("3", "0"), triangle_bin()), "honest.glb");
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].primitives.at(0).positions.size(), 9u);
}

TEST(HostileGlb, CountsAndOffsetsThatOverflowAreRefused) {
  for (const auto& [count, offset] : {std::pair<std::string, std::string>{"4611686018427387904", "0"},  // 2^62
                                      {"3", "18446744073709551600"},                                     // near 2^64
                                      {"3", "4294967292"},                                               // wraps 32 bits
                                      {"1537228672809129302", "0"},  // count * 12 wraps to a small size
                                      {"4", "0"}}) {                 // simply past the view
    const std::string why = error_of(glb(triangle_json(count, offset), triangle_bin()));
    EXPECT_NE(why.find("crafted.glb"), std::string::npos) << count << " " << offset << ": " << why;
  }
}

TEST(HostileGlb, DeepExtrasAreRefused) {
  std::string json = triangle_json("3", "0");
  json.insert(json.rfind('}'), R"(, "extras": {"x": )" + std::string(80000, '[') + std::string(80000, ']') + "}");
  EXPECT_NE(error_of(glb(json, triangle_bin())).find("nested deeper than 64 levels"), std::string::npos);
}

TEST(HostileGlb, ExternalBuffersAreRefused) {
  const test::ScratchDir dir("hostile_glb");
  std::ofstream(dir / "secret.bin", std::ios::binary) << triangle_bin();
  const std::string json = triangle_json("3", "0", R"({"byteLength": 84, "uri": ")" + (dir / "secret.bin").string() + "\"}");
  const std::string why = error_of(glb(json, ""));
  EXPECT_NE(why.find("external file"), std::string::npos) << why;
  const std::string relative = triangle_json("3", "0", R"({"byteLength": 84, "uri": "../../../../../../etc/passwd"})");
  EXPECT_NE(error_of(glb(relative, "")).find("crafted.glb"), std::string::npos);
}

}  // namespace
}  // namespace procex

// procex merge of parts someone else may have made: merge reads a part's
// buffer views and accessors by the ranges the part states, so a part whose
// binary chunk is cut short, whose accessor runs past its view or whose view's
// length wraps past 2^64 is refused with a message naming the part and what
// is wrong, and nothing is written (the ASan build checks that no byte
// outside the part is read).
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/merge_command.h"
#include "core/io/gltf_write.h"
#include "tests/app/command_test.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::read_text;

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xff);
}

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

// A glTF binary around json and bin, each padded as the format asks.
std::string glb(std::string json_text, std::string bin) {
  while (json_text.size() % 4) json_text += ' ';
  std::string out = "glTF";
  put_u32(out, 2);
  put_u32(out, static_cast<std::uint32_t>(12 + 8 + json_text.size() + 8 + bin.size()));
  put_u32(out, static_cast<std::uint32_t>(json_text.size()));
  out += "JSON" + json_text;
  put_u32(out, static_cast<std::uint32_t>(bin.size()));
  out += std::string("BIN\0", 4) + bin;
  return out;
}

class MergeHostileParts : public test::CommandTest {
 protected:
  // Shard i of 2 of one run: building i, one triangle (views: positions 0-36,
  // normals 36-72, indices 72-84, tags 84-96; accessors in that order).
  fs::path part(int i, const std::string& name) {
    GltfScene scene;
    GltfMeshData& b = scene.meshes.emplace_back();
    b.building = "b" + std::to_string(i), b.feature = i;
    GltfPrimitiveData& p = b.primitives.emplace_back();
    p.tag = "wall";
    p.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    p.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    p.indices = {0, 1, 2};
    scene.extras["shard"] = R"({"count":2,"footprints":"f","index":)" + std::to_string(i) + R"(,"recipe":"r"})";
    write_glb(dir_ / name, scene);
    return dir_ / name;
  }
  // Part 1 with its JSON changed by edit (the file put together again).
  fs::path edited(const std::function<void(json&)>& edit) {
    const std::string bytes = read_text(part(1, "honest.glb"));
    const std::uint32_t json_length = u32_at(bytes, 12);
    json doc = json::parse(bytes.substr(20, json_length));
    edit(doc);
    std::ofstream(dir_ / "hostile.glb", std::ios::binary) << glb(doc.dump(), bytes.substr(20 + json_length + 8));
    return dir_ / "hostile.glb";
  }
  // Merges part 0 and the hostile part: refused, the hostile part named with
  // `why`, no output.
  void expect_refused(const fs::path& hostile, const std::string& why) {
    MergeCommandOptions merge{{part(0, "good.glb"), hostile}, dir_ / "merged.glb", {}};
    EXPECT_EQ(run_merge(merge, out_, err_), 2);
    const std::string said = err_.str();
    EXPECT_NE(said.find("'" + hostile.string() + "' is not a .glb as procex writes it: "), std::string::npos) << said;
    EXPECT_NE(said.find(why), std::string::npos) << said;
    EXPECT_EQ(said.find("good.glb"), std::string::npos) << said;
    EXPECT_FALSE(fs::exists(merge.output));
    err_.str("");
  }
};

TEST_F(MergeHostileParts, TheHonestPartsMerge) {
  MergeCommandOptions merge{{part(0, "a.glb"), edited([](json&) {})}, dir_ / "merged.glb", {}};
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  EXPECT_NE(out_.str().find("2 parts, 2 meshes"), std::string::npos) << out_.str();
}

TEST_F(MergeHostileParts, ATruncatedBinaryChunkIsRefused) {
  // The file cut short: its header's length no longer matches.
  std::string bytes = read_text(part(1, "whole.glb"));
  bytes.resize(bytes.size() - 40);
  std::ofstream(dir_ / "cut.glb", std::ios::binary) << bytes;
  expect_refused(dir_ / "cut.glb", "cut short");
  // Cut short with the header's length made to match: the binary chunk's own length runs past the end.
  const std::uint32_t size = static_cast<std::uint32_t>(bytes.size());
  bytes.replace(8, 4, std::string(reinterpret_cast<const char*>(&size), 4));
  std::ofstream(dir_ / "cut.glb", std::ios::binary) << bytes;
  expect_refused(dir_ / "cut.glb", "its binary chunk of 96 bytes runs past the file's end (56 bytes are left");
  // The buffer longer than the binary chunk that holds it.
  expect_refused(edited([](json& doc) { doc["buffers"][0]["byteLength"] = 1000; }),
                 "buffer 0 is 1000 bytes but its binary chunk holds 96");
}

TEST_F(MergeHostileParts, AnAccessorBeyondItsBufferViewIsRefused) {
  expect_refused(edited([](json& doc) { doc["accessors"][0]["count"] = 4; }),
                 "accessor 0 runs past its buffer view 0 of 36 bytes");
  expect_refused(edited([](json& doc) { doc["accessors"][2]["byteOffset"] = 4; }),
                 "accessor 2 runs past its buffer view 2 of 12 bytes");
  // A count whose size wraps 64 bits to a small number.
  expect_refused(edited([](json& doc) { doc["accessors"][0]["count"] = std::uint64_t{1537228672809129302}; }),
                 "accessor 0 runs past its buffer view");
  expect_refused(edited([](json& doc) { doc["accessors"][1]["bufferView"] = 9; }), "accessor 1 has no buffer view");
}

TEST_F(MergeHostileParts, ABufferViewWhoseLengthOverflowsIsRefused) {
  // Offset + length wraps 2^64 to 20: within the buffer, were it summed.
  expect_refused(edited([](json& doc) {
                   doc["bufferViews"][1]["byteOffset"] = 36;
                   doc["bufferViews"][1]["byteLength"] = std::uint64_t{18446744073709551600u};
                 }),
                 "buffer view 1 (bytes 36 to 36 + 18446744073709551600) runs past its buffer of 96 bytes");
  expect_refused(edited([](json& doc) { doc["bufferViews"][2]["byteLength"] = 100; }),
                 "buffer view 2 (bytes 72 to 72 + 100) runs past its buffer of 96 bytes");
  expect_refused(edited([](json& doc) { doc["bufferViews"][0]["byteLength"] = -4; }),
                 "buffer view 0's byteLength is not an index");
}

TEST_F(MergeHostileParts, BrokenJsonAndMissingElementsAreNamed) {
  expect_refused(edited([](json& doc) { doc["nodes"] = json::object(); }), "nodes is not an array");
  expect_refused(edited([](json& doc) { doc["nodes"][0]["mesh"] = 7; }), "mesh 7 is missing");
  expect_refused(edited([](json& doc) { doc["scenes"][0]["nodes"][0] = 3; }), "node 3 is missing");
  expect_refused(edited([](json& doc) { doc["meshes"][0]["primitives"][0]["material"] = 5; }), "material 5 is missing");
  std::string bytes = read_text(part(1, "syntax.glb"));
  bytes[20] = '#';  // the JSON chunk's first byte
  std::ofstream(dir_ / "syntax.glb", std::ios::binary) << bytes;
  expect_refused(dir_ / "syntax.glb", "its JSON is not valid at byte");
}

}  // namespace
}  // namespace procex

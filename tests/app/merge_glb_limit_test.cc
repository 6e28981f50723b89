// procex merge of parts whose buildings are more than one .glb holds (4 GiB)
// is refused before any building is read, naming the parts and what to do.
// The parts are real shards of a batch made to claim gigabytes: their buffer
// and binary chunk grown by zeros the file system keeps sparse (nothing
// past the shard's own bytes is written), a file GlbReader reads as it is.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli/batch_command.h"
#include "app/cli/merge_command.h"
#include "app/cli/recipe_session.h"
#include "core/io/glb_read.h"
#include "tests/app/command_test.h"
#include "tests/app/generated_footprints.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::read_text;

const fs::path kSamples = PROCEX_SAMPLES;
constexpr std::uint64_t kClaimed = std::uint64_t{1450} << 20;  // 1.45 GiB a part: three pass 4 GiB, two do not

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(s[at + static_cast<std::size_t>(k)]);
  return v;
}

void append_u32(std::string& s, std::uint64_t v) {
  for (int k = 0; k < 4; ++k) s += static_cast<char>((v >> (8 * k)) & 0xff);
}

// Replaces the digits after the first `key` found from `from` on.
void set_number(std::string& json, const std::string& key, std::size_t from, const std::string& digits) {
  const std::size_t at = json.find(key, from);
  ASSERT_NE(at, std::string::npos) << key;
  const std::size_t begin = at + key.size(), end = json.find_first_not_of("0123456789", begin);
  json.replace(begin, end - begin, digits);
}

// A copy of shard `from` that claims about `claimed` bytes: its buffer and
// binary chunk longer by zeros (sparse); its buildings as they were, or with
// a building's translation given four numbers, which reading that building
// refuses (only buildings' nodes have a translation; instances a matrix).
void inflate(const fs::path& from, const fs::path& to, std::uint64_t claimed, bool break_a_building = false) {
  const std::string glb = read_text(from);
  const std::uint32_t json_length = u32_at(glb, 12);
  std::string json = glb.substr(20, json_length);
  const std::string bin = glb.substr(20 + json_length + 8);
  ASSERT_EQ(bin.size(), u32_at(glb, 20 + json_length));
  const std::string buffer_key = "\"buffers\":[{\"byteLength\":";
  const std::size_t buffer_at = json.find(buffer_key) + buffer_key.size();
  const std::uint64_t buffer = std::stoull(json.substr(buffer_at));
  if (break_a_building) {
    const std::size_t at = json.find("\"translation\":[");
    ASSERT_NE(at, std::string::npos);
    json.insert(at + 15, "0,");
  }
  while (json.back() == ' ') json.pop_back();
  const std::uint64_t extra = (claimed - 28 - json.size() - 16 - bin.size()) / 4 * 4;  // 16: room for longer digits
  set_number(json, buffer_key, 0, std::to_string(buffer + extra));
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::string head = "glTF";
  append_u32(head, 2);
  const std::uint64_t total = 12 + 8 + json.size() + 8 + bin.size() + extra;
  append_u32(head, total);
  append_u32(head, json.size());
  head += "JSON";
  std::string bin_head;
  append_u32(bin_head, bin.size() + extra);
  bin_head += std::string("BIN\0", 4);
  {
    std::ofstream out(to, std::ios::binary);
    out << head << json << bin_head << bin;
  }
  fs::resize_file(to, total);
  ASSERT_EQ(GlbReader::length(to), total);
}

class MergeGlbLimit : public test::CommandTest {
 protected:
  // The .glb shards of a batch of 60 generated footprints split n ways.
  std::vector<fs::path> shards(std::size_t n) {
    if (!fs::exists(dir_ / "footprints.geojson")) test::write_footprints(dir_ / "footprints.geojson", 60);
    std::vector<fs::path> out;
    for (std::size_t i = 0; i < n; ++i) {
      BatchCommandOptions o;
      o.recipe = kSamples / "city.pxg";
      o.footprints = dir_ / "footprints.geojson";
      o.output = dir_ / std::string("s").append(std::to_string(i)).append("of").append(std::to_string(n)).append(".glb");
      o.shard = i, o.shards = n, o.progress = false;
      EXPECT_EQ(run_batch(o, out_, err_), 0) << err_.str();
      out.push_back(o.output);
    }
    return out;
  }
  std::vector<fs::path> inflated(const std::vector<fs::path>& parts, bool break_the_last = false) {
    std::vector<fs::path> out;
    for (const fs::path& p : parts) {
      out.push_back(fs::path(p).replace_extension(".big.glb"));
      inflate(p, out.back(), kClaimed, break_the_last && &p == &parts.back());
    }
    return out;
  }
  int merge(const std::vector<fs::path>& parts, const std::string& output) {
    err_.str("");
    return run_merge({parts, dir_ / output, {}}, out_, err_);
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
};

// Three parts claiming 4.35 GiB, the last with a building that cannot be
// read: refused by the limit (so before that building was read), each part
// named, and nothing written.
TEST_F(MergeGlbLimit, PartsPastTheLimitAreRefusedBeforeAnyBuildingIsRead) {
  const std::vector<fs::path> parts = shards(3);
  // The broken building, read, stops a merge that fits.
  const std::vector<fs::path> broken = {parts[0], parts[1], dir_ / "broken.glb"};
  inflate(parts[2], broken[2], fs::file_size(parts[2]) + 64, true);
  EXPECT_EQ(merge(broken, "fits.glb"), kExitUnusableInput);
  const std::string unreadable = "broken.glb' is not a .glb as procex writes it: building node ";
  EXPECT_NE(err_.str().find(unreadable), std::string::npos) << err_.str();
  EXPECT_NE(err_.str().find("translation is not 3 numbers"), std::string::npos) << err_.str();

  const std::vector<fs::path> big = inflated(parts, true);
  const std::vector<std::string> before = names();
  EXPECT_EQ(merge(big, "merged.glb"), kExitUnusableInput);
  const std::string message = err_.str();
  EXPECT_NE(message.find("procex merge: refused: the 3 parts ("), std::string::npos) << message;
  for (const fs::path& p : big) EXPECT_NE(message.find(p.string() + " 1.5 GB"), std::string::npos) << message;
  EXPECT_NE(message.find("4.6 GB in all) hold "), std::string::npos) << message;
  EXPECT_NE(message.find("more than a .glb holds (4 GiB); nothing written to " + (dir_ / "merged.glb").string()),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("Keep the shards as separate .glb files"), std::string::npos) << message;
  EXPECT_NE(message.find("(at least 2 groups)"), std::string::npos) << message;
  EXPECT_EQ(message.find("translation is not 3 numbers"), std::string::npos) << "a building was read: " << message;
  EXPECT_EQ(names(), before);  // no output, no temporary file
}

// Two such parts (2.9 GiB claimed) are not refused: their buildings merge
// into the bytes the parts they were made from merge into.
TEST_F(MergeGlbLimit, PartsUnderTheLimitMergeAsBefore) {
  const std::vector<fs::path> parts = shards(2);
  ASSERT_EQ(merge(parts, "small.glb"), 0) << err_.str();
  ASSERT_EQ(merge(inflated(parts), "big.glb"), 0) << err_.str();
  EXPECT_TRUE(read_text(dir_ / "big.glb") == read_text(dir_ / "small.glb"));
}

}  // namespace
}  // namespace procex

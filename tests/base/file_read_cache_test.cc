// FileReadCache: a file is read once per version, however many other files
// are read meanwhile (a batch whose recipe names many meshes keeps each one),
// and its new version replaces the old one.
#include "base/file_read_cache.h"

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace procex {
namespace {

TEST(FileReadCache, ReadsAFileOncePerVersionHoweverManyFilesItHolds) {
  FileReadCache<int, std::string> cache;
  int reads = 0;
  const auto get = [&](const std::string& file, int version) {
    return cache.get(file, version, [&] {
      ++reads;
      return file + "@" + std::to_string(version);
    });
  };
  for (int round = 0; round < 3; ++round)
    for (int f = 0; f < 1000; ++f) EXPECT_EQ(get("mesh" + std::to_string(f), 1), "mesh" + std::to_string(f) + "@1");
  EXPECT_EQ(reads, 1000);

  EXPECT_EQ(get("mesh7", 2), "mesh7@2");  // edited: read again
  EXPECT_EQ(get("mesh7", 2), "mesh7@2");
  EXPECT_EQ(reads, 1001);
  EXPECT_EQ(get("mesh7", 1), "mesh7@1");  // the old version was not kept
  EXPECT_EQ(reads, 1002);
}

TEST(FileReadCache, WorkersAskingAtOnceReadOnce) {
  FileReadCache<int, int> cache;
  std::atomic<int> reads{0};
  std::vector<std::thread> workers;
  for (int w = 0; w < 8; ++w)
    workers.emplace_back([&] {
      for (int i = 0; i < 200; ++i) EXPECT_EQ(cache.get("texture", 3, [&] { return ++reads, 42; }), 42);
    });
  for (std::thread& t : workers) t.join();
  EXPECT_EQ(reads, 1);
}

}  // namespace
}  // namespace procex

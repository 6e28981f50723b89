// Whether one .glb can hold a batch's buildings, judged before they are made
// from a few of them made ahead: a million of samples/city.pxg's buildings
// make 14 GB of .glb, and the writer sees that it cannot hold them (its 4 GiB,
// core/io/gltf_write.h) only at the 300,000th, half an hour into the run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace procex {

// Buildings made ahead: enough that the mean of their sizes is within a few
// per cent, few enough to cost nothing beside the batches that need it.
inline constexpr std::size_t kGlbSizeSample = 256;

// The positions (into the batch's `count` buildings, in input order) of the
// buildings to make ahead: kGlbSizeSample of them spread evenly over the
// batch, so that an input sorted by size (a district of towers at its end)
// is judged whole. None when the batch is too small for a sample to save
// anything: the writer's own check stops it soon enough.
std::vector<std::size_t> glb_size_sample(std::size_t count);

struct GlbSizeEstimate {
  std::size_t buildings = 0;  // in the batch
  std::size_t sampled = 0;
  double per_building = 0;    // mean bytes of .glb a building (refused and failed ones: none)
  double total = 0;           // per_building times buildings
  // Three standard errors of the mean below total: what the batch passes but
  // in about one case in a thousand. A batch is refused only above this.
  double at_least = 0;
};

// From the .glb bytes of each sampled building (GlbStreamWriter::bytes
// before and after it).
GlbSizeEstimate estimate_glb_size(std::span<const std::uint64_t> sampled_bytes, std::size_t buildings);

// Why the batch into `output` is refused before it starts (its estimate is
// above max_bytes), and what to do instead (glb_too_large_advice).
std::string glb_too_large_message(const std::filesystem::path& output, const GlbSizeEstimate& estimate,
                                  std::uint64_t max_bytes);

// What to do when the buildings, `total` bytes of .glb, are more than one
// .glb holds (max_bytes): the number of shards that puts each in one file
// with room to spare, and what not to do with them.
std::string glb_too_large_advice(double total, std::uint64_t max_bytes);

// Bytes as a person reads them: "13.8 GB", "512 bytes".
std::string byte_size_text(double bytes);

}  // namespace procex

#include "app/cli/glb_size_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/io/gltf_write.h"

namespace procex {

std::vector<std::size_t> glb_size_sample(std::size_t count) {
  // Below four samples' worth, making the sample ahead would add a quarter
  // or more to the batch's work.
  if (count < 4 * kGlbSizeSample) return {};
  std::vector<std::size_t> at(kGlbSizeSample);
  for (std::size_t k = 0; k < kGlbSizeSample; ++k) at[k] = (2 * k + 1) * count / (2 * kGlbSizeSample);  // cell centres
  return at;
}

GlbSizeEstimate estimate_glb_size(std::span<const std::uint64_t> sampled_bytes, std::size_t buildings) {
  GlbSizeEstimate e;
  e.buildings = buildings, e.sampled = sampled_bytes.size();
  if (sampled_bytes.empty()) return e;
  const double n = static_cast<double>(sampled_bytes.size());
  double sum = 0, squares = 0;
  for (const std::uint64_t b : sampled_bytes) sum += static_cast<double>(b);
  e.per_building = sum / n;
  for (const std::uint64_t b : sampled_bytes) squares += (static_cast<double>(b) - e.per_building) * (static_cast<double>(b) - e.per_building);
  const double standard_error = sampled_bytes.size() > 1 ? std::sqrt(squares / (n - 1) / n) : e.per_building;
  e.total = e.per_building * static_cast<double>(buildings);
  e.at_least = std::max(0.0, e.per_building - 3 * standard_error) * static_cast<double>(buildings);
  return e;
}

std::string byte_size_text(double bytes) {
  static constexpr const char* kUnits[] = {"bytes", "KB", "MB", "GB", "TB"};
  int unit = 0;
  while (bytes >= 1000 && unit < 4) bytes /= 1000, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, kUnits[unit]);
  return text;
}

std::string glb_too_large_message(const std::filesystem::path& output, const GlbSizeEstimate& estimate,
                                  std::uint64_t max_bytes) {
  return output.string() + ": its " + std::to_string(estimate.buildings) + " buildings would make about " +
         byte_size_text(estimate.total) + " of .glb (" + byte_size_text(estimate.per_building) + " each, judged from " +
         std::to_string(estimate.sampled) + " of them made ahead across the batch), more than " +
         glb_limit_text(max_bytes) + "; nothing made. " + glb_too_large_advice(estimate.total, max_bytes);
}

std::string glb_too_large_advice(double total, std::uint64_t max_bytes) {
  // Each shard's .glb at most 90 % full: the buildings' sizes vary, and the
  // file's head, placed meshes and images come on top of theirs.
  const auto shards = static_cast<std::uint64_t>(std::ceil(total / (0.9 * static_cast<double>(max_bytes))));
  return "Split the batch with --shard i/N, N at least " + std::to_string(std::max<std::uint64_t>(shards, 2)) +
         ", and keep the shards' .glb files apart (procex merge would join them into one as large), or write one file "
         "per building into a folder (-o FOLDER/)";
}

}  // namespace procex

#include "core/io/feature_sources.h"

#include <algorithm>

namespace procex {

std::vector<FeatureSource> feature_sources(const FeatureSpool& spool, const std::vector<GeoJsonFeatureError>& errors,
                                           std::size_t shard, std::size_t shards) {
  std::vector<FeatureSource> sources;
  // Reserved (about a shard's share): a doubling vector held most of batch_iter's growth with its footprints (BENCHMARKS).
  sources.reserve((spool.size() + errors.size() + shards - 1) / shards);
  for (std::size_t i = 0; i < spool.size(); ++i)
    if (spool.index(i) % shards == shard) sources.push_back({spool.index(i), i, nullptr});
  for (const GeoJsonFeatureError& e : errors)
    if (e.index % shards == shard) sources.push_back({e.index, 0, &e});
  std::sort(sources.begin(), sources.end(), [](const FeatureSource& a, const FeatureSource& b) { return a.index < b.index; });
  return sources;
}

}  // namespace procex

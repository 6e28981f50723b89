// A batch's footprints in input order, readable or not, as procex batch and
// procex.batch_iter hand their buildings over: each is its position in a
// FeatureSpool or the error that says why it could not be read. 24 bytes a
// footprint (what an unreadable one says is kept once, in the errors given):
// a million of them are 24 MB, where the features themselves wait on disk.
#pragma once

#include <cstddef>
#include <vector>

#include "core/io/feature_spool.h"
#include "core/io/geojson.h"

namespace procex {

struct FeatureSource {
  std::size_t index;                 // in the footprints given (GeoJsonFeature::index)
  std::size_t spooled;               // its position in the spool, unless error
  const GeoJsonFeatureError* error;  // not null: unreadable; points into the errors given
};

// The footprints of `spool` and `errors` whose index % shards == shard, by
// index. `errors` must outlive what is returned.
std::vector<FeatureSource> feature_sources(const FeatureSpool& spool, const std::vector<GeoJsonFeatureError>& errors,
                                           std::size_t shard = 0, std::size_t shards = 1);

}  // namespace procex

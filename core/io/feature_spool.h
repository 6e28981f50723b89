// A batch's footprints set aside on disk as they are read, and read back one
// at a time by position: a million footprints held as GeoJsonFeature take
// about 600 MB (the records, their property maps, their rings), the spool's
// index 32 bytes each. The file is an unnamed temporary file (base/spool_file.h)
// in the folder given, so it goes with the process however it ends.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "base/spool_file.h"
#include "core/io/geojson.h"

namespace procex {

class FeatureSpool final : public FeatureStore {
 public:
  // Throws IoError naming `folder` if no temporary file can be made in it.
  explicit FeatureSpool(std::string folder);

  void add(GeoJsonFeature f) override;
  void clear() override;
  void keep_if(const std::function<bool(GeoJsonFeature&)>& keep) override;

  std::size_t size() const { return entries_.size(); }
  // The i-th footprint's GeoJsonFeature::index (its position in the file).
  std::size_t index(std::size_t i) const { return entries_[i].index; }
  // The i-th footprint as it was added, with the properties added since.
  // Throws IoError if the file cannot be read back.
  GeoJsonFeature at(std::size_t i) const;
  // Gives the i-th footprint each of `properties` it lacks (labels found
  // once every footprint is read: party_edges, street_edges).
  void add_properties(std::size_t i, const std::vector<std::pair<std::string, std::string>>& properties);

 private:
  struct Range {
    std::uint64_t at = 0, length = 0;
  };
  struct Entry {
    std::uint64_t index = 0;
    Range feature, added;  // added.length 0: no properties added
  };
  Range append(const std::string& record);
  std::string folder_;
  std::unique_ptr<SpoolFile> file_;
  std::vector<Entry> entries_;
};

}  // namespace procex

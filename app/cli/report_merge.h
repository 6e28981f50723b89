// The reports of a sharded `procex batch` joined into the report an
// unsharded run writes: each part checked to be a batch report and the parts
// one whole run (app/cli/shard_stamp.h), the buildings in feature order, the
// summary recounted. A part's entries are read as its parser finishes them
// and set aside on disk, and the parts' entries are then joined in feature
// order a building at a time: memory holds one entry per part, whatever the
// number of buildings.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/cli/report_entries.h"
#include "base/atomic_file_set.h"

namespace procex {

class MergedReport {
 public:
  // Throws IoError naming the part that is not a batch report, or the parts
  // that are not one run. The entries wait in temporary files in `folder`
  // (beside the merged report).
  MergedReport(const std::vector<std::filesystem::path>& parts, const std::string& folder);
  // The run's shard stamp as compact JSON (a .glb scene's extras.shard), or
  // "" when there were no parts.
  const std::string& shard() const { return shard_; }
  // The report's text, for AtomicFileSet::add.
  std::vector<FilePiece> pieces() { return entries_.report(report_); }

 private:
  nlohmann::ordered_json report_;  // with "buildings" empty: the entries are entries_
  ReportEntries entries_;
  std::string shard_;
};

}  // namespace procex

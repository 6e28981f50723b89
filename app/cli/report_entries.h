// A report's "buildings" array, too long to hold in memory (a batch of a
// million buildings, the merge of its shards): each element rendered as
// report_text lays it out there, joined in a temporary file as they come,
// and copied from there into the report, whose other members are small.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/atomic_file_set.h"
#include "base/spool_file.h"

namespace procex {

class ReportEntries {
 public:
  // The elements wait in `folder` (beside the outputs). Throws IoError
  // naming it if no temporary file can be made there.
  explicit ReportEntries(const std::string& folder) : spool_(folder) {}
  // An element's text as report_text lays it out in a top-level member's
  // array (two levels deep), without separators.
  static std::string text(const nlohmann::ordered_json& entry);

  // Adds an element rendered by text().
  void add(std::string_view entry_text);
  std::size_t count() const { return count_; }

  // The text of `report`, whose "buildings" is an empty array, with the
  // elements added so far in it: pieces for AtomicFileSet::add, valid until
  // the next call.
  std::vector<FilePiece> report(const nlohmann::ordered_json& report);

 private:
  SpoolFile spool_;
  std::size_t count_ = 0;
  std::string head_, tail_;
};

}  // namespace procex

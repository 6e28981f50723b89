#include "app/cli/report_entries.h"

#include "app/cli/report_text.h"

namespace procex {

std::string ReportEntries::text(const nlohmann::ordered_json& entry) {
  const std::string flat = report_text(entry);
  std::string out = "  ";
  for (std::size_t i = 0; i + 1 < flat.size(); ++i) out += flat[i] == '\n' ? std::string("\n  ") : std::string(1, flat[i]);
  return out;
}

void ReportEntries::add(std::string_view entry_text) {
  spool_.append(count_ == 0 ? "\n" : ",\n");
  spool_.append(entry_text);
  ++count_;
}

std::vector<FilePiece> ReportEntries::report(const nlohmann::ordered_json& report) {
  const std::string text = report_text(report);
  // No string value holds a raw newline, so this is the array's place.
  const std::string empty = "\n \"buildings\": []";
  const std::size_t at = text.find(empty) + empty.size() - 1;
  head_ = text.substr(0, at), tail_ = text.substr(at + 1);
  return {{head_}, {{}, &spool_}, {count_ == 0 ? "]" : "\n ]"}, {tail_}};
}

}  // namespace procex

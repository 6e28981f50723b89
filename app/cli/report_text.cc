#include "app/cli/report_text.h"

namespace procex {

std::string report_text(const nlohmann::ordered_json& report) {
  return report.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace procex

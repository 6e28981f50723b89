// The JSON text of a command's report (roof, batch, merge). File names,
// options and ids are bytes from a file system or a command line and need not
// be UTF-8, which JSON text must be: such bytes are written as U+FFFD rather
// than aborting the write after all the work is done.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace procex {

std::string report_text(const nlohmann::ordered_json& report);

}  // namespace procex

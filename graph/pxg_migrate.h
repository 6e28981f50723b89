// pxg_migrate.h -- upgrades the JSON of older .pxg versions to the current one (internal to graph/).
#pragma once

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace procex::detail {

// Reports a problem at a JSON pointer; must throw.
using PxgFail = std::function<void(const std::string& pointer, const std::string& message)>;

// Rewrites `j` (a whole file of version `version`) in place as version kPxgVersion.
void migrate_pxg(nlohmann::json& j, int version, const PxgFail& fail);

}  // namespace procex::detail

// The summaries of the sample recipes stored in samples/expected/: what the
// sample tests compare with, and what procex_update_expected writes
// (scripts/update-expected.sh; never run by ctest, so no test run can rewrite
// what it checks).
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "nodes/support/mesh_summary.h"

namespace procex::test {

// Every sample recipe but city.pxg, which needs footprints bound (its summary
// comes from a batch report), sorted.
inline std::vector<std::string> sample_recipe_names(const std::filesystem::path& samples) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(samples))
    if (e.path().extension() == ".pxg" && e.path().stem() != "city") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A recipe's mesh summary with the tolerance it is compared within; placed
// meshes (instances per mesh name) only where a recipe places some.
inline nlohmann::ordered_json summary_json(const MeshSummary& s) {
  nlohmann::ordered_json j = {{"meshes", s.meshes},
                              {"faces", s.faces},
                              {"faces_per_tag", s.faces_per_tag},
                              {"bounds", {{"min", {s.min.x, s.min.y, s.min.z}}, {"max", {s.max.x, s.max.y, s.max.z}}}},
                              {"volume", s.volume}};
  if (!s.placed.empty()) j["placed"] = s.placed;
  j["tolerance"] = {{"length", 1e-6}, {"volume_relative", 1e-6}};
  return j;
}

// Per building of a batch report: its faces per tag, bounds and volume, and
// its placed meshes (instances per mesh name) where it has some.
inline nlohmann::ordered_json city_buildings(const nlohmann::ordered_json& report) {
  nlohmann::ordered_json got = nlohmann::ordered_json::object();
  for (const auto& b : report["buildings"]) {
    nlohmann::ordered_json one = {{"faces_per_tag", b["faces_per_tag"]}, {"bounds", b["bounds"]}, {"volume", b["volume"]}};
    if (b.contains("placed") && !b["placed"].empty()) one["placed"] = b["placed"];
    got[b["id"].get<std::string>()] = std::move(one);
  }
  return got;
}

inline nlohmann::ordered_json city_summary(const nlohmann::ordered_json& report) {
  return {{"tolerance", {{"length", 1e-6}, {"volume_relative", 1e-6}}}, {"buildings", city_buildings(report)}};
}

}  // namespace procex::test

#include "tests/support/generators/edge_profiles.h"

#include <stdexcept>

#include "tests/support/house_profiles.h"

namespace procex::testing {
namespace {

std::vector<Profile> presets() {
  std::vector<Profile> all = house_profiles();
  all.push_back({"house", {{0, 0}, {0, 3}, {-6, 9}}, {"wall", "roof"}});
  all.push_back({"gambrel", {{0, 0}, {0, 3}, {-2, 5}, {-5, 7}}, {"wall", "lower", "upper"}});
  all.push_back({"hip", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}});
  all.push_back({"bay", {{0, 0}, {0, 1.5}, {-2, 3.5}}, {"bay wall", "bay roof"}});
  all.push_back({"dormer", {{0, 0}, {0, 1.2}, {-3, 4.2}}, {"dormer wall", "dormer roof"}});
  all.push_back({"recess", {{0, 0}, {0, 2.2}, {-3, 5.2}}, {"recess wall", "recess roof"}});
  return all;
}

PlanEdit natural(const std::string& name, double height, double width, double depth, int profile) {
  PlanEdit e;
  e.name = name;
  e.at = {name, {PlanAnchor::Mode::Fraction, 0.5}, height, 0, {}};
  e.kind = PlanEdit::Kind::Natural;
  e.width = width;
  e.depth = depth;
  e.edges.assign(3, EdgeSpec{0.0, 1000000, profile});
  return e;
}

}  // namespace

std::vector<std::string> profile_preset_names() {
  std::vector<std::string> names;
  for (const Profile& p : presets()) names.push_back(p.name);
  return names;
}

Profile profile_preset(const std::string& name) {
  for (const Profile& p : presets())
    if (p.name == name) return p;
  throw std::invalid_argument("no profile preset named '" + name + "'");
}

std::vector<std::string> plan_edit_profile_names() { return {"hip", "bay", "dormer", "recess"}; }

std::vector<PlanEdit> preset_plan_edits() {
  PlanEdit recess;
  recess.name = "recess";
  recess.at = {"recess", {PlanAnchor::Mode::FromStart, 1.0}, 0.0, 0, {}};
  recess.shape = {{0, 0}, {0, -0.5}, {0.8, -0.5}, {0.8, 0}};
  recess.edges.assign(3, EdgeSpec{0.0, 2000000, 3});
  return {natural("bay", 1.0, 1.5, 0.6, 1), natural("dormer", 3.0, 1.2, 0.3, 2), recess};
}

}  // namespace procex::testing

// Switch: picks one of several inputs by an attribute's value (a building type).
#include <string_view>

#include <nlohmann/json.hpp>

#include "graph/registry.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t value, cases;
};
Params par;

// Version 1 had five fixed cases, each its own parameter case_1..case_5.
void upgrade(int saved_version, nlohmann::json& params) {
  if (saved_version >= 2) return;
  nlohmann::json cases = nlohmann::json::array();
  for (int k = 1; k <= 5; ++k) {
    const std::string name = "case_" + std::to_string(k);
    cases.push_back(params.contains(name) ? params[name] : nlohmann::json(""));
    params.erase(name);
  }
  params["cases"] = std::move(cases);
}

// The input `value` chooses: k for the k-th case listing it, 0 (default) for
// none. Read in place: a batch asks three times per building, and a string
// stream per case was 2.5 % of its instructions.
std::size_t chosen(const std::vector<Value>& params) {
  const std::string& value = params[par.value].get<std::string>();
  const auto& cases = params[par.cases].get<std::vector<std::string>>();
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::string_view list = cases[k];
    for (bool more = true; more;) {
      const std::size_t comma = list.find(',');
      const std::string_view item = list.substr(0, comma);
      const auto b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
      if (b != std::string_view::npos && item.substr(b, e - b + 1) == value) return k + 1;
      more = comma != std::string_view::npos;
      if (more) list.remove_prefix(comma + 1);
    }
  }
  return 0;
}

std::optional<std::size_t> pass(const std::vector<Value>& params, std::size_t) { return chosen(params); }

void declare(NodeDecl& d) {
  d.doc("Hands on one input, chosen by `value` (usually exposed as `building`, so `procex batch` sets it "
        "from each feature's GeoJSON property of that name). Entry k of `cases` lists the values, comma-separated, "
        "that choose input `case_k`; any other value (or an unconnected case) chooses `default`. One input per "
        "entry. Only the chosen branch is evaluated.")
      .category("Flow");
  par.value = d.param<std::string>("value").default_value(std::string()).doc("the attribute's value for this building").index();
  par.cases = d.param<std::vector<std::string>>("cases").default_value(std::vector<std::string>{"", ""}).sets_port_count()
      .doc("per case input, the values choosing it, comma-separated").index();
  d.input<Value>("default");
  for (std::size_t k = 1; k <= d.count_of("cases"); ++k) d.input<Value>("case_" + std::to_string(k)).optional();
  d.output<Value>("out");
  d.pass_through(pass);
  d.upgrade(upgrade);
}

// Reached only when the chosen case is not connected: fall back to default.
void evaluate(EvalContext& ctx) {
  const std::size_t k = chosen({ctx.param_value(par.value), ctx.param_value(par.cases)});
  ctx.set_output_value(0, ctx.has_input(k) ? ctx.input_value(k) : ctx.input_value(0));
}

}  // namespace
PROCEX_REGISTER_NODE("Switch", 2, declare, evaluate);
}  // namespace procex

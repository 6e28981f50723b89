// Switch: picks one of several inputs by an attribute's value (a building type).
#include <sstream>

#include "graph/registry.h"

namespace procex {
namespace {

constexpr std::size_t kCases = 5;

// The input `value` chooses: 1..kCases for a matching case, 0 for default.
std::size_t chosen(const std::vector<Value>& params) {
  const std::string& value = params[0].get<std::string>();
  for (std::size_t k = 1; k <= kCases; ++k) {
    std::istringstream list(params[k].get<std::string>());
    for (std::string item; std::getline(list, item, ',');) {
      const auto b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
      if (b != std::string::npos && item.substr(b, e - b + 1) == value) return k;
    }
  }
  return 0;
}

std::optional<std::size_t> pass(const std::vector<Value>& params, std::size_t) { return chosen(params); }

void declare(NodeDecl& d) {
  d.doc("Hands on one input, chosen by `value` (usually exposed as `building`, so `procex batch` sets it "
        "from each feature's GeoJSON property of that name). `case_k` lists the values, comma-separated, that "
        "choose input `case_k`; any other value (or an unconnected case) chooses `default`. Only the chosen "
        "branch is evaluated.")
      .category("Flow");
  d.param<std::string>("value").default_value(std::string()).doc("the attribute's value for this building");
  for (std::size_t k = 1; k <= kCases; ++k)
    d.param<std::string>("case_" + std::to_string(k)).default_value(std::string())
        .doc("values choosing input case_" + std::to_string(k) + ", comma-separated");
  d.input<Value>("default");
  for (std::size_t k = 1; k <= kCases; ++k) d.input<Value>("case_" + std::to_string(k)).optional();
  d.output<Value>("out");
  d.pass_through(pass);
}

// Reached only when the chosen case is not connected: fall back to default.
void evaluate(EvalContext& ctx) {
  std::vector<Value> params;
  for (std::size_t i = 0; i <= kCases; ++i) params.push_back(ctx.param_value(i));
  const std::size_t k = chosen(params);
  ctx.set_output_value(0, ctx.has_input(k) ? ctx.input_value(k) : ctx.input_value(0));
}

}  // namespace
PROCEX_REGISTER_NODE("Switch", 1, declare, evaluate);
}  // namespace procex

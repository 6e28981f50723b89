#include "graph/eval_context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace procex {

std::size_t EvalContext::index_of(std::optional<std::size_t> i, std::string_view name) const {
  if (!i) {
    std::fprintf(stderr, "procex: node type '%s' has no port or parameter named '%.*s'; check its declaration\n",
                 decl_.type_name().c_str(), static_cast<int>(name.size()), name.data());
    std::abort();
  }
  return *i;
}

std::size_t EvalContext::choice_index(std::size_t i) const {
  const auto& choices = decl_.params().at(i).choices;
  return static_cast<std::size_t>(std::find(choices.begin(), choices.end(), choice(i)) - choices.begin());
}

void EvalContext::set_output_value(std::size_t i, Value v) {
  outputs_.at(i) = std::move(v);
}

}  // namespace procex

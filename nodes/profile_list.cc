// Profile List: gathers profiles for Assign Profiles.
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

constexpr int kInputs = 6;

void declare(NodeDecl& d) {
  d.doc("Gathers up to six profiles into a list, in input order (unconnected inputs are skipped). "
        "Assign Profiles refers to them by name or by position in this list.")
      .category("Profile");
  for (int i = 1; i <= kInputs; ++i) {
    auto port = d.input<Profile>("profile_" + std::to_string(i));
    if (i > 1) port.optional();
  }
  d.output<std::vector<Profile>>("profiles");
}

void evaluate(EvalContext& ctx) {
  std::vector<Profile> list;
  for (std::size_t i = 0; i < kInputs; ++i)
    if (ctx.has_input(i)) list.push_back(ctx.input<Profile>(i));
  ctx.set_output(0, std::move(list));
}

}  // namespace
PROCEX_REGISTER_NODE("Profile List", 1, declare, evaluate);
}  // namespace procex

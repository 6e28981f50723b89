#include "nodes/support/errors.h"

#include "core/geom/error.h"

namespace procex {

std::string describe(const std::exception& e) {
  std::string out = e.what();
  if (const auto* in = dynamic_cast<const InputError*>(&e)) {
    if (in->loop() >= 0) out.append(" (loop ").append(std::to_string(in->loop()));
    if (in->vertex() >= 0)
      out.append(in->loop() >= 0 ? ", vertex " : " (vertex ").append(std::to_string(in->vertex()));
    if (in->loop() >= 0 || in->vertex() >= 0) out += ")";
  } else if (const auto* sw = dynamic_cast<const SweepError*>(&e)) {
    out.append(" (height ").append(std::to_string(sw->height()));
    if (!sw->edge_ids().empty()) out.append(", edges");
    for (int id : sw->edge_ids()) out.append(" ").append(std::to_string(id));
    out += ")";
  }
  return out;
}

}  // namespace procex

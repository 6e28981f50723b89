#include "core/sweep/sweep.h"

#include "core/geom/error.h"

namespace procex {

Surface sweep(const Footprint&, const SweepOptions&) {
  throw SweepError("sweep engine not built yet", 0.0, {});
}

}  // namespace procex

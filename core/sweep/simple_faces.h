// The sweep's last check of its surface: every face a simple polygon.
#pragma once

#include "core/mesh/surface.h"

namespace procex::engine {

// Throws SweepError naming the face's source edge where a face of one loop
// folds over itself. Groups of events that a batch resolves as one instant,
// in the order rounding gave them (the apex of a jittered star, hundreds of
// planes through a millimetre), can leave a face whose boundary zigzags
// across itself by micrometres: closed, and still not a solid. Thrown, it
// makes the sweep try the next clustering scale, as a surface that does not
// close does. The sweep asks it only where some batch did that
// (State::shared_instant): elsewhere every event was resolved in height
// order, and checking every face cost 3 to 5% more instructions in a city's sweep.
// A face with holes is split into simple pieces when the mesh is built, which
// refuses one it cannot split; the base is the plan, checked before the sweep.
void check_simple_faces(const Surface& surface);

}  // namespace procex::engine

// A roof run past its walls: the roof's planes carried out by an eave distance
// beyond walls under a level roof edge and by a verge distance beyond walls
// under a sloping one (a gable's rake), thickened along their normals into a
// slab with a vertical fascia round its outer edge. The slab is a closed solid
// of its own that sits on the building, its underside over the walls lying on
// the building's roof, so the building stays the closed solid it was.
//
// A convex roof (every crease a ridge, hip or mansard break, as the roofs a
// sweep raises over a convex plan are: gable, hip, mansard, gambrel) has the
// slab's underside the lowest of its planes at each point of the plan run
// out past the walls, and its top the lowest of those planes moved up by the
// thickness, so where slopes meet it is cut as a roofer would cut it. A roof
// with valleys (an L, T or U plan, a courtyard) is run out face by face: each
// outline edge's face carries on past it, the creases meeting the outline
// run straight on, and each corner of the top is where its faces' planes,
// raised, meet again; where thickening would need new corners (raised planes
// that no longer meet at one point, an edge a few millimetres long turned
// over) it is refused, naming the place.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "core/mesh/surface.h"

namespace procex {

struct RoofOverhang {
  double eave = 0.5;       // how far past the walls under level roof edges, in plan (m)
  double verge = 0.3;      // how far past the walls under sloping roof edges (gables), in plan (m)
  double thickness = 0.2;  // the slab's thickness, along each roof plane's normal (m)
};

// The slab over `roof`: the roof's faces, each a planar polygon
// counter-clockwise seen from above (as a building's outward faces are).
// Its faces are tagged "roof" (the top), "fascia" (the vertical outer edge),
// "soffit" (the underside past the walls) and "underside" (lying on the
// building's roof); all are FaceKind::Side with no source edge.
// Throws InputError naming the parameter (negative or not finite), the face
// (vertical, facing down, degenerate), or a point where the roof cannot be
// run out: a gap in a convex outline, an overhang that folds over or runs
// into another part of itself, a wall rising through the roof.
Surface roof_overhang(const std::vector<std::vector<glm::dvec3>>& roof, const RoofOverhang& overhang);

}  // namespace procex

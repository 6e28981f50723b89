// The epsilons of mesh placement, named, in one place (beside the engine's in
// core/geom/tolerances.h, which they follow: lengths relative to a scale).
#pragma once

namespace procex {

// A frame's axes must be unit and perpendicular to within this (dimensionless):
// frames come from the sweep already orthonormal, so this only catches
// hand-made or corrupted frames.
inline constexpr double kFrameOrthonormality = 1e-6;

// A transform whose |det| of its 3x3 part is below this * scale^3 (scale: its
// largest column) collapses a mesh to a plane.
inline constexpr double kSingularDeterminantRelative = 1e-12;

// Repetition counts: length / spacing within this (relative) of an integer
// counts as that integer, so 10 m at 2.5 m gives 4 cells whatever the rounding.
inline constexpr double kRepeatCountRelative = 1e-9;

// A node matrix is written as one glTF matrix when its columns are orthogonal
// to within this (cosine of their angle); otherwise it is split into TRS nodes.
inline constexpr double kTrsColumnCosine = 1e-9;

}  // namespace procex

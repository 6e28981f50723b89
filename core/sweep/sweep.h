// The sweep-plane engine: procedural extrusions (Kelly & Wonka, section 4).
// A plane rises from the footprint; each edge's face moves at its own angle;
// where three or more faces meet, a generalized intersection event rewires the
// cross-section. The result is a closed, consistently oriented 2-manifold.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/anchor.h"
#include "core/geom/footprint.h"
#include "core/geom/plan_edit.h"
#include "core/mesh/surface.h"

namespace procex {

// How to resolve parallel, same-direction edges meeting (paper 4.5, fig. 18-19).
enum class Ambiguity { MaximizeVolume, MinimizeVolume };

struct SweepOptions {
  std::optional<double> max_height;  // caps the sweep with horizontal faces
  Ambiguity ambiguity = Ambiguity::MaximizeVolume;
  std::vector<Anchor> anchors;  // resolved into Surface::anchors
  // Inserted into the cross-section at their anchors' heights; where each was
  // applied (or why not) goes to Surface::plan_edits. Their edges' profiles
  // index into the footprint's.
  std::vector<PlanEdit> plan_edits;
};

// Throws InputError for unusable footprints and SweepError when an event
// cannot be resolved; never returns a surface that is not closed.
Surface sweep(const Footprint& footprint, const SweepOptions& options = {});

}  // namespace procex

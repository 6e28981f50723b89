// The sweep-plane engine: procedural extrusions (Kelly & Wonka, section 4).
// A plane rises from the footprint; each edge's face moves at its own angle;
// where three or more faces meet, a generalized intersection event rewires the
// cross-section. The result is a closed, consistently oriented 2-manifold.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/geom/anchor.h"
#include "core/geom/footprint.h"
#include "core/geom/plan_edit.h"
#include "core/mesh/surface.h"

namespace procex {

// How to resolve parallel, same-direction edges meeting (paper 4.5, fig. 18-19).
enum class Ambiguity { MaximizeVolume, MinimizeVolume };

// Limits on one footprint's sweep (0: none). An input that makes the engine
// run away (corners made without end, events that never rise, a sweep far
// slower than its size warrants) fails with a SweepBudgetError naming the
// limit it passed, in bounded time and memory, instead of a hang or a crash.
struct SweepBudget {
  // Vertices made by one attempt (nested sweeps included): corners, planes
  // and faces grow with them, so this bounds the engine's memory. The corners
  // made, and the potential events held at one height, are held to it apart.
  std::size_t max_vertices = 10'000'000;
  // Potential events worked out by one attempt as its corners are listed: a
  // reflex corner lists one per live plane it meets, or among many thousands
  // of live planes those its list's index search reached (at least its
  // lowest few), so this grows as vertices times reflex corners at most.
  std::size_t max_events = 1'000'000'000;
  // CPU seconds of the thread running sweep(), its retries included (not wall
  // time: a footprint must not pass on a quiet machine and fail on a busy one).
  double max_seconds = 600.0;

  bool operator==(const SweepBudget&) const = default;
};

struct SweepOptions {
  std::optional<double> max_height;  // caps the sweep with horizontal faces
  Ambiguity ambiguity = Ambiguity::MaximizeVolume;
  std::vector<Anchor> anchors;  // resolved into Surface::anchors
  // Inserted into the cross-section at their anchors' heights; where each was
  // applied (or why not) goes to Surface::plan_edits. Their edges' profiles
  // index into the footprint's.
  std::vector<PlanEdit> plan_edits;
  SweepBudget budget;

  // Member by member, so that whatever is added here is compared too (the CGAL
  // oracle tells a roof sweep() makes by options equal to the defaults).
  bool operator==(const SweepOptions&) const = default;
};

// Throws InputError for unusable footprints, SweepError when an event cannot
// be resolved and SweepBudgetError past the budget; never returns a surface
// that is not closed.
Surface sweep(const Footprint& footprint, const SweepOptions& options = {});

// How many sweeps in this process closed only after a retry at another
// clustering scale (Surface::retries > 0): what a hand-made case must never
// need, counted where no caller can forget to look.
std::uint64_t sweeps_retried();

}  // namespace procex

// The sweep's live state: the planes (p-edges) and the corners that link them
// into loops on the sweep plane, plus the output half-edges each face collects.
// Indices, not pointers; corners and edges are never erased, only marked dead,
// so iteration order (and therefore output) is deterministic.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/geom/profile.h"
#include "core/mesh/surface.h"
#include "core/sweep/budget.h"
#include "core/sweep/meeting_heights.h"
#include "core/sweep/plan_position.h"
#include "core/sweep/plane.h"
#include "core/sweep/sweep.h"
#include "core/geom/tolerances.h"

namespace procex::engine {

using Tolerances = SweepTolerances;

inline constexpr int kNone = -1;

// A footprint edge and where the sweep is along its profile.
struct Source {
  std::int32_t id = -1;              // EdgeSpec::id
  const Profile* profile = nullptr;  // null: one plane all the way up
  std::size_t point = 0;             // the profile point the current plane starts at
  double base = 0.0;                 // the height the profile starts at (plan edits insert edges above 0)
  int edge = -1;                     // its current plane
  int profile_index = -1;            // EdgeSpec::profile
  glm::dvec2 start{0.0}, end{0.0};   // the footprint edge (for plan anchors)
};

// A p-edge: one plane of one footprint edge.
struct Edge {
  Plane plane;
  glm::dvec2 dir{1.0, 0.0};  // unit direction of the edge in the plan
  int source = -1;           // index into State::sources
  std::int32_t source_id = -1;
  int face = kNone;          // output face group this plane's region belongs to
  // The corners s with s.next_edge == this, in the order made, linked through
  // Corner::next_span (maybe stale: State::spans drops the dead), and how many
  // the list holds. A vector per edge was a tenth of the city's allocations.
  int first_span = kNone, last_span = kNone;
  std::size_t listed_spans = 0;
  // The edge whose plane ran on over this edge's span where an ambiguous
  // corner between them was resolved (ambiguity.h): a collision found before
  // that, at the same height, meets the heir there.
  int heir = kNone;
};

// How a corner moves, fixed when it is made from its two edges' planes.
enum class Motion : std::uint8_t {
  Regular,    // along the line where the two planes meet
  Parallel,   // same direction, same plane: perpendicular to the edges
  Ambiguous,  // same direction, different slopes: no direction (paper 4.5)
  Ridge,      // opposite directions: the planes meet in a horizontal line
};

// A corner: the moving point between prev_edge and next_edge on the sweep
// plane. It moves in a straight line from where it was made, so its position
// at any height stays well conditioned even where its planes are nearly parallel.
struct Corner {
  int prev_edge = kNone, next_edge = kNone;
  int prev = kNone, next = kNone;  // neighbouring corners in the loop
  std::uint32_t origin = 0;        // output vertex where this corner started
  int next_span = kNone;           // the next corner listed on next_edge's spans (Edge::first_span)
  glm::dvec2 base{0.0};            // plan position at height base_z
  double base_z = 0.0;
  glm::dvec2 velocity{0.0};        // plan displacement per unit of height
  Motion motion = Motion::Regular;
  bool alive = true;
};

// The first corners of an edge's listed spans, in the order made.
class SpanList {
 public:
  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = int;
    using difference_type = std::ptrdiff_t;
    using pointer = const int*;
    using reference = int;
    iterator() = default;
    iterator(const std::vector<Corner>* corners, int c) : corners_(corners), c_(c) {}
    int operator*() const { return c_; }
    iterator& operator++() {
      c_ = (*corners_)[static_cast<std::size_t>(c_)].next_span;
      return *this;
    }
    iterator operator++(int) {
      iterator was = *this;
      ++*this;
      return was;
    }
    bool operator==(const iterator& o) const { return c_ == o.c_; }

   private:
    const std::vector<Corner>* corners_ = nullptr;
    int c_ = kNone;
  };
  SpanList(const std::vector<Corner>& corners, int first) : corners_(&corners), first_(first) {}
  iterator begin() const { return {corners_, first_}; }
  iterator end() const { return {corners_, kNone}; }
  bool empty() const { return first_ == kNone; }

 private:
  const std::vector<Corner>* corners_;
  int first_;
};

// A directed boundary edge of an output face, seen from outside the solid.
struct HalfEdge {
  std::uint32_t from, to;
};

struct FaceGroup {
  FaceKind kind = FaceKind::Side;
  std::int32_t source_edge = -1;
  std::string tag;
  glm::dvec3 outward{0.0, 0.0, 1.0};  // unit normal pointing out of the solid
  glm::dvec3 origin{0.0};             // any point on the face's plane
  std::vector<HalfEdge> half_edges;
};

struct StateArrays;

// resolve_intersections' lists, kept from one batch to the next and, after
// a small sweep, for the thread's next sweep (intersection_event.cc).
struct BatchScratch;
struct BatchScratchDeleter {
  void operator()(BatchScratch* s) const;
};

class State {
 public:
  // `budget` (shared by the nested sweeps of one attempt) counts what this
  // state makes; null: no limits. The arrays of corners, edges, sources and
  // vertices start with the storage of the thread's last finished sweep
  // (spares.h): grown afresh, filling them missed the cache at every line.
  State(const Tolerances& tol, const SweepOptions& options, Budget* budget = nullptr);
  ~State();
  State(State&&) noexcept;
  State& operator=(State&&) noexcept;

  const Tolerances& tol() const { return tol_; }
  const SweepOptions& options() const { return options_; }
  Budget* budget() const { return budget_; }
  // Counts n potential events queued against the budget.
  void count_events(std::size_t n) const {
    if (budget_) budget_->add_events(n, height);
  }
  // Refuses the sweep once a batch holds more than the budget's candidates.
  void hold_candidates(std::size_t n) const {
    if (budget_) budget_->hold_candidates(n, height);
  }
  // The path of a corner at p at height z moving by v per unit of height,
  // meeting planes from `earliest` to `cap` by this sweep's rule (its
  // tolerances; from outside too once a plane leans out).
  CornerPath corner_path(glm::dvec2 p, glm::dvec2 v, double z, double earliest, double cap) const {
    return {p, v, z, earliest, cap, any_outward, tol_.position(), tol_.relative};
  }
  // Refuses the sweep once its time is up (called once per event batch, and
  // as a large batch is gathered and resolved).
  void check_time() const {
    if (budget_) budget_->check_time(height);
  }

  std::vector<Source> sources;
  std::vector<Edge> edges;
  std::vector<Corner> corners;
  std::vector<glm::dvec3> vertices;
  std::vector<FaceGroup> faces;
  int base_face = kNone;
  double height = 0.0;  // the sweep plane's current height
  // Positions in error messages, in the footprint's own coordinates: load()
  // (sweep.cc) sets where the frame it moves the plan into is centred.
  PlanPosition plan_position;
  bool any_outward = false;  // some plane leans outward: convex corners can split too
  // Some batch resolved several groups as one instant, in rounding's order
  // (resolve_intersections): what can leave a face folded (simple_faces.h).
  bool shared_instant = false;
  // An edge with this many spans (and more than four per edge taking part)
  // has the corners at their ends looked up, not visited one by one, where a
  // cluster gathers the corners at its point (edge_corners.h). Tests compare
  // 0 (every edge looked up) with SIZE_MAX (none).
  std::size_t corners_indexed_from = 64;

  // A new plane for source `source` through `point` at height z0, in a new
  // face tagged `tag`, or continuing face `face` if given.
  int add_edge(glm::dvec2 point, double z0, glm::dvec2 dir, double k, int source, const std::string& tag,
               int face = -1);
  int add_corner(int prev_edge, int next_edge, std::uint32_t origin);
  // How a corner between the two edges moves, and by how much per unit of height.
  std::pair<Motion, glm::dvec2> motion_of(int prev_edge, int next_edge) const;
  std::uint32_t add_vertex(glm::dvec3 p);
  // The output vertex at plan point p on the sweep plane (now at `height`):
  // one made at this height within delta3 of p if there is one, else a new
  // one at (p, z). Every step that resolves events at one height (clusters,
  // spikes folding across to other clusters, ambiguity steps) reaches a point
  // of the sweep plane through this, so each point of it is one vertex.
  std::uint32_t vertex_at(glm::dvec2 p, double z);
  void link(int a, int b) {  // corner a is followed by corner b
    corners[a].next = b;
    corners[b].prev = a;
    if (relinked) relinked->insert(relinked->end(), {a, b});
  }
  // Where the event queue's triangulation follows the loops
  // (kinetic_triangulation.h), every corner link() relinks goes here.
  std::vector<int>* relinked = nullptr;

  // Where a corner is on the sweep plane at height z.
  glm::dvec2 position(int c, double z) const {
    const Corner& k = corners[c];
    return k.base + (z - k.base_z) * k.velocity;
  }
  bool reflex(int c) const;
  // Whether corner c may run into an edge: only a reflex corner cuts into
  // its own loop; where planes lean out, any corner can also meet another
  // polygon growing towards it.
  bool may_split(int c) const {
    return any_outward || corners[c].motion != Motion::Regular || reflex(c);
  }
  // How fast the span from corner c to the next lengthens per unit of height:
  // it closes only where this is negative. Corners keep their velocities, so
  // it holds for the pair as long as it lives.
  double span_rate(int c) const;
  // The height at which the span from corner c to the next closes (the two
  // corners meet along its edge), or NaN where they do not approach, meet
  // below `floor` (beyond rounding), or were made at one collision and meet
  // there because of it.
  double span_closes_at(int c, double floor) const;

  // Tolerances::meeting_slack of planes a, b and c, where corners `ends` run
  // into them: 0 where one of those moves by a rule of its own (parallel,
  // ambiguous), not along two of the planes' crossing.
  double meeting_slack(int a, int b, int c, std::span<const int> ends) const;

  // Output: a corner's trajectory from its origin up to vertex v, shared by the
  // faces of its two edges. The corner is not killed.
  void emit_trajectory(int c, std::uint32_t v);
  // Output: the span of edge e from corner s to corner t ends here, horizontally
  // between the vertices vs and vt.
  void emit_top(int e, std::uint32_t vs, std::uint32_t vt);
  // The vertex of corner c at the current height (its origin if it started here).
  std::uint32_t vertex_now(int c);

  // Live spans of an edge: corners s with s.next_edge == e (stale entries dropped).
  SpanList spans(int e);
  // The spans listed on edge e, stale entries (dead corners) too.
  SpanList listed_spans(int e) const { return {corners, edges[e].first_span}; }
  // The span of edge e (corner s to s.next) that contains p at height z, its
  // plane within `reach` of p: s, or kNone.
  int span_through(int e, glm::dvec2 p, double z, double reach) const;

  // Taken on the first batch (a finished sweep's, or new); cleared, not
  // freed, by each batch after it.
  std::unique_ptr<BatchScratch, BatchScratchDeleter> batch_scratch;

 private:
  Tolerances tol_;
  SweepOptions options_;
  Budget* budget_;
  std::unique_ptr<StateArrays> arrays_;  // the spare taken: the arrays go back in it when done
  // vertex_at's vertices by delta3 cell, of the current height level only:
  // those of earlier levels never match again. The table is open-addressed
  // and a slot of an earlier level counts as empty, so a new level clears
  // nothing (a hash map of every level's cells was 4-5 % of the city's
  // sweeps, in its nodes and their cache misses).
  struct LevelSlot {
    std::uint64_t level = 0;
    std::int64_t x = 0, y = 0;
    std::uint32_t v = 0;
  };
  // The slot of cell (x, y) at this level, or the empty slot where it goes.
  LevelSlot& level_slot(std::int64_t x, std::int64_t y);
  std::vector<LevelSlot> level_slots_ = std::vector<LevelSlot>(16);  // a power of two
  std::size_t level_used_ = 0;                                          // slots of level_
  std::uint64_t level_ = 0;
  double level_height_ = -HUGE_VAL;
};

}  // namespace procex::engine

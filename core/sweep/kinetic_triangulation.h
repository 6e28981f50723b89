// A triangulation of the cross-section that moves with its corners, as the
// source of split candidates (issue 18 item 1; Aichholzer and Aurenhammer
// 1998, Palfrader, Held and Huber 2012): a reflex corner can run into an
// edge's span only across a triangle it is a vertex of, so the spans facing
// it in its triangles are the only splits it can make before one of them
// collapses. Listing every live plane instead made the random plans' sweep
// O(n r) (BENCHMARKS "A kinetic triangulation of the cross-section").
//
// The sweep stays in charge of the loops: the triangulation only follows.
// Where a triangle's corner reaches the side opposite it and that side is a
// spoke (inside the region), the spoke is flipped, ahead of the sweep up to
// its next candidate's height. Where the side is a span, the sweep resolves
// the split or edge event there, relinking corners (State::link reports them
// here), and the region round every relinked corner, widened until the new
// spans stay inside it, is triangulated again from the loops as they are
// then. Every (corner, edge) pair that faces across a triangle at any time
// is handed out once; the event queue works out where the corner meets the
// edge's plane as it would for any other split, so a pair handed out early
// or twice costs a candidate that fails, never a roof.
//
// The sweep resolves the events within a clustering height as one, and a
// corner at 1e5 m per m of rise moves centimetres in that: its loops may
// cross by that much where it stands, and a triangle made there may be
// inside out. Such a triangle's corners are handed back as tangled (the
// queue lists them against every live plane); where the region cannot be
// triangulated again at all, the triangulation is given up (false), and the
// queue lists every corner's splits against every live plane from there on,
// as without it.
//
// A batch's splits that wait (on an edge's plane, on no span of it yet)
// decide how the groups of one instant rewire the spans, and a corner faces
// few of those edges: round every neighbourhood of a batch's events, and of
// the corners it made, the corners and spans near it are paired too
// (hand_around). Not enough yet, so no sweep uses it
// (EventQueue::kTriangulatedFrom): the tests' jittered star of 3,600 corners
// still does not close where the listing's does, and where a neighbourhood
// is crowded its corners list every plane, which costs the star of 16,384
// four times the listing's splits (BENCHMARKS "The instant's
// neighbourhoods").
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <queue>
#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

class KineticTriangulation {
 public:
  // A corner and the edge of a span that faces it across a triangle.
  struct Facing {
    int corner, edge;
  };

  // Triangulates the region inside the live loops at the sweep's height;
  // false where it cannot (loops that are not simple, or that lean out).
  bool build(const State& st);
  void clear();
  // Corners State::link relinked since the last update (it appends here
  // while st.relinked points at it).
  std::vector<int>& relinked() { return relinked_; }
  // Triangulates again the triangles round every relinked corner, and round
  // the corners that died with them, from the loops as they are now.
  bool update(const State& st);
  // The height of the lowest collapse waiting, or HUGE_VAL.
  double next_collapse() const { return heap_.empty() ? HUGE_VAL : heap_.top().z; }
  // Flips every spoke whose triangle collapses at or below z. A triangle whose
  // corner reaches a span is the sweep's event; one still standing well past
  // it (the sweep saw the corner pass the span's end) is triangulated again.
  bool collapse_through(const State& st, double z);
  // The pairs that came to face each other since this was last emptied.
  std::vector<Facing>& facing() { return facing_; }

  // Where a batch of the sweep's events happens: a corner at p at height z
  // meets its next corner (`other`) or the plane of `edge` there.
  struct Place {
    glm::dvec2 p;
    double z;
    int corner, other, edge;
  };
  // Hands out (to facing()) the pairs that may meet near the places of one
  // batch without facing each other across a triangle: the sweep resolves
  // an instant's events together, and a split that waits there (on an
  // edge's plane, off its spans) decides how the instant rewires the spans
  // round it. Places within `reach` of each other are one neighbourhood; its
  // corners are those of its events and those within reach of its box
  // (allowing for how far each moves in `rise`), its edges those of its
  // events and those with a span as near, and every pair of the two not
  // handed out before is. A neighbourhood of one place is left alone, and
  // one with too many triangles near it hands its corners back as tangled
  // (they list every live plane). False where nothing new was handed out.
  bool hand_around(const State& st, const std::vector<Place>& places, double reach, double rise);
  // Corners of triangles made or found inside out since this was last
  // emptied: where the loops cross by rounding (hundreds of corners within a
  // clustering distance, a corner passing a span's end), the spans facing a
  // corner are not all it can reach, and it lists every live plane.
  std::vector<int>& tangled() { return tangled_; }

  // Whether the triangles tile the live loops as a triangulation must: each
  // side joined both ways or a span of the loops, every corner of a loop of
  // three or more in a triangle, and as many triangles as the loops' corners
  // and holes need (tests).
  bool consistent(const State& st) const;

  // Counts for benchmarks and tests.
  struct Work {
    std::size_t flips = 0, updates = 0, cavity_triangles = 0, widenings = 0, rebuilds = 0, repairs = 0;
    std::size_t tangled = 0;  // triangles made or found inside out (the loops cross there by rounding)
    std::size_t walked = 0;   // triangles walked round a batch's neighbourhoods (hand_around)
  };
  const Work& work() const { return work_; }

 private:
  // Counter-clockwise; side i runs from v[i + 1] to v[i + 2], opposite v[i];
  // n[i] is the triangle across it, or kNone where the side is a span (the
  // live loop runs from v[i + 1] to v[i + 2] there).
  struct Tri {
    int v[3];
    int n[3];
    std::uint32_t version = 0;
    bool alive = false;
  };
  struct Collapse {
    double z;
    int tri;
    std::uint32_t version;
    std::uint8_t vertex;  // the corner that reaches the opposite side
    bool operator>(const Collapse& o) const { return z > o.z; }
  };
  // A directed side of the region to triangulate again, the region on its
  // left, and the triangle across it that stays (or kNone: a span).
  struct Side {
    int from, to;
    int across, across_side;
  };

  int add_tri(int a, int b, int c);
  void drop_tri(int t);
  void tangle(int a, int b, int c);
  // The triangles round corner c (one of its triangles is vtri_[c]), into out.
  void fan(int c, std::vector<int>& out) const;
  int side_of(int t, int a, int b) const;  // the side from a to b, or -1
  // Schedules triangle t's next collapse after height `now` and hands out
  // its facing pairs; its side `fresh` is a spoke a flip made at `now`.
  void settle(const State& st, int t, double now, int fresh = -1);
  // Flips the spoke opposite corner k of triangle t, which reaches it at `now`.
  void flip(const State& st, int t, int k, double now);
  // Triangulates the region inside loops[outer] and outside loops[holes]
  // (of corners at `points`) into new triangles, appended to `made`; false
  // where a hole is not inside it.
  bool add_region(const State& st, const std::vector<std::vector<int>>& loops,
                  const std::vector<std::vector<glm::dvec2>>& points, std::size_t outer,
                  const std::vector<std::size_t>& holes, std::vector<int>& made);
  // Triangulates the loops `cycles` (of corners) into new triangles, joined
  // to each other and across `sides`; false where they do not fit.
  bool fill(const State& st, const std::vector<std::vector<int>>& cycles, const std::vector<Side>& sides);
  // Marks triangle t as part of the cavity, and the fans of its dead corners.
  void take(const State& st, int t);
  // The cavity's rim as cycles of corners, the region on their left: its
  // sides to triangles that stay, its spans still live, and the spans the
  // sweep made round relinked corners. False where they do not close up.
  bool rim(const State& st, std::vector<Side>& sides, std::vector<std::vector<int>>& cycles);
  // Triangulates again the triangles marked in cavity_ (their list in
  // cavity_tris_), widened where a new span leaves it; false where the region
  // left does not close up.
  bool retriangulate(const State& st);
  bool rebuild(const State& st);
  // Hands out (corner, edge) unless it was before; true where it is now.
  bool hand(const State& st, int c, int e);

  std::vector<Tri> tris_;
  std::vector<int> free_;
  std::vector<int> vtri_;  // corner -> one of its triangles, or kNone
  std::priority_queue<Collapse, std::vector<Collapse>, std::greater<Collapse>> heap_;
  std::vector<int> relinked_;
  std::vector<Facing> facing_;
  std::vector<int> tangled_;
  // Per corner, the edges already handed out with it (a handful: the spans
  // that ever faced it).
  std::vector<std::vector<int>> handed_;
  // update()'s: triangles in the cavity (marked by stamp), and their list.
  std::vector<std::uint32_t> cavity_;
  std::uint32_t stamp_ = 0;
  std::vector<int> cavity_tris_, fan_;
  std::vector<int> relinked_fan_;  // update()'s (take() fills fan_ as it goes)
  // hand_around's: per triangle, the walk that reached it (by stamp); the
  // places by grid cell and their neighbourhoods (union-find), and what each
  // neighbourhood found near it.
  std::vector<std::uint32_t> walked_;
  std::uint32_t walk_ = 0;
  std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, int>> cells_;  // (grid cell, place)
  // A neighbourhood's places' bounding box, and the lowest of their heights.
  struct Box {
    glm::dvec2 lo{HUGE_VAL}, hi{-HUGE_VAL};
    double z = HUGE_VAL;
    double distance(glm::dvec2 p) const;
    double distance(glm::dvec2 a, glm::dvec2 b) const;  // of the segment from a to b
  };
  std::vector<Box> boxes_;
  std::vector<char> crowded_;  // by neighbourhood: its walk was cut short
  std::vector<std::pair<int, int>> hood_order_;  // (neighbourhood, place), sorted
  std::vector<int> hood_, walk_tris_;
  std::vector<std::pair<int, int>> near_corners_, near_edges_;  // (neighbourhood, corner or edge)
  std::vector<std::uint32_t> edge_mark_;
  std::uint32_t mark_ = 0;
  Work work_;
  // The height the triangulation stands at: its flips run ahead of the
  // sweep's batches (to the next candidate's height), and what it makes
  // again is made where they are then, not where the sweep's height is.
  double clock_ = -HUGE_VAL;
  double now(const State& st) const { return std::max(st.height, clock_); }
  std::uint32_t version_ = 0;  // a triangle's, new at each change: stale collapses never match
};

}  // namespace procex::engine

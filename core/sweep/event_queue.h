// The lazy event queue (paper 4.1): potential events wherever three planes
// meet, ordered by height. Nothing is checked against the live loops until the
// sweep plane reaches the event.
//
// A reflex corner may run into any live edge: O(n) potential split events per
// corner, most of which never happen (the corner dies first, or the edge's
// spans are elsewhere by then). Each scheduling is a list of its own, and only
// the lowest of each list sits in the height queue; popping it brings up the
// list's next one. A list holds only its lowest few splits: when they are used
// up it works the rest out again from what it was listed against (the edges'
// planes as they were then, kept shared by every list of that time) and picks
// the next few above the last it queued. So the queue and the lists stay O(n)
// however many reflex corners there are, and a list whose corner has died is
// dropped unread. A list of many live edges works its few out through the
// edges' PlaneIndex, which finds the same ones without testing every edge.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <queue>
#include <tuple>
#include <vector>

#include "core/sweep/kinetic_triangulation.h"
#include "core/sweep/plane_index.h"
#include "core/sweep/sweep_state.h"

namespace procex::engine {

struct Candidate {
  double z = 0.0;
  glm::dvec2 p{0.0};
  int corner = kNone;  // the corner that collides
  int next = kNone;    // edge event: the following corner it meets (snapshot)
  int edge = kNone;    // split event: the edge the corner runs into
};

class EventQueue {
 public:
  // Below this many live edges testing each costs less than building and
  // searching the index (measured with it from 1,024, before searches gave
  // up: random polygons of 1,024 vertices 1.7x and jittered stars of 4,096
  // 1.5x slower through it).
  static constexpr std::size_t kIndexedFrom = 8192;
  // Sweeps of at least this many corners take their split candidates from a
  // kinetic triangulation of the cross-section. None do yet: it does not
  // follow every plan of 262,144 corners, and at 65,536 it costs what it
  // saves (BENCHMARKS "Split candidates from a kinetic triangulation").
  static constexpr std::size_t kTriangulatedFrom = SIZE_MAX;
  // Lists of at least `indexed_from` live edges are worked out through their
  // PlaneIndex, smaller ones by testing every edge; sweeps of at least
  // `triangulated_from` corners list only the spans facing a corner across
  // the triangulation (tests choose either).
  explicit EventQueue(std::size_t indexed_from = kIndexedFrom, std::size_t triangulated_from = kTriangulatedFrom)
      : indexed_from_(indexed_from), triangulated_from_(triangulated_from) {}
  // Empties the queue for another sweep, keeping its storage (spares.h).
  void clear();
  // Before the first corner is scheduled: whether this sweep's splits come
  // from a kinetic triangulation (every plane leaning in, enough corners,
  // loops it can triangulate).
  void start(State& st);
  bool triangulated() const { return triangulated_; }
  const KineticTriangulation& triangulation() const { return kt_; }
  // Before each batch: the triangulation follows what the last one relinked,
  // flips its spokes up to the next candidate's height, and the spans that
  // came to face a corner are listed as its splits.
  void catch_up(State& st);

  // Queues every potential event of corner c: meeting its next corner (the
  // span between them shrinks to nothing) and, where c can cut into the loop,
  // meeting any other live edge. `resolved` lists the edges of the collision
  // that made c, if any: c does not collide with them again where it stands.
  void schedule(State& st, int c, const std::vector<int>& resolved = {});
  // Queues the events of corner c running into each of `edges` (if c can cut
  // into the loop at all).
  void schedule_splits(State& st, int c, const std::vector<int>& edges, const std::vector<int>& resolved = {});
  // Queues only the event of corner c with its next corner.
  void schedule_edge_event(State& st, int c);
  // Whether a corner made by a collision of the planes of `resolved` (sorted)
  // meets edge's plane at height `at` because of it: one of them, no higher
  // than `near` (just above where it was made). A corner made where hundreds
  // of planes meet (a jittered star's centre) asks this of each of its splits.
  static bool met_where_made(const std::vector<int>& resolved, int edge, double at, double near) {
    return at <= near && std::binary_search(resolved.begin(), resolved.end(), edge);
  }
  // Whether corner c's splits were listed by the rule in force now: once a
  // plane leans out, convex corners split too, and corners meet planes from
  // outside.
  bool knows_outward(const State& st, int c) const {
    return !st.any_outward || (static_cast<std::size_t>(c) < outward_.size() && outward_[c]);
  }

  bool empty() const { return heap_.empty(); }
  double next_height() const { return heap_.top().z; }
  // Removes every candidate within the height tolerance of the lowest and
  // returns those of live corners, lowest first (valid until the next call),
  // but the splits that only repeat two collapses among them (closes_here).
  const std::vector<Candidate>& pop_cluster(State& st);

  // Split candidates held in lists now, and the most held at once: what the
  // lists cost in memory (a few per list, however many edges are live).
  std::size_t held() const { return held_; }
  std::size_t peak_held() const { return peak_held_; }
  // Splits worked out so far, at listing and each time a list runs out: the
  // queue's work, which testing every edge makes O(n r).
  std::size_t worked() const { return worked_; }

 private:
  // A split candidate: where the corner meets the edge's plane.
  using Split = Meeting;
  // A split's "edge" at or past this names a plane shared by several edges:
  // Targets::shared[edge - kShared].
  static constexpr int kShared = 1 << 30;
  // The live spans of a shared plane's edges at one height, sorted along its
  // line, for one batch: where a corner meets the plane, which of them are
  // there (named).
  struct SharedSpans {
    std::uint64_t batch = 0;  // the batch it was sorted for, or 0
    double z = 0.0;           // the height it was sorted at
    double drift = 0.0;       // the fastest any span's end moves along the line
    // Each span's ends along the line, by its low end, and the highest end so far.
    std::vector<double> lo, hi, hi_max;
    std::vector<int> edge;
  };
  // The planes a corner may run into, their coefficients side by side (the
  // test of every corner against every plane is the sweep's inner loop).
  // Only appended to: a list reads the first `size` planes, as they were when
  // it was listed, however many came since.
  //
  // Edges whose planes are the same to the bit (collinear, of one slope: a
  // grid's lines of walls) are one plane here. A corner meets all of them at
  // one point and height; as a split per edge, a square with k x k holes put
  // O(k) of every hole's corner's in one batch (O(n^1.5), nearly all missing
  // their edge's spans, each tested and then waiting in resolve_intersections).
  // The plane's split names, when popped, only the edges with a span there,
  // looked up along the line (named).
  struct Targets : PlaneColumns {
    std::vector<int> edge;  // a plane's one edge, or kShared + its place in `shared`
    std::vector<std::vector<int>> shared;      // the edges of each shared plane
    mutable std::vector<SharedSpans> spans;    // by shared plane, sorted as batches ask
    // Of the live edges (each listed once), built as lists of many need it:
    // it changes how their splits are found, not what they are.
    bool live = false;
    mutable PlaneIndex index;
    PlaneIndex::Planes planes() const { return {edge.data(), nx.data(), ny.data(), k.data(), c.data()}; }
    // Appends edge e's plane, of e alone.
    void add(int e, const Plane& pl);
    void reserve(std::size_t n);
    // The same edges with the same coefficients, to the bit.
    bool same_as(const Targets& o) const;
  };
  // Appends the planes of `edges` to t, each shared plane once. A plane once
  // read stays as it was (lists and the index hold its edge), so edges added
  // to a set later (Targets::add) are planes of their own.
  void list_planes(const State& st, const std::vector<int>& edges, Targets& t);
  // One scheduling's split candidates: what corner c was at when listed, and
  // the edges it was listed against, so that its splits can be worked out
  // again to the same bits. Only the lowest few are held, lowest last.
  struct SplitList {
    std::shared_ptr<const Targets> targets;
    std::size_t size = 0;  // the first `size` of targets
    CornerPath path;  // at the sweep plane's height when listed
    double near = 0.0;
    int prev_edge = kNone, next_edge = kNone;
    std::vector<int> resolved;  // edges of the collision that made the corner, sorted
    std::vector<Split> splits;  // the lowest not yet queued, lowest last
    std::size_t hold = 0;       // how many it holds when it works them out
    bool complete = false;      // it holds every split not yet queued
    Split last{0.0, kNone};     // the last queued
    std::size_t same = 0;       // queued in a row equal to `last` (an edge listed twice)
  };
  // Splits a list holds at once. Most corners live to see only a few of them
  // popped; each time the held ones run out, the list is worked out again
  // (one pass over its edges), so a list that runs out holds twice as many
  // the next time, up to kHeldMost: a long-lived corner whose splits keep
  // failing (a star's, passed by the edges' spans) costs a pass per
  // kHeldMost splits, not per kHeld.
  static constexpr std::size_t kHeld = 8, kHeldMost = 128;
  // A candidate in the height queue; its point is worked out when it is popped.
  struct Entry {
    double z, at;  // queued at height z; the planes meet at height `at`
    int corner, next, edge;
    int list;  // the split list it heads, or kNone (an edge event)
  };
  struct EntryLater {
    bool operator()(const Entry& a, const Entry& b) const;
  };
  // The order of one list's splits, as the queue orders them.
  using SplitEarlier = MeetingEarlier;
  // The edges with live spans. Edges gain spans only with new corners, which
  // add their edges; an edge that lost its spans since only costs candidates
  // that fail validation, until a full pass starts a new set and drops it.
  void refresh_live(State& st);
  void list_live(const State& st, int e);
  // Lists the splits of corner c against the first `size` of `targets`.
  // `from`: the height it is listed at (the sweep's, or where a corner made
  // in the last batch was made).
  void add_splits(const State& st, int c, std::shared_ptr<const Targets> targets, std::size_t size,
                  const std::vector<int>& resolved, double from);
  // Works out every split of `list` by testing each of its edges and offers
  // those not queued yet; returns how many it worked out.
  std::size_t find_splits(const SplitList& list, double through);
  // Takes split s into within_ if it is queued at or below `through`, else
  // among the list's lowest `hold` (lowest_), if it is one of them.
  void offer(const SplitList& list, const Split& s, double through);
  void hold_among_lowest(const SplitList& list, const Split& s);
  // Holds the lowest few of list i's splits after the last it queued, after
  // those queued at or below `through`, which go to within_ (unordered);
  // returns how many it worked out.
  std::size_t hold_next(int i, double through = -HUGE_VAL);
  // Whether `list` queues a split with `edge` at height `at` at all: not with
  // the corner's own edges, nor where the collision that made the corner put it.
  static bool queues(const SplitList& list, double at, int edge) {
    if (edge == list.prev_edge || edge == list.next_edge) return false;
    return !met_where_made(list.resolved, edge, at, list.near);
  }
  // The height a list's split is queued at: not below where it was listed.
  static double queued_at(const SplitList& list, const Split& s) { return std::max(s.at, list.path.z); }
  // Puts the lowest split of list i (of corner c) in the queue, or frees the list.
  void advance(int i, int c);
  // Notes that list i queued split s: its last, and how many equal to it.
  static void note_queued(SplitList& list, const Split& s);
  // The edges of split s's shared plane that it names, its corner at p at
  // height z: those with a span there, in order, each once. The plane's
  // other edges are passed: their spans are elsewhere along its line, and
  // could reach the point within the batch only past the nearest span on
  // either side, so where no span holds the point those two are named (a
  // lower cluster of the batch may rewire their ends to it).
  void named(const State& st, const SplitList& list, const Split& s, glm::dvec2 p, double z, std::vector<int>& out);
  // Adds the candidates of split s of list (of corner c) to the batch being
  // popped, but those closes_here drops.
  void hand_out(State& st, const SplitList& list, int c, const Split& s);
  // Every split of list i (of corner c) queued at or below `through` goes to
  // the batch being popped, in one pass over its edges (closes_here drops
  // some); then the list's next is queued.
  void drain(State& st, int i, int c, double through);
  // Whether split k repeats what two collapses of the batch being popped say:
  // its corner's span (or the one ending at it) and the span of its edge
  // through its point both close within delta3 of that point. The collision
  // it would add, the corner's two planes and the edge's, is then inside
  // theirs: the corner and the edge's span are at the point, the edge is not
  // cut through (resolve_cluster), and the three planes come in with them.
  // At the apex of an exact star every reflex corner meets every plane (n^2/2
  // splits at one point and height), and every span closes there.
  bool closes_here(State& st, const Candidate& k) const;
  void free_list(int i);
  // schedule_splits' listing, of the planes of `edges` alone.
  void list_splits(State& st, int c, const std::vector<int>& edges, const std::vector<int>& resolved);
  // Lists the splits of the pairs the triangulation handed out (facing, and
  // the tangled corners' against every plane).
  void list_facing(State& st);
  // pop_cluster's: takes every candidate queued at or below `through` into
  // the batch (cluster_, heads_, shared_heads_).
  void pop_through(State& st, double through);
  // Triangulated, lists the pairs that may meet near the batch's candidates
  // from `widened` on and its shared planes' heads from `widened_shared` on
  // (KineticTriangulation::hand_around), which may move `rise` within it;
  // false where there were none.
  bool widen(State& st, std::size_t& widened, std::size_t& widened_shared, double rise);
  // How far apart a batch's events are one neighbourhood: the sweep's clustering reach.
  static double reach(const State& st);
  // Leaves the triangulation: every live corner lists its splits against
  // every live plane, as a sweep without it does.
  void drop_triangulation(State& st);
  // Lists live corner c's splits against every live plane, once while
  // triangulated (listed_whole_).
  void list_every_plane(State& st, int c);
  bool listed_whole(int c) const;
  // A corner listed against every plane after some of its facing pairs were
  // (tangled, crowded, or the triangulation left) has those splits twice: a
  // batch keeps the first of each (corner, edge), since it does not take a
  // collision twice well (pop_cluster, while lists_twice_).
  void drop_repeated_splits();
  // State::meeting_slack of entry e's planes, while its corners still meet there.
  double slack(const State& st, const Entry& e) const;

  struct Heap : std::priority_queue<Entry, std::vector<Entry>, EntryLater> {
    void clear() { c.clear(); }
  };
  Heap heap_;
  std::vector<SplitList> lists_;
  std::vector<int> free_lists_;
  std::shared_ptr<Targets> live_ = std::make_shared<Targets>();
  std::shared_ptr<const Targets> some_;               // the last edges schedule_splits was given
  std::vector<char> listed_;                          // edge -> in live_
  std::vector<char> outward_;                         // corner -> scheduled once a plane leaned out
  std::size_t live_corners_ = 0, rebuilt_at_ = 0;    // corners seen by live_, at its last full pass
  std::size_t held_ = 0, peak_held_ = 0, worked_ = 0;
  std::size_t indexed_from_, triangulated_from_;
  KineticTriangulation kt_;
  bool triangulated_ = false;
  bool leave_triangulation_ = false;  // planes changed under corners: drop it at the next catch_up()
  bool lists_twice_ = false;          // this sweep was triangulated: a pair may be listed twice
  // The edges of the collision that made each corner, while triangulated:
  // its splits are listed after the batch that made it.
  std::vector<std::vector<int>> made_by_;
  const std::vector<int>& made_by(int c) const;
  // Where each corner made in the last batch was made (NaN once listed):
  // the batch resolves its clusters each at its own height, and a corner's
  // splits listed from the batch's last height instead would queue those
  // below it there, in another order than the listing's (the tests' stars of
  // 3,500 and 4,000 corners then did not close).
  std::vector<double> made_at_;
  std::vector<int> fresh_;
  double listed_from(const State& st, int c) const;
  std::vector<int> facing_edges_;  // catch_up()'s
  std::vector<char> listed_whole_;  // corner -> listed against every live plane (a tangle round it)
  PlaneIndex::Scratch index_scratch_;
  std::vector<double> at_;  // scratch of find_splits
  std::vector<std::uint32_t> hits_;
  std::vector<Split> found_, found_within_;  // of the index's search: above and within the batch
  // hold_next's: the lowest offered above its `through`, in order, and how
  // many were offered there.
  std::vector<Split> lowest_;
  std::size_t after_through_ = 0;
  std::vector<Candidate> cluster_;  // what pop_cluster returned last
  // pop_cluster's: where each span closing in the batch closes, by its first
  // corner (current where `batch` is batch_), the lists whose first split in
  // the batch was popped (its place in cluster_, the list), and the splits
  // hold_next took at or below its `through`.
  struct Closing {
    std::uint64_t batch = 0;
    glm::dvec2 p{0.0};
  };
  std::vector<Closing> closing_;
  std::uint64_t batch_ = 0;
  std::vector<std::pair<std::size_t, int>> heads_;
  std::vector<Split> within_;
  std::vector<int> named_;  // hand_out's
  std::vector<std::tuple<double, double, int>> shared_sorted_;  // named()'s
  // list_planes': each edge's plane by its bits, its first edge of that plane,
  // how many edges share it (by first), and its place in the Targets.
  struct PlaneKey {
    std::array<std::uint64_t, 4> bits;
  };
  std::vector<std::pair<PlaneKey, std::size_t>> keyed_;
  std::vector<std::size_t> first_, sharing_, place_;
  std::vector<int> live_edges_;  // refresh_live's
  // pop_cluster's: the heads that are splits with a shared plane (SIZE_MAX in
  // heads_), by corner.
  std::vector<std::pair<int, Split>> shared_heads_;
  std::vector<KineticTriangulation::Place> places_;  // widen()'s and catch_up()'s
  std::vector<std::tuple<int, int, std::size_t>> repeated_;  // drop_repeated_splits': (corner, edge, place)
};

}  // namespace procex::engine

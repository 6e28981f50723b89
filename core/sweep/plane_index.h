// A corner's lowest meetings among many planes without testing every plane
// (issue 18 item 1): a reflex corner may run into any live edge's plane, and
// testing each of n planes for each of r reflex corners is O(n r).
//
// The planes are kept in trees (kd-trees over the planes' normals and
// offsets, split at medians), each node bounding how near and how fast a
// corner can approach its planes, hence how low it can meet any of them; the
// search goes lowest bound first and stops once it holds as many meetings as
// asked, all below every unvisited node's bound. Each meeting is worked out by
// meeting_heights on the plane's own coefficients, so it is the meeting testing
// every plane gives, to the bit, and the lowest few are the same ones.
//
// The planes are appended to (a set of live edges gains those of new corners)
// and read by prefix (a list reads the planes as they were when it was
// listed): the trees cover consecutive runs of planes, merged as they grow
// (each about twice the next), and a plane past a list's prefix is skipped.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "core/sweep/meeting_heights.h"

namespace procex::engine {

// Where a corner meets an edge's plane.
struct Meeting {
  double at;
  int edge;
};

// The order the event queue hands out one corner's meetings: by the height
// it queues them at (not below the sweep plane's height z), then by edge.
struct MeetingEarlier {
  double z;
  bool operator()(const Meeting& a, const Meeting& b) const {
    const double za = std::max(a.at, z), zb = std::max(b.at, z);
    return za != zb ? za < zb : a.edge < b.edge;
  }
};

class PlaneIndex {
 public:
  // The planes n.x - k z = c side by side, appended to only.
  struct Planes {
    const int* edge;
    const double *nx, *ny, *k, *c;
  };
  // A corner at p at height z moving by v per unit of height, tested against
  // the first `size` planes as meeting_heights tests them; only meetings
  // after `after` (MeetingEarlier) count, unless its edge is negative.
  // Every meeting queued at or below `through` is wanted (a batch takes them
  // all at once).
  struct Query : CornerPath {
    std::size_t size;
    Meeting after;
    double through;
  };
  // Scratch space of lowest(), kept by the caller across searches.
  struct Scratch {
    std::vector<std::pair<double, std::uint64_t>> open;  // (bound, tree << 32 | node), a min-heap
    std::vector<double> meet;
  };

  // Planes [indexed(), size) not yet in a tree are tested one by one, until
  // they are enough to be worth a tree of their own: extend() builds it,
  // shaped for corners about as far from the planes as `near` is.
  void extend(const Planes& planes, std::size_t size, glm::dvec2 near);
  std::size_t indexed() const { return indexed_; }

  // The meetings after q.after (MeetingEarlier) queued at or below
  // q.through, into `within`, and the `hold` lowest above it, into `out`
  // (each unordered), each plane's once. Returns how many meetings it worked
  // out, or nothing where the search gives up: past a sixteenth of the planes
  // besides those it hands out within, the bounds do not tell the lowest apart
  // (a star's reflex corner meets almost every line near the star's centre,
  // within a millimetre of one height), and testing every plane costs less (a
  // node's bounds and the heap cost a few plane tests each, which run side by
  // side).
  std::optional<std::size_t> lowest(const Planes& planes, const Query& q, std::size_t hold, std::vector<Meeting>& out,
                                    std::vector<Meeting>& within, Scratch& scratch);
  // Whether searching is worth it: not once a quarter of the searches gave up.
  bool worth_searching() const { return searches_ < kTrial || 4 * given_up_ < searches_; }

 private:
  struct Node {
    // Bounds of the planes' normals, offsets (from the tree's origin) and slopes.
    double nx_lo, nx_hi, ny_lo, ny_hi, c_lo, c_hi, k_lo, k_hi;
    std::uint32_t begin, end;  // the node's planes in the tree's order
    std::int32_t left;         // children left and left + 1, or kLeaf
  };
  struct Tree {
    std::size_t from = 0, to = 0;  // the planes it holds
    glm::dvec2 origin{0.0};
    // How far off the bounds' arithmetic may be from meeting_heights': the
    // magnitudes of the terms it rounds.
    double c_abs = 0.0, k_abs = 0.0;
    std::vector<Node> nodes;
    // The planes in the tree's order, so that a leaf's are side by side.
    std::vector<double> nx, ny, k, c;
    std::vector<int> edge;
    std::vector<std::uint32_t> index;  // position among the planes
  };
  static Tree build(const Planes& planes, std::size_t from, std::size_t to, glm::dvec2 near);
  // A height no meeting with the node's planes is queued below, or HUGE_VAL
  // where none of them can meet the corner or all meet it before q.after;
  // the higher of the bounds taken at the corner's height and at h0.
  static double bound(const Tree& t, const Node& n, const Query& q, double h0);
  // The rates the corner's distance to the node's planes changes at, n.v - k,
  // bounded with their rounding.
  static std::pair<double, double> rates(const Tree& t, const Node& n, const Query& q);
  // The same seen from where the corner is at height h0 > q.z, given the
  // planes' rates of approach [r_lo, r_hi]; -HUGE_VAL where it bounds nothing.
  // The corner's distance to the node's planes' lines where it is at height
  // h0, n.(p + v (h0 - z) - origin) - c' - k h0, bounded with the rounding of
  // it and of meeting_heights' distance at z (equal in exact arithmetic).
  static std::pair<double, double> distance_at(const Tree& t, const Node& n, const Query& q, double h0);
  static double bound_from(const Tree& t, const Node& n, const Query& q, double h0, double r_lo, double r_hi);

  // Searches before worth_searching() judges.
  static constexpr std::size_t kTrial = 16;
  // A search gives up past 1 / kGiveUpPast of the planes, and not before
  // kGiveUpLeast (a few dozen leaves: a search through fewer planes than that
  // costs little whichever way it goes).
  static constexpr std::size_t kGiveUpPast = 16, kGiveUpLeast = 512;

  std::vector<Tree> trees_;
  std::size_t indexed_ = 0;
  std::size_t searches_ = 0, given_up_ = 0;
};

}  // namespace procex::engine

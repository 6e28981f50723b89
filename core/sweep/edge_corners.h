// The corners at the ends of an edge's spans, sorted along the edge, for the
// edges with many spans. A cluster takes in every corner of its edges that
// sits at its point (resolve_cluster); found by visiting every span of every
// edge taking part, that was quadratic where one edge is cut a thousand
// times: a comb's bar, cut at every tooth in one instant, spent half its roof
// there at 65,536 vertices (issue 18).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

class EdgeCorners {
 public:
  // Whether e has spans enough that looking corners up beats visiting them
  // all, with `partners` edges to look up the corners between
  // (State::corners_indexed_from).
  static bool worth(const State& st, int e, std::size_t partners) {
    const std::size_t spans = st.edges[e].listed_spans;
    // Each partner edge costs a lookup, each span a visit.
    return st.corners_indexed_from == 0 || (spans >= st.corners_indexed_from && 4 * partners < spans);
  }

  // Appends the live corners at the ends of e's spans whose place along the
  // edge at height z lies within `reach` of p's, and maybe a few more.
  void near(const State& st, int e, glm::dvec2 p, double z, double reach, std::vector<int>& out);
  // Appends the live corners between edges e and f that end a span of e.
  void between(const State& st, int e, int f, std::vector<int>& out);
  // Entries sorted in or moved by merges so far: the index's upkeep.
  std::size_t moved() const { return moved_; }

 private:
  // Sorted runs, each more than twice as long as the next, and the entries
  // made since, unsorted (a few): an entry is merged O(log n) times, where
  // merging every few made into one sorted list moved the whole list each
  // time (the comb's bar at 1,048,576 vertices: a sixth of the sweep).
  template <class Entry>
  struct Runs {
    std::vector<std::vector<Entry>> sorted;
    std::vector<Entry> recent;
    std::size_t size() const;
  };
  struct Index {
    // Places along the edge at height z0, and (other edge, corner).
    Runs<std::pair<double, int>> places;
    Runs<std::pair<int, int>> partners;
    double z0 = 0.0;
    double fastest = 0.0;        // along the edge, of any corner listed: how far places drift from z0
    std::size_t looked_at = 0;  // entries looked at since places were last taken
  };

  Index& index_of(const State& st, int e, double z);
  void take_new_corners(const State& st);
  void add(const State& st, Index& index, int e, int c);
  // Sorts the entries made since into a run of their own, dropping the dead,
  // and merges it into the runs before it while they are not twice as long.
  template <class Entry>
  void merge_recent(const State& st, Runs<Entry>& runs);
  // Takes every place again at height z, in one run.
  void retake(const State& st, Index& index, int e, double z);

  std::vector<int> slot_;  // by edge: its index in indexes_, or -1
  std::vector<Index> indexes_;
  std::size_t seen_ = 0;  // corners made before this are listed where they belong
  std::size_t moved_ = 0;
};

}  // namespace procex::engine

// Finding which of many 2D segments touch or cross, in about O(n log n) for
// the inputs procex sees (footprint loops, face outlines): the segments are
// grouped in a hierarchy of strips turned along them and only segments whose
// strips overlap are compared, with the exact predicates of predicates.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

struct Segment2 {
  glm::dvec2 a, b;
};

// Calls visit(i, j), i < j, once for every pair of segments that come
// within 2 * within of each other (touching counts), and perhaps for some
// farther apart whose boxes, grown by within, overlap; until it returns
// false. A segment may be a point (a == b).
void for_each_near_segment_pair(const std::vector<Segment2>& segments, double within,
                                const std::function<bool(std::size_t, std::size_t)>& visit);

// Whether segments i and j share a point or, with within > 0, come within
// that distance of each other: what is apart by less than a tolerance is not
// apart at that tolerance.
bool segments_meet(const Segment2& i, const Segment2& j, double within);

// Pairs (i, j), i < j, of segments that share at least one point. Segments
// that follow each other (next[i] == j: segment i ends where j starts, as in
// a loop) share that endpoint by design and are reported only if they also
// overlap (the loop doubles back on itself). next may be empty (no chains);
// otherwise next[i] is the segment following i, or SIZE_MAX for none.
// Stops after max_pairs pairs. With within > 0, segments that come within
// that distance of each other count as touching too (consecutive ones when
// the far end of one lies that near the other: they fold back): what is
// apart by less than a tolerance is not apart at that tolerance.
std::vector<std::pair<std::size_t, std::size_t>> intersecting_segment_pairs(const std::vector<Segment2>& segments,
                                                                            const std::vector<std::size_t>& next,
                                                                            std::size_t max_pairs = 64,
                                                                            double within = 0.0);

// The segments of closed loops, with next[] linking each loop's edges in a
// cycle; first[k] is the index of loop k's first edge.
struct LoopSegments {
  std::vector<Segment2> segments;
  std::vector<std::size_t> next;
  std::vector<std::size_t> first;
};
LoopSegments loop_segments(const std::vector<std::vector<glm::dvec2>>& loops);

// The first two edges of a closed loop found to meet other than where one
// follows the other (edge k runs from loop[k] to loop[k + 1]): none where the
// loop is a simple polygon.
std::optional<std::pair<std::size_t, std::size_t>> loop_crossing(const std::vector<glm::dvec2>& loop);

}  // namespace procex

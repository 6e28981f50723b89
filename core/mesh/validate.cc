#include "core/mesh/validate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <sstream>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/convex_partition.h"
#include "core/geom/oriented_box.h"
#include "core/geom/polygon3.h"
#include "core/geom/round_edge.h"
#include "core/geom/segment_intersections.h"
#include "core/geom/tolerances.h"
#include "core/mesh/height_field.h"

namespace procex {

namespace {

// Problems listed per kind before the rest are only counted.
constexpr std::size_t kMaxProblemsPerKind = 20;
// Pairs of intersecting triangles looked for before the check stops.
constexpr std::size_t kMaxIntersectionPairs = 64;

glm::dvec3 to_glm(const Mesh::Point& p) { return {p[0], p[1], p[2]}; }

class Problems {
 public:
  explicit Problems(std::vector<std::string>& out) : out_(out) {}
  void add(const std::string& kind, const std::string& text) {
    if (++counts_[kind] <= kMaxProblemsPerKind) out_.push_back(text);
  }
  ~Problems() {
    for (const auto& [kind, count] : counts_)
      if (count > kMaxProblemsPerKind)
        out_.push_back("... and " + std::to_string(count - kMaxProblemsPerKind) + " more " + kind + " problems");
  }

 private:
  std::vector<std::string>& out_;
  std::map<std::string, std::size_t> counts_;
};

std::string fmt_number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string fmt_point(const glm::dvec3& p) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

// Vertices at equal positions share one id, so a face whose neighbours were
// stitched through copies of their vertices (as OBJ readers do with faces
// OpenMesh refuses) is still seen next to them. Ids are numbered in the order
// of each position's first vertex. The positions are sorted in one array (a
// hash map of them made a heap block a vertex, read back in no order: 0.46 s
// of a 262,144-corner roof's validation); a vertex with a NaN equals none.
std::vector<std::uint32_t> weld_positions(const Mesh& mesh) {
  struct Position {
    std::array<double, 3> p;
    std::uint32_t vertex;
  };
  std::vector<Position> sorted;
  sorted.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    if (!std::isnan(p[0]) && !std::isnan(p[1]) && !std::isnan(p[2]))
      sorted.push_back({{p[0], p[1], p[2]}, static_cast<std::uint32_t>(v.idx())});
  }
  std::sort(sorted.begin(), sorted.end(), [](const Position& a, const Position& b) {
    return a.p != b.p ? a.p < b.p : a.vertex < b.vertex;
  });
  std::vector<std::uint32_t> first(mesh.n_vertices());  // the first vertex at each vertex's position
  for (std::uint32_t v = 0; v < first.size(); ++v) first[v] = v;
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k].p == sorted[k - 1].p) first[sorted[k].vertex] = first[sorted[k - 1].vertex];
  std::vector<std::uint32_t> welded(mesh.n_vertices());
  std::uint32_t ids = 0;
  for (std::uint32_t v = 0; v < welded.size(); ++v) welded[v] = first[v] == v ? ids++ : welded[first[v]];
  return welded;
}

void check_topology(const Mesh& mesh, const std::vector<std::uint32_t>& welded, ValidationReport& r, Problems& problems) {
  r.closed = true;
  for (const auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h)) continue;
    r.closed = false;
    const auto opposite = mesh.opposite_halfedge_handle(h);
    problems.add("closed", "edge (" + std::to_string(mesh.from_vertex_handle(h).idx()) + ", " +
                               std::to_string(mesh.to_vertex_handle(h).idx()) + ") has a face on one side only (face " +
                               std::to_string(mesh.face_handle(opposite).idx()) + "): the mesh is not closed");
  }

  // A vertex whose faces form one fan has at most one gap (one outgoing
  // boundary half-edge); OpenMesh links several fans through their gaps.
  bool fans_ok = true;
  std::vector<int> gaps(mesh.n_vertices(), 0);
  for (const auto h : mesh.halfedges())
    if (mesh.is_boundary(h)) ++gaps[mesh.from_vertex_handle(h).idx()];
  for (const auto v : mesh.vertices()) {
    if (mesh.is_isolated(v)) {
      fans_ok = false;
      problems.add("manifold", "vertex " + std::to_string(v.idx()) + " belongs to no face");
    } else if (gaps[v.idx()] > 1) {
      fans_ok = false;
      problems.add("manifold", "vertex " + std::to_string(v.idx()) + " joins several separate fans of faces");
    }
  }

  // Directed edges between welded positions: each must be used once, and
  // each undirected edge by exactly two faces, unless parts of the solid
  // touch along it (round_edge.h): as many faces each way, alternating round it.
  // One array sorted by edge, each edge's faces in the order met (a tree map
  // of a list an edge made a heap block per half-edge, in no order in memory).
  struct Directed {
    std::uint32_t from, to;
    int face;
  };
  std::vector<Directed> directed;
  directed.reserve(mesh.n_halfedges());
  std::vector<glm::dvec3> position(mesh.n_vertices());
  for (const auto v : mesh.vertices()) position[welded[v.idx()]] = to_glm(mesh.point(v));
  for (const auto f : mesh.faces())
    for (const auto h : mesh.fh_range(f))
      directed.push_back({welded[mesh.from_vertex_handle(h).idx()], welded[mesh.to_vertex_handle(h).idx()], f.idx()});
  const auto by_edge = [](const Directed& a, const Directed& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  };
  std::stable_sort(directed.begin(), directed.end(), by_edge);
  auto normal = [&](int f) {
    std::vector<glm::dvec3> pts;
    for (const auto v : mesh.fv_range(mesh.face_handle(f))) pts.push_back(to_glm(mesh.point(v)));
    return glm::normalize(newell_normal(pts));
  };
  using Run = std::span<const Directed>;
  auto touching_along = [&](const Directed& edge, Run ahead, Run back) {
    if (ahead.size() != back.size()) return false;
    std::vector<FaceAtEdge> round;
    for (const Directed& d : ahead) round.push_back({normal(d.face), true});
    for (const Directed& d : back) round.push_back({normal(d.face), false});
    return twins_round_edge(position[edge.to] - position[edge.from], round).has_value();
  };
  bool edges_ok = true, directions_ok = true;
  for (auto first = directed.begin(); first != directed.end();) {
    const auto last = std::find_if(first, directed.end(), [&](const Directed& d) { return by_edge(*first, d); });
    const Directed& edge = *first;
    const Run faces(first, last);
    const auto [back_first, back_last] = std::equal_range(directed.begin(), directed.end(),
                                                          Directed{edge.to, edge.from, 0}, by_edge);
    const Run back(back_first, back_last);
    first = last;
    const std::size_t total = faces.size() + back.size();
    if (total > 2 && !back.empty() && touching_along(edge, faces, back)) continue;
    if (total > 2 && edge.from < edge.to) {
      edges_ok = false;
      problems.add("manifold", "edge between welded vertices " + std::to_string(edge.from) + " and " +
                                   std::to_string(edge.to) + " has " + std::to_string(total) + " faces");
    }
    if (faces.size() > 1) {
      directions_ok = false;
      problems.add("oriented", "faces " + std::to_string(faces[0].face) + " and " + std::to_string(faces[1].face) +
                                   " both run along the edge from welded vertex " + std::to_string(edge.from) +
                                   " to " + std::to_string(edge.to) + ": one of them is flipped");
    }
  }
  r.manifold = r.closed && fans_ok && edges_ok;
  r.oriented = directions_ok;
}

}  // namespace

double signed_volume(const Mesh& mesh) {
  // Relative to a vertex of the mesh: far from the origin (a building at
  // x = 1e9) the products of absolute coordinates would lose the volume.
  const glm::dvec3 origin = mesh.n_vertices() > 0 ? to_glm(mesh.point(*mesh.vertices_begin())) : glm::dvec3(0.0);
  double six_v = 0.0;
  for (const auto f : mesh.faces()) {
    auto it = mesh.cfv_iter(f);
    const glm::dvec3 a = to_glm(mesh.point(*it)) - origin;
    ++it;
    glm::dvec3 b = to_glm(mesh.point(*it)) - origin;
    for (++it; it.is_valid(); ++it) {
      const glm::dvec3 c = to_glm(mesh.point(*it)) - origin;
      six_v += glm::dot(a, glm::cross(b, c));
      b = c;
    }
  }
  return six_v / 6.0;
}

namespace {

// Splits every face into triangles (over each convex piece), the slivers
// without area after the rest (their count is returned in `slivers`); checks
// on the way that each face is a simple polygon.
std::vector<MeshTriangle> triangulate_faces(const Mesh& mesh, const std::vector<std::uint32_t>& welded,
                                            double tolerance, ValidationReport& r, Problems& problems,
                                            std::size_t& slivers) {
  std::vector<MeshTriangle> tris, thin;
  tris.reserve(mesh.n_faces() * 2);
  std::vector<glm::dvec3> pts;
  std::vector<std::uint32_t> ids;
  for (const auto f : mesh.faces()) {
    pts.clear();
    ids.clear();
    for (const auto v : mesh.fv_range(f)) {
      pts.push_back(to_glm(mesh.point(v)));
      ids.push_back(welded[v.idx()]);
    }
    const glm::dvec3 normal = newell_normal(pts);
    const std::vector<glm::dvec2> flat = drop_axis(pts, normal);
    std::vector<std::vector<std::uint32_t>> pieces;
    if (is_convex(flat)) {
      pieces.emplace_back(pts.size());
      for (std::uint32_t k = 0; k < pts.size(); ++k) pieces[0][k] = k;
    } else {
      if (const auto crossing = loop_crossing(flat)) {
        r.self_intersection_free = false;
        problems.add("self-intersection", "face " + std::to_string(f.idx()) + " is not a simple polygon: its edges " +
                                              std::to_string(crossing->first) + " and " +
                                              std::to_string(crossing->second) + " meet");
      }
      pieces = convex_partition({flat});
    }
    for (const auto& piece : pieces) {
      // Halving the piece rather than fanning it keeps most triangles small,
      // so a face with thousands of vertices does not become thousands of
      // slivers spanning the whole face (and the whole grid).
      std::vector<std::pair<std::size_t, std::size_t>> chains{{0, piece.size() - 1}};
      while (!chains.empty()) {
        const auto [lo, hi] = chains.back();
        chains.pop_back();
        if (hi - lo < 2) continue;
        const std::size_t mid = (lo + hi) / 2;
        chains.push_back({lo, mid});
        chains.push_back({mid, hi});
        MeshTriangle t{{pts[piece[lo]], pts[piece[mid]], pts[piece[hi]]},
                       {ids[piece[lo]], ids[piece[mid]], ids[piece[hi]]},
                       f.idx()};
        const glm::dvec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
        const double longest = std::max({glm::length(e1), glm::length(e2), glm::length(t.p[2] - t.p[1])});
        (glm::length(glm::cross(e1, e2)) > tolerance * longest ? tris : thin).push_back(t);
      }
    }
  }
  slivers = thin.size();
  tris.insert(tris.end(), thin.begin(), thin.end());
  return tris;
}

// Coplanar triangles facing the same way overlap if an edge of one properly
// crosses an edge of the other or a vertex of one lies inside the other.
// Facing opposite ways they are two solids in contact, which is allowed.
bool coplanar_overlap(const MeshTriangle& a, const MeshTriangle& b, const glm::dvec3& na, const glm::dvec3& nb,
                      double tol) {
  if (glm::dot(na, nb) <= 0.0) return false;
  auto inside = [&](const glm::dvec3& x, const MeshTriangle& t) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 inward = glm::normalize(glm::cross(na, t.p[(k + 1) % 3] - t.p[k]));
      if (glm::dot(inward, x - t.p[k]) <= tol) return false;
    }
    return true;
  };
  for (int i = 0; i < 3; ++i)
    if (inside(a.p[i], b) || inside(b.p[i], a)) return true;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 &p = a.p[i], &q = a.p[(i + 1) % 3];
    for (int j = 0; j < 3; ++j) {
      const glm::dvec3 &r = b.p[j], &s = b.p[(j + 1) % 3];
      const double o1 = glm::dot(na, glm::cross(q - p, r - p)), o2 = glm::dot(na, glm::cross(q - p, s - p));
      const double o3 = glm::dot(na, glm::cross(s - r, p - r)), o4 = glm::dot(na, glm::cross(s - r, q - r));
      const double lpq = glm::length(q - p) * tol, lrs = glm::length(s - r) * tol;
      if (((o1 > lpq && o2 < -lpq) || (o1 < -lpq && o2 > lpq)) && ((o3 > lrs && o4 < -lrs) || (o3 < -lrs && o4 > lrs)))
        return true;
    }
  }
  return false;
}

// Where triangle t meets the other triangle's plane (d: its vertices' signed
// distances to it), as an interval along the planes' common line direction.
std::pair<double, double> plane_interval(const MeshTriangle& t, const std::array<double, 3>& d, const glm::dvec3& dir) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto add = [&](const glm::dvec3& p) {
    const double s = glm::dot(dir, p);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  };
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    if (d[k] == 0.0) add(t.p[k]);
    if ((d[k] > 0.0 && d[l] < 0.0) || (d[k] < 0.0 && d[l] > 0.0)) add(t.p[k] + (d[k] / (d[k] - d[l])) * (t.p[l] - t.p[k]));
  }
  return {lo, hi};
}

glm::dvec3 unit_normal(const MeshTriangle& t) { return glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0])); }

// Two triangles intersect when each passes through the other's plane
// (vertices strictly on both sides) and the two crossing segments, which lie
// on the planes' common line, overlap by more than tol. Triangles that only
// touch (a vertex or edge on the other's plane, or along a line) do not.
// na and nb are the triangles' unit_normal.
bool triangles_intersect(const MeshTriangle& a, const MeshTriangle& b, const glm::dvec3& na, const glm::dvec3& nb,
                         double tol) {
  std::array<double, 3> da{}, db{};  // a's vertices against b's plane, and back
  for (int k = 0; k < 3; ++k) {
    da[k] = glm::dot(nb, a.p[k] - b.p[0]);
    db[k] = glm::dot(na, b.p[k] - a.p[0]);
  }
  auto flat = [tol](const std::array<double, 3>& d) {
    return std::abs(d[0]) <= tol && std::abs(d[1]) <= tol && std::abs(d[2]) <= tol;
  };
  if (flat(da) && flat(db)) return coplanar_overlap(a, b, na, nb, tol);
  auto straddles = [tol](const std::array<double, 3>& d) {
    return std::max({d[0], d[1], d[2]}) > tol && std::min({d[0], d[1], d[2]}) < -tol;
  };
  if (!straddles(da) || !straddles(db)) return false;
  const glm::dvec3 cross = glm::cross(na, nb);
  if (glm::length(cross) == 0.0) return false;
  const glm::dvec3 dir = glm::normalize(cross);
  const auto [a_lo, a_hi] = plane_interval(a, da, dir);
  const auto [b_lo, b_hi] = plane_interval(b, db, dir);
  return std::min(a_hi, b_hi) - std::max(a_lo, b_lo) > tol;
}

// Triangles sharing an edge lie on two planes through it and meet only along
// it (or fold flat onto each other facing opposite ways, which touching
// allows). Triangles sharing one vertex are tested: planes through a common
// vertex cross on a line through it, and a fold-over there shows as a segment
// of that line inside both.
bool share_edge(const MeshTriangle& a, const MeshTriangle& b) {
  int shared = 0;
  for (std::uint32_t u : a.v)
    for (std::uint32_t w : b.v)
      if (u == w) ++shared;
  return shared >= 2;
}

// Pairs of triangles that share a vertex are found round that vertex, the
// rest through a bounding-volume hierarchy. A bounding box cannot part the
// triangles of a fan: a regular polygon's roof has n triangles meeting at its
// apex, so every box holds the apex and every pair of boxes overlaps, and a
// grid or a hierarchy of boxes alone tests O(n^2) pairs there. Two triangles
// through one vertex intersect only along a segment from it (their common
// part is convex and holds the vertex), so whether they do is decided by the
// directions leaving the vertex; the hierarchy keeps each large fan in a
// subtree of its own and never compares a fan with itself.
class IntersectionSearch {
 public:
  // `left`, by triangle: how the proof over the base (height_field.h) left
  // it to the search (kCovered, kUpright or a wall's outline edge); empty
  // where the proof did not hold. With only_left, a pair the proof covers is
  // not tested; else it is, and found crossing contradicts the proof.
  IntersectionSearch(std::vector<MeshTriangle> tris, double tol, ValidationReport& r, Problems& problems,
                     std::vector<std::uint32_t> left = {}, bool only_left = false)
      : tris_(std::move(tris)), tol_(tol), r_(r), problems_(problems), left_(std::move(left)),
        only_left_(only_left && !left_.empty()), boxes_(tris_.size()), normals_(tris_.size()), fit_(tris_.size()),
        turned_(tris_.size() >= kTurnedFrom) {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const MeshTriangle& t = tris_[i];
      normals_[i] = unit_normal(t);
      glm::dvec3 a = t.p[0], b = t.p[0];
      for (const auto& p : t.p) {
        a = glm::min(a, p);
        b = glm::max(b, p);
      }
      boxes_[i] = {a - tol, b + tol};
      // The box's two largest sides against the triangle: 2 for a triangle
      // along the axes, about length / width for a sliver running diagonally.
      glm::dvec3 e = b - a;
      if (e.x < e.y) std::swap(e.x, e.y);
      if (e.y < e.z) std::swap(e.y, e.z);
      if (e.x < e.y) std::swap(e.x, e.y);
      fit_[i] = {e.x * e.y, 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]))};
    }
  }

  void run() {
    if (tris_.size() < 2) return;
    if (only_left_) {
      check_walls_by_edge();
      if (std::find(left_.begin(), left_.end(), kUpright) == left_.end()) return;
    }
    {
      const std::vector<std::vector<std::uint32_t>> around = triangles_around_vertices();
      for (std::uint32_t v = 0; v < around.size() && !done(); ++v) check_vertex(v, around[v]);
      if (done()) return;
      build_hierarchy(around);
    }
    in_tree_order();
    if (nodes_.empty()) return;
    if (only_left_) {
      upright_.assign(nodes_.size(), 0);
      mark_upright(root_);
    }
    self_pairs(root_);
  }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  // Round a vertex of fewer triangles every pair is tested directly; a vertex
  // of more is a fan worth a subtree of its own.
  static constexpr std::size_t kFanSize = 16;
  static constexpr std::size_t kLeafSize = 4;
  // Below this many triangles a hierarchy of boxes along the axes is
  // searched faster than its turned boxes are made.
  static constexpr std::size_t kTurnedFrom = 256;
  // Turned boxes are made for nodes whose triangles' boxes hold more than
  // this many times their area: long thin triangles running diagonally.
  static constexpr double kLoose = 8.0;
  // A loose range is split along or across its long edges only where that
  // costs (split_loose) less than this share of the split along an axis: the
  // cost only estimates the pairs, and a star's roof, whose slivers run every
  // way, lost more pairs to close calls than it gained (measured: random
  // spiky roofs of 16,384 and 65,536 corners 20M -> 6.3M and 180M -> 33M
  // pairs; stars of 4,096 and 8,192 corners up 10 % and 3 %, combs of 8,192
  // up 28 %; with no margin, stars up 80 %).
  static constexpr double kTurnWorth = 0.8;

  // The area of the triangles below a node, and of their boxes.
  struct Fit {
    double room = 0.0, area = 0.0;
    Fit operator+(const Fit& o) const { return {room + o.room, area + o.area}; }
  };

  struct Box {
    glm::dvec3 lo, hi;
  };
  struct Node {
    Box box;
    std::uint32_t first = 0, count = 0;     // a leaf's triangles in order_ (in tris_, once in_tree_order)
    std::uint32_t left = kNone, right = kNone;
    std::uint32_t fan = kNone;  // the welded vertex every triangle below shares, if one does
    Fit fit;
  };

  bool done() const { return found_ >= kMaxIntersectionPairs; }

  static bool overlap(const Box& a, const Box& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
  }

  std::vector<std::vector<std::uint32_t>> triangles_around_vertices() const {
    std::uint32_t n = 0;
    for (const MeshTriangle& t : tris_) n = std::max({n, t.v[0] + 1, t.v[1] + 1, t.v[2] + 1});
    std::vector<std::vector<std::uint32_t>> around(n);
    for (std::uint32_t i = 0; i < tris_.size(); ++i)
      for (std::uint32_t v : tris_[i].v) around[v].push_back(i);
    return around;
  }

  // Whether the proof covers the pair: neither is upright, and they are not
  // walls on one edge of the base's outline.
  bool covered(std::uint32_t i, std::uint32_t j) const {
    return !left_.empty() && left_[i] != kUpright && left_[j] != kUpright &&
           (left_[i] != left_[j] || left_[i] == kCovered);
  }

  // The pairs of walls on one edge of the base's outline (only_left_): the
  // rest of their pairs the proof covers.
  void check_walls_by_edge() {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> walls;  // (edge, triangle)
    for (std::uint32_t i = 0; i < left_.size(); ++i)
      if (left_[i] != kCovered && left_[i] != kUpright) walls.emplace_back(left_[i], i);
    std::sort(walls.begin(), walls.end());
    for (std::size_t first = 0; first < walls.size() && !done();) {
      std::size_t end = first;
      while (end < walls.size() && walls[end].first == walls[first].first) ++end;
      for (std::size_t p = first; p < end; ++p)
        for (std::size_t q = p + 1; q < end; ++q) test(walls[p].second, walls[q].second);
      first = end;
    }
  }

  void test(std::uint32_t i, std::uint32_t j) {
    if (only_left_ && covered(i, j)) return;  // walls on one edge are not: check_walls_by_edge
    ++r_.triangle_pairs_tested;
    const MeshTriangle &a = tris_[i], &b = tris_[j];
    if (a.face == b.face || share_edge(a, b) || !overlap(boxes_[i], boxes_[j])) return;
    if (!triangles_intersect(a, b, normals_[i], normals_[j], tol_)) return;
    r_.self_intersection_free = false;
    if (covered(i, j)) r_.proof_contradicted = true;
    ++found_;
    if (!reported_.insert({std::min(a.face, b.face), std::max(a.face, b.face)}).second) return;
    problems_.add("self-intersection", "faces " + std::to_string(std::min(a.face, b.face)) + " and " +
                                           std::to_string(std::max(a.face, b.face)) + " intersect near " +
                                           fmt_point((a.p[0] + a.p[1] + a.p[2]) / 3.0));
  }

  // The pairs through vertex v. Round a large fan, each triangle's corner at v
  // is seen from v as an arc of directions; if all directions lie within one
  // half-space, projecting them onto a plane there (centrally, so arcs stay
  // straight) turns each corner into a segment, and two corners can meet
  // beyond v only where their segments do: only segments whose boxes overlap
  // are tested. A vertex whose directions fill more than a half-space has
  // every pair tested.
  void check_vertex(std::uint32_t v, const std::vector<std::uint32_t>& fan) {
    if (fan.size() < 2) return;
    if (only_left_ && std::none_of(fan.begin(), fan.end(), [&](std::uint32_t t) { return left_[t] == kUpright; }))
      return;
    // The list is in triangle order, so a face's triangles form one run, and
    // pairs start after it: a face fanned from this vertex (a footprint's
    // base split into thousands of triangles) adds no pairs of its own.
    auto all_pairs = [&] {
      std::size_t run_end = 0;
      for (std::size_t p = 0; p < fan.size() && !done(); ++p) {
        if (p == run_end)
          while (run_end < fan.size() && tris_[fan[run_end]].face == tris_[fan[p]].face) ++run_end;
        for (std::size_t q = run_end; q < fan.size() && !done(); ++q) test(fan[p], fan[q]);
      }
    };
    if (fan.size() < kFanSize) return all_pairs();
    std::vector<std::array<glm::dvec3, 2>> arcs(fan.size());
    glm::dvec3 axis{0.0};
    for (std::size_t k = 0; k < fan.size(); ++k) {
      const MeshTriangle& t = tris_[fan[k]];
      const int at = t.v[0] == v ? 0 : t.v[1] == v ? 1 : 2;
      for (int e = 0; e < 2; ++e) {
        arcs[k][e] = glm::normalize(t.p[(at + 1 + e) % 3] - t.p[at]);
        axis += arcs[k][e];
      }
    }
    // Directions nearer than this to the half-space's edge would project far
    // out, where rounding could part segments that meet.
    constexpr double kMinCosine = 0.05;
    if (!(glm::length(axis) > 0.0)) return all_pairs();
    axis = glm::normalize(axis);
    for (const auto& arc : arcs)
      if (glm::dot(arc[0], axis) < kMinCosine || glm::dot(arc[1], axis) < kMinCosine) return all_pairs();
    const glm::dvec3 e1 = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 e2 = glm::cross(axis, e1);
    // Projected points are at most 1 / kMinCosine from the origin; the margin
    // covers the rounding of the projection many times over.
    const double margin = 1e-9 / kMinCosine;
    std::vector<Segment2> corners(fan.size());
    for (std::size_t k = 0; k < fan.size(); ++k) {
      glm::dvec2 ends[2];
      for (int e = 0; e < 2; ++e) {
        const glm::dvec3& d = arcs[k][e];
        ends[e] = glm::dvec2(glm::dot(d, e1), glm::dot(d, e2)) / glm::dot(d, axis);
      }
      corners[k] = {ends[0], ends[1]};
    }
    for_each_near_segment_pair(corners, margin, [&](std::size_t p, std::size_t q) {
      test(fan[p], fan[q]);
      return !done();
    });
  }

  static std::uint32_t shared_vertex(const MeshTriangle& a, const MeshTriangle& b) {
    for (std::uint32_t u : a.v)
      for (std::uint32_t w : b.v)
        if (u == w) return u;
    return kNone;
  }

  Box box_of(const std::vector<std::uint32_t>& order, std::size_t first, std::size_t count) const {
    Box b = boxes_[order[first]];
    for (std::size_t k = first; k < first + count; ++k) {
      b.lo = glm::min(b.lo, boxes_[order[k]].lo);
      b.hi = glm::max(b.hi, boxes_[order[k]].hi);
    }
    return b;
  }

  // Puts the lower half of ids[first, first + count), by centre along the
  // axis where the centres spread most, before the upper half.
  template <class Centre>
  static void split_at_median(std::vector<std::uint32_t>& ids, std::size_t first, std::size_t count, Centre centre) {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    for (std::size_t k = first; k < first + count; ++k) {
      lo = glm::min(lo, centre(ids[k]));
      hi = glm::max(hi, centre(ids[k]));
    }
    const glm::dvec3 span = hi - lo;
    const int axis = span.x >= span.y && span.x >= span.z ? 0 : span.y >= span.z ? 1 : 2;
    const auto begin = ids.begin() + static_cast<std::ptrdiff_t>(first);
    std::nth_element(begin, begin + static_cast<std::ptrdiff_t>(count / 2), begin + static_cast<std::ptrdiff_t>(count),
                     [&](std::uint32_t a, std::uint32_t b) { return centre(a)[axis] < centre(b)[axis]; });
  }

  static double surface(glm::dvec3 e) { return e.x * e.y + e.y * e.z + e.z * e.x; }

  // Splits a range of long thin triangles running diagonally (loose: their
  // boxes along the axes hold more than kLoose times their area) at the
  // median of their centres along the plan direction whose halves have the
  // least surface between them (the surface area heuristic: a box is met by
  // others about in proportion to its surface): the longest axis, or along or
  // across the way their long edges run. A bundle of spikes side by side is
  // then cut across, not along: cut along, each half still spans the bundle,
  // and every pair of its triangles is compared.
  void split_loose(std::size_t first, std::size_t count) {
    const auto begin = order_.begin() + static_cast<std::ptrdiff_t>(first);
    const auto mid = begin + static_cast<std::ptrdiff_t>(count / 2), end = begin + static_cast<std::ptrdiff_t>(count);
    // The long edges' way in the plan: the principal direction of their
    // directions doubled in angle, so that opposite edges add up.
    glm::dvec2 doubled{0.0};
    for (auto it = begin; it != end; ++it) {
      const MeshTriangle& t = tris_[*it];
      glm::dvec3 longest{0.0};
      for (int k = 0; k < 3; ++k) {
        const glm::dvec3 e = t.p[(k + 1) % 3] - t.p[k];
        if (glm::dot(e, e) > glm::dot(longest, longest)) longest = e;
      }
      doubled += glm::dvec2(longest.x * longest.x - longest.y * longest.y, 2.0 * longest.x * longest.y);
    }
    const double angle = 0.5 * std::atan2(doubled.y, doubled.x);
    const glm::dvec2 along{std::cos(angle), std::sin(angle)}, across{-along.y, along.x};
    split_at_median(order_, first, count, [&](std::uint32_t t) { return (boxes_[t].lo + boxes_[t].hi) * 0.5; });
    // A split's cost: each half's surface boxed along the axes or along the
    // long edges, whichever is less (its box along the axes, or its turned
    // one, parts it from others), times its triangles.
    auto cost = [&] {
      double total = 0.0;
      for (const auto& [from, to] : {std::pair{begin, mid}, std::pair{mid, end}}) {
        glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-lo}, rlo{lo}, rhi{hi};
        for (auto it = from; it != to; ++it) {
          lo = glm::min(lo, boxes_[*it].lo);
          hi = glm::max(hi, boxes_[*it].hi);
          for (const glm::dvec3& p : tris_[*it].p) {
            const glm::dvec3 r{along.x * p.x + along.y * p.y, along.x * p.y - along.y * p.x, p.z};
            rlo = glm::min(rlo, r);
            rhi = glm::max(rhi, r);
          }
        }
        total += std::min(surface(hi - lo), surface(rhi - rlo + 2.0 * tol_)) * static_cast<double>(to - from);
      }
      return total;
    };
    double best = cost();
    split_.assign(begin, end);
    for (const glm::dvec2& d : {along, across}) {
      keys_.resize(tris_.size());
      for (auto it = begin; it != end; ++it) {
        const glm::dvec3 c = tris_[*it].p[0] + tris_[*it].p[1] + tris_[*it].p[2];
        keys_[*it] = d.x * c.x + d.y * c.y;
      }
      std::nth_element(begin, mid, end, [&](std::uint32_t a, std::uint32_t b) { return keys_[a] < keys_[b]; });
      const double c = cost();
      if (c < kTurnWorth * best) {
        best = c;
        split_.assign(begin, end);
      }
    }
    std::copy(split_.begin(), split_.end(), begin);
  }

  std::uint32_t build(std::size_t first, std::size_t count, std::uint32_t fan) {
    const std::uint32_t id = static_cast<std::uint32_t>(nodes_.size());
    Fit fit;
    for (std::size_t k = first; k < first + count; ++k) fit = fit + fit_[order_[k]];
    nodes_.push_back({box_of(order_, first, count), static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count),
                      kNone, kNone, fan, fit});
    if (count <= kLeafSize) return id;
    if (loose(nodes_[id]))
      split_loose(first, count);
    else
      split_at_median(order_, first, count, [&](std::uint32_t t) { return (boxes_[t].lo + boxes_[t].hi) * 0.5; });
    const std::uint32_t left = build(first, count / 2, fan);
    const std::uint32_t right = build(first + count / 2, count - count / 2, fan);
    nodes_[id].left = left;
    nodes_[id].right = right;
    return id;
  }

  // Joins subtrees (the fans and the rest) into one tree, by the median of
  // their boxes' centres along the longest axis, so that fans far apart sit in
  // subtrees far apart.
  std::uint32_t join(std::vector<std::uint32_t>& roots, std::size_t first, std::size_t count) {
    if (count == 1) return roots[first];
    split_at_median(roots, first, count, [&](std::uint32_t n) { return (nodes_[n].box.lo + nodes_[n].box.hi) * 0.5; });
    const std::uint32_t left = join(roots, first, count / 2);
    const std::uint32_t right = join(roots, first + count / 2, count - count / 2);
    Node n;
    n.box = {glm::min(nodes_[left].box.lo, nodes_[right].box.lo), glm::max(nodes_[left].box.hi, nodes_[right].box.hi)};
    n.left = left;
    n.right = right;
    n.fit = nodes_[left].fit + nodes_[right].fit;
    nodes_.push_back(n);
    return static_cast<std::uint32_t>(nodes_.size() - 1);
  }

  // Each triangle goes to the largest fan it belongs to, if any is large.
  void build_hierarchy(const std::vector<std::vector<std::uint32_t>>& around) {
    std::vector<std::uint32_t> fan_of(tris_.size(), kNone);
    for (std::uint32_t i = 0; i < tris_.size(); ++i) {
      std::size_t best = kFanSize - 1;
      for (std::uint32_t v : tris_[i].v)
        if (around[v].size() > best) {
          best = around[v].size();
          fan_of[i] = v;
        }
    }
    order_.resize(tris_.size());
    for (std::uint32_t i = 0; i < tris_.size(); ++i) order_[i] = i;
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
      return fan_of[a] != fan_of[b] ? fan_of[a] < fan_of[b] : a < b;
    });
    std::vector<std::uint32_t> roots;
    for (std::size_t first = 0; first < order_.size();) {
      std::size_t end = first;
      while (end < order_.size() && fan_of[order_[end]] == fan_of[order_[first]]) ++end;
      roots.push_back(build(first, end - first, fan_of[order_[first]]));
      first = end;
    }
    root_ = join(roots, 0, roots.size());
  }

  // The triangles, their boxes and normals put in the order the leaves hold
  // them, so that a pair of leaves reads two runs of memory, not triangles
  // scattered over arrays of hundreds of thousands (a 262,144-corner roof's).
  void in_tree_order() {
    std::vector<bool> placed(order_.size(), false);
    for (std::uint32_t start = 0; start < order_.size(); ++start) {
      if (placed[start]) continue;
      // Each triangle k takes the one at order_[k]: round the cycle from start.
      const MeshTriangle tri = tris_[start];
      const Box box = boxes_[start];
      const glm::dvec3 normal = normals_[start];
      const std::uint32_t left = left_.empty() ? kCovered : left_[start];
      std::uint32_t k = start;
      for (; order_[k] != start; k = order_[k]) {
        tris_[k] = tris_[order_[k]];
        boxes_[k] = boxes_[order_[k]];
        normals_[k] = normals_[order_[k]];
        if (!left_.empty()) left_[k] = left_[order_[k]];
        placed[k] = true;
      }
      tris_[k] = tri, boxes_[k] = box, normals_[k] = normal;
      if (!left_.empty()) left_[k] = left;
      placed[k] = true;
    }
    order_ = {};
    fit_ = {};
  }

  // Whether node id holds an upright triangle the proof left to the search
  // (only_left_): the pairs of a subtree without one the proof covers, but
  // those of walls on one edge, which check_walls_by_edge tested.
  char mark_upright(std::uint32_t id) {
    const Node& n = nodes_[id];
    char any = 0;
    if (n.count > 0)
      for (std::uint32_t k = n.first; k < n.first + n.count && !any; ++k) any = left_[k] == kUpright;
    if (!is_leaf(n)) {
      const char l = mark_upright(n.left), r = mark_upright(n.right);
      any = any || l || r;
    }
    return upright_[id] = any;
  }

  bool is_leaf(const Node& n) const { return n.left == kNone; }

  bool loose(const Node& n) const { return turned_ && n.fit.room > kLoose * n.fit.area; }

  // A node's turned box, made when first asked for: most pairs of nodes
  // are parted by their boxes along the axes, and a fan is never compared
  // with itself. A node of the hierarchy over a range of triangles boxes
  // their corners; a node joining subtrees, its children's boxes.
  const OrientedBox& turned(std::uint32_t id) {
    if (turned_boxes_.empty()) turned_boxes_.resize(nodes_.size());
    if (turned_boxes_[id]) return *turned_boxes_[id];
    const Node& n = nodes_[id];
    if (n.count > 0) {
      corners_.clear();
      for (std::size_t k = n.first; k < n.first + n.count; ++k)
        corners_.insert(corners_.end(), tris_[k].p.begin(), tris_[k].p.end());
      turned_boxes_[id] = oriented_box_of(corners_, tol_);
    } else {
      // The children's boxes first: making them reuses corners_.
      const OrientedBox& l = turned(n.left);
      const OrientedBox& r = turned(n.right);
      corners_.clear();
      for (const OrientedBox* b : {&l, &r})
        for (int k = 0; k < 8; ++k)
          corners_.push_back(b->centre + b->axes * (b->half * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1)));
      turned_boxes_[id] = oriented_box_of(corners_, 0.0);
    }
    return *turned_boxes_[id];
  }

  void self_pairs(std::uint32_t id) {
    const Node& n = nodes_[id];
    if (done() || n.fan != kNone) return;  // a fan's pairs were tested round its vertex
    if (only_left_ && !upright_[id]) return;
    if (is_leaf(n)) {
      for (std::uint32_t p = n.first; p < n.first + n.count; ++p)
        for (std::uint32_t q = p + 1; q < n.first + n.count; ++q) test_apart(p, q);
      return;
    }
    const std::uint32_t left = n.left, right = n.right;
    self_pairs(left);
    self_pairs(right);
    cross_pairs(left, right);
  }

  void cross_pairs(std::uint32_t a, std::uint32_t b) {
    const Node &na = nodes_[a], &nb = nodes_[b];
    if (done() || !overlap(na.box, nb.box) || (na.fan != kNone && na.fan == nb.fan) ||
        (only_left_ && !upright_[a] && !upright_[b]) ||
        (loose(na) && loose(nb) && !oriented_overlap(turned(a), turned(b))))
      return;
    if (is_leaf(na) && is_leaf(nb)) {
      for (std::uint32_t p = na.first; p < na.first + na.count; ++p)
        for (std::uint32_t q = nb.first; q < nb.first + nb.count; ++q) test_apart(p, q);
      return;
    }
    const auto size = [](const Node& n) {
      const glm::dvec3 e = n.box.hi - n.box.lo;
      return e.x + e.y + e.z;
    };
    if (is_leaf(nb) || (!is_leaf(na) && size(na) >= size(nb))) {
      const std::uint32_t left = na.left, right = na.right;
      cross_pairs(left, b);
      cross_pairs(right, b);
    } else {
      const std::uint32_t left = nb.left, right = nb.right;
      cross_pairs(a, left);
      cross_pairs(a, right);
    }
  }

  // Pairs that share a vertex were tested round it.
  void test_apart(std::uint32_t i, std::uint32_t j) {
    if (shared_vertex(tris_[i], tris_[j]) == kNone) test(i, j);
  }

  std::vector<MeshTriangle> tris_;  // in tree order once the hierarchy is built (in_tree_order)
  double tol_;
  ValidationReport& r_;
  Problems& problems_;
  std::vector<std::uint32_t> left_;  // by triangle, as tris_
  const bool only_left_;
  std::vector<char> upright_;  // by node, with only_left_ (mark_upright)
  std::vector<Box> boxes_;
  // Made once: a sliver of a spiky plan's roof is in a hundred pairs.
  std::vector<glm::dvec3> normals_;  // by triangle
  std::vector<Fit> fit_;             // by triangle
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> split_;  // scratch of split_loose
  std::vector<double> keys_;          // by triangle, scratch of split_loose
  std::vector<Node> nodes_;
  // With turned_, loose nodes whose boxes along the axes overlap are also
  // compared by their boxes along the principal axes of their triangles:
  // those part long thin triangles side by side, running every way.
  const bool turned_;
  std::vector<std::optional<OrientedBox>> turned_boxes_;  // by node, made by turned()
  std::vector<glm::dvec3> corners_;  // the points a turned box is made of
  std::uint32_t root_ = kNone;
  std::size_t found_ = 0;
  std::set<std::pair<int, int>> reported_;
};

}  // namespace

ValidationOptions roof_validation(const Surface& roof) {
  ValidationOptions options;
  options.relative = mesh_distance_relative(roof.tolerance_relative);
  return options;
}

ValidationReport validate(const Mesh& mesh, const ValidationOptions& options) {
  ValidationReport r;
  {
    Problems problems(r.problems);
    if (mesh.n_faces() == 0) {
      problems.add("closed", "the mesh has no faces");
      return r;
    }
    glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    for (const auto v : mesh.vertices()) {
      lo = glm::min(lo, to_glm(mesh.point(v)));
      hi = glm::max(hi, to_glm(mesh.point(v)));
    }
    const double diagonal = glm::length(hi - lo);
    const double tol = options.tolerance > 0.0 ? options.tolerance
                                               : std::max(options.relative * diagonal,
                                                          std::numeric_limits<double>::min());
    r.tolerance = tol;
    const std::vector<std::uint32_t> welded = weld_positions(mesh);
    check_topology(mesh, welded, r, problems);

    r.volume = signed_volume(mesh);
    if (!(r.volume > 0.0)) {
      r.oriented = false;
      problems.add("oriented", "signed volume " + fmt_number(r.volume) + " is not positive: the faces point inwards");
    }

    r.planar = true;
    std::vector<glm::dvec3> pts;
    for (const auto f : mesh.faces()) {
      pts.clear();
      glm::dvec3 centre{0.0};
      for (const auto v : mesh.fv_range(f)) {
        pts.push_back(to_glm(mesh.point(v)));
        centre += pts.back();
      }
      centre /= static_cast<double>(pts.size());
      const glm::dvec3 normal = newell_normal(pts);
      const double area2 = glm::length(normal);
      if (!(area2 > 0.0)) {
        r.planar = false;
        problems.add("planar", "face " + std::to_string(f.idx()) + " has no area, so no plane");
        continue;
      }
      double error = 0.0;
      for (const auto& p : pts) error = std::max(error, std::abs(glm::dot(normal / area2, p - centre)));
      r.max_planarity_error = std::max(r.max_planarity_error, error);
      if (error > tol) {
        r.planar = false;
        problems.add("planar", "face " + std::to_string(f.idx()) + " is off its plane by " + fmt_number(error) +
                                   " (tolerance " + fmt_number(tol) + ")");
      }
    }

    r.self_intersection_free = true;
    if (options.check_self_intersections) {
      std::size_t slivers = 0;
      std::vector<MeshTriangle> tris = triangulate_faces(mesh, welded, tol, r, problems, slivers);
      std::optional<std::vector<std::uint32_t>> left = proven_apart_over_base(tris, slivers, tol);
      r.proven_apart = left.has_value();
      tris.resize(tris.size() - slivers);
      // Fully proven, nothing is left; with walls, only their pairs are.
      if (!left || options.search_proven_pairs ||
          std::any_of(left->begin(), left->end(), [](std::uint32_t l) { return l != kCovered; }))
        IntersectionSearch(std::move(tris), tol, r, problems, std::move(left).value_or(std::vector<std::uint32_t>{}),
                           !options.search_proven_pairs)
            .run();
    }
  }
  return r;
}

}  // namespace procex

// A feasibility probe, not product code: how fast is a kinetic triangulation
// of the shrinking cross-section (Aichholzer and Aurenhammer 1998; Palfrader,
// Held and Huber 2012, "On computing straight skeletons by means of kinetic
// triangulations") in double arithmetic, and how many flip events does it
// take, on bench/scale_inputs.py's plans? The question behind it: could such a
// triangulation hand procex's sweep its split candidates (issue 18 item 1,
// BENCHMARKS "Splits out of their edge's reach")?
//
// One simple loop, every edge at 45 degrees: each wavefront edge moves inward
// at unit speed, so the height is the offset distance t. The area not yet
// swept is triangulated (CGAL's constrained Delaunay triangulation of the
// plan, interior triangles only); every triangle corner is a wavefront vertex
// moving on a straight line, so a triangle's signed area is a quadratic in t
// and its first root from + to - is when it collapses:
//   - a wavefront side shrinks to nothing: an edge event (a skeleton node);
//   - a vertex reaches the opposite side, a wavefront edge: a split event (a node);
//   - a vertex reaches the opposite side, a spoke: a flip event (no node,
//     the triangulation is repaired by flipping the spoke);
//   - a triangle of three wavefront sides: its loop's last collapse (a node).
// Events come from a heap of collapse times invalidated lazily (a version per
// triangle). A generic simple n-gon has n - 2 nodes.
//
// The same plan is swept by procex::sweep() in the same run (interleaved with
// the probe when --runs > 1), and the probe's node heights are compared with
// the heights of the roof's vertices above the ground, then the nodes with the
// vertices by position (x, y, height); KT_PROBE_SHOW=1 lists on stderr those
// more than 1e-5 m from any of the other's. --perturb moves the probe's plan
// alone by up to EPS, to tell the plan's own conditioning from a disagreement.
//
// Double arithmetic, generic position assumed; degenerate cases are counted
// and reported, not resolved (a comb's teeth, whose sides are antiparallel and
// meet along a segment, leave it stuck, as they stop Surfer2's double build).
//
//   procex_kinetic_triangulation_probe [--runs K] [--no-sweep] [--nodes FILE] [--perturb EPS] PLAN.json...
//
// Prints one block per plan: CPU seconds (CDT, event loop, sweep()), event
// counts, degenerate cases met, peak RSS after the probe's first run (before
// the sweep), and the comparison.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "bench/process_usage.h"
#include "core/geom/cross.h"
#include "core/geom/nesting.h"
#include "core/geom/prepare.h"
#include "core/io/polyjson.h"
#include "core/sweep/sweep.h"

namespace {

using glm::dvec2;

using procex::cross;
using procex::bench::cpu_seconds;
using procex::bench::peak_rss_mb;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------
// The kinetic triangulation.

// A wavefront vertex: at p at time t0, moving at v; between the wavefront
// edges ea (before it, counter-clockwise) and eb (after it).
struct KVertex {
  dvec2 p;
  double t0 = 0.0;
  dvec2 v;
  int ea = -1, eb = -1;
  dvec2 at(double t) const { return p + v * (t - t0); }
};

enum class Kind : std::uint8_t { None, Edge, Split, Flip, Last };

// A counter-clockwise triangle. Side i is the one opposite v[i], from v[i+1]
// to v[i+2]; n[i] is the triangle across it, or -1 where it is (part of) the
// wavefront edge e[i]. Around v[i], the next triangle counter-clockwise is
// n[i+1] and the next clockwise n[i+2].
struct Tri {
  int v[3];
  int n[3];
  int e[3];
  std::uint32_t version = 0;
  bool alive = true;
  // What the scheduled collapse is: for Edge the side that shrinks, for
  // Split and Flip the vertex that reaches the opposite side.
  Kind kind = Kind::None;
  std::uint8_t side = 0;
  bool vertices_meet = false;  // two of its vertices meet there (see classify_flat)
};

struct Event {
  double t;
  int tri;
  std::uint32_t version;
  bool operator>(const Event& o) const { return t > o.t; }
};

struct Node {
  dvec2 p;
  double t;
};

struct Stats {
  double cdt_s = 0.0, events_s = 0.0;
  std::size_t edge = 0, split = 0, flip = 0, last = 0;
  std::size_t pops = 0, stale = 0;        // heap entries popped, of them out of date
  std::size_t rescheduled = 0;            // collapse times worked out
  std::size_t fan_steps = 0;              // triangles re-pointed at new vertices
  // Degenerate cases met (none in generic position):
  std::size_t simultaneous = 0;           // an event at the same time as the one before it
  std::size_t root_in_past = 0;           // a collapse root before now (rounding), taken as now
  std::size_t fast_vertex = 0;            // a vertex made faster than 1e8 (two edges nearly antiparallel;
                                          // exactly antiparallel, as a comb's tooth, it is left standing)
  std::size_t spoke_collapse = 0;         // two vertices met along a spoke (a vertex event)
  std::size_t point_collapse = 0;         // a triangle's three vertices meet at its flat collapse: set aside
  std::size_t split_beside_corner = 0;    // a split whose edge's end is the splitting vertex's neighbour
  std::size_t edge_id_mismatch = 0;       // a wavefront side whose ends do not name its edge
  std::size_t stuck = 0;                  // the loop stopped: too many events without time moving on
  // What moving corners by a clustering distance would cost (see report):
  std::size_t thin_fans[2] = {0, 0};      // events whose new vertex's fan has a triangle thinner than d
  double max_speed = 0.0;
  std::size_t vertices = 0;
  bool finished = false;
};

class KineticTriangulation {
 public:
  // pts: one simple loop, counter-clockwise.
  explicit KineticTriangulation(const std::vector<dvec2>& pts) : pts_(pts) {
    const std::size_t n = pts.size();
    double lo_x = kInf, lo_y = kInf, hi_x = -kInf, hi_y = -kInf;
    for (const dvec2& p : pts) {
      lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    }
    extent_ = std::max(hi_x - lo_x, hi_y - lo_y);
    normal_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const dvec2 d = glm::normalize(pts[(i + 1) % n] - pts[i]);
      normal_[i] = dvec2(-d.y, d.x);  // inward: the interior is on the left
    }
  }

  // CGAL's constrained Delaunay triangulation of the plan; its interior
  // triangles become ours.
  void triangulate() {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
    using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;
    using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
    const int n = static_cast<int>(pts_.size());
    std::vector<std::pair<K::Point_2, int>> in;
    in.reserve(pts_.size());
    for (int i = 0; i < n; ++i) in.emplace_back(K::Point_2(pts_[i].x, pts_[i].y), i);
    Cdt cdt;
    cdt.insert(in.begin(), in.end());
    std::vector<Cdt::Vertex_handle> handle(pts_.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info()] = v;
    for (int i = 0; i < n; ++i) cdt.insert_constraint(handle[i], handle[(i + 1) % n]);
    if (cdt.number_of_vertices() != pts_.size()) throw std::runtime_error("CDT merged vertices");
    // Exterior faces: those reached from the infinite face without crossing
    // the loop; every other finite face is inside (one loop, no holes).
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 0;
    std::vector<Cdt::Face_handle> stack{cdt.infinite_face()};
    cdt.infinite_face()->info() = -1;
    while (!stack.empty()) {
      Cdt::Face_handle f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle g = f->neighbor(i);
        if (g->info() == 0 && !cdt.is_constrained({f, i})) g->info() = -1, stack.push_back(g);
      }
    }
    int inside = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (f->info() == 0) f->info() = inside++;
    tris_.assign(static_cast<std::size_t>(inside), Tri{});
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (f->info() < 0) continue;
      Tri& t = tris_[static_cast<std::size_t>(f->info())];
      for (int i = 0; i < 3; ++i) t.v[i] = f->vertex(i)->info();
      for (int i = 0; i < 3; ++i) {
        const int a = t.v[(i + 1) % 3], b = t.v[(i + 2) % 3];
        if (cdt.is_constrained({f, i})) {
          if ((a + 1) % n != b) throw std::runtime_error("a constrained side against the loop's direction");
          t.n[i] = -1;
          t.e[i] = a;  // edge a runs from pts[a] to pts[a + 1]
        } else {
          t.n[i] = f->neighbor(i)->info();
          t.e[i] = -1;
          if (t.n[i] < 0) throw std::runtime_error("an interior triangle next to an exterior one across a spoke");
        }
      }
    }
    if (tris_.size() != pts_.size() - 2) throw std::runtime_error("the CDT's interior is not n - 2 triangles");
  }

  Stats run() {
    Stats s;
    stats_ = &s;
    const double start = cpu_seconds();
    triangulate();
    const double mid = cpu_seconds();
    s.cdt_s = mid - start;
    const std::size_t n = pts_.size();
    verts_.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      const int ea = static_cast<int>((i + n - 1) % n), eb = static_cast<int>(i);
      verts_.push_back({pts_[i], 0.0, velocity(ea, eb), ea, eb});
    }
    for (std::size_t i = 0; i < tris_.size(); ++i) schedule(static_cast<int>(i));
    std::size_t same_time_run = 0;
    while (!heap_.empty()) {
      const Event ev = heap_.top();
      heap_.pop();
      ++s.pops;
      Tri& t = tris_[static_cast<std::size_t>(ev.tri)];
      if (!t.alive || t.version != ev.version) {
        ++s.stale;
        continue;
      }
      if (ev.t <= now_) {
        ++s.simultaneous;
        // A flip that undoes itself, or a cascade at one point, would spin here.
        if (++same_time_run > 10 * pts_.size() + 1000) {
          ++s.stuck;
          break;
        }
      } else {
        same_time_run = 0;
      }
      now_ = std::max(now_, ev.t);
      switch (t.kind) {
        case Kind::Edge: edge_event(ev.tri, t.side); break;
        case Kind::Split: split_event(ev.tri, t.side); break;
        case Kind::Flip: flip_event(ev.tri, t.side); break;
        case Kind::Last: last_event(ev.tri); break;
        case Kind::None: break;
      }
    }
    s.events_s = cpu_seconds() - mid;
    s.vertices = verts_.size();
    s.finished = s.stuck == 0 && std::none_of(tris_.begin(), tris_.end(), [](const Tri& x) { return x.alive; });
    stats_ = nullptr;
    return s;
  }

  const std::vector<Node>& nodes() const { return nodes_; }

 private:
  // The velocity of a vertex between edges a and b: v . na = v . nb = 1,
  // v = (na + nb) / (1 + na . nb) = 2 (na + nb) / |na + nb|^2; the second form
  // keeps its accuracy where the edges are nearly antiparallel (a spike).
  dvec2 velocity(int a, int b) {
    const dvec2 s = normal_[static_cast<std::size_t>(a)] + normal_[static_cast<std::size_t>(b)];
    const double s2 = glm::dot(s, s);
    const dvec2 v = s2 > 0.0 ? s * (2.0 / s2) : dvec2(0.0);
    const double speed = s2 > 0.0 ? 2.0 / std::sqrt(s2) : kInf;
    if (stats_ != nullptr) {
      stats_->max_speed = std::max(stats_->max_speed, speed);
      if (speed > 1e8) ++stats_->fast_vertex;
    }
    return v;
  }

  int index_of(int tri, int vtx) const {
    const Tri& t = tris_[static_cast<std::size_t>(tri)];
    return t.v[0] == vtx ? 0 : t.v[1] == vtx ? 1 : 2;
  }
  void repoint(int tri, int from, int to) {
    if (tri < 0) return;
    Tri& t = tris_[static_cast<std::size_t>(tri)];
    for (int i = 0; i < 3; ++i)
      if (t.n[i] == from) {
        t.n[i] = to;
        return;
      }
  }
  void make_wavefront(int tri, int from, int edge) {
    Tri& t = tris_[static_cast<std::size_t>(tri)];
    for (int i = 0; i < 3; ++i)
      if (t.n[i] == from) {
        t.n[i] = -1;
        t.e[i] = edge;
        return;
      }
  }

  // The earliest time from now at which the triangle's area reaches zero
  // going down, and what it is there. A side on the wavefront makes the area
  // a product of two linear functions (the side's length along its edge, and
  // the third vertex's distance from the edge's line), whose roots are worked
  // out apart: more accurate than the quadratic, and an edge event is told
  // from a vertex reaching the line by which factor vanishes.
  void schedule(int ti) {
    Tri& t = tris_[static_cast<std::size_t>(ti)];
    ++t.version;
    ++stats_->rescheduled;
    t.kind = Kind::None;
    t.vertices_meet = false;
    dvec2 q[3], w[3];
    for (int i = 0; i < 3; ++i) {
      const KVertex& kv = verts_[static_cast<std::size_t>(t.v[i])];
      q[i] = kv.at(now_);
      w[i] = kv.v;
    }
    double best = kInf;
    int wavefront_sides = 0;
    auto take = [&](double s, Kind kind, int side) {
      if (s < best) best = s, t.kind = kind, t.side = static_cast<std::uint8_t>(side);
    };
    for (int i = 0; i < 3; ++i) {
      if (t.n[i] >= 0) continue;
      ++wavefront_sides;
      const dvec2 nrm = normal_[static_cast<std::size_t>(t.e[i])];
      const dvec2 d(nrm.y, -nrm.x);
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      const double l0 = glm::dot(d, q[b] - q[a]), l1 = glm::dot(d, w[b] - w[a]);
      if (l1 < 0.0) take(-l0 / l1, Kind::Edge, i);
    }
    if (wavefront_sides == 3) {
      if (t.kind == Kind::Edge) t.kind = Kind::Last;
    } else if (wavefront_sides == 1) {
      int i = 0;
      while (t.n[i] >= 0) ++i;
      const dvec2 nrm = normal_[static_cast<std::size_t>(t.e[i])];
      const int a = (i + 1) % 3;
      const double h0 = glm::dot(nrm, q[i] - q[a]), h1 = glm::dot(nrm, w[i] - w[a]);
      if (h1 < 0.0 && -h0 / h1 < best) {
        const Flat f = classify_flat(t, q, w, std::max(-h0 / h1, 0.0));
        if (f.point) {
          ++stats_->point_collapse;  // the wavefront side shrinks there too: its edge event stands
        } else {
          take(-h0 / h1, f.kind, f.vertex);
          t.vertices_meet = f.vertices_meet;
        }
      }
    } else if (wavefront_sides == 0) {
      // 2 A(s) = c + b s + a s^2 around now.
      const dvec2 e1 = q[1] - q[0], e2 = q[2] - q[0], f1 = w[1] - w[0], f2 = w[2] - w[0];
      const double c = cross(e1, e2), b = cross(e1, f2) + cross(f1, e2), a = cross(f1, f2);
      double s = kInf;
      if (a == 0.0) {
        if (b < 0.0) s = -c / b;
      } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc >= 0.0) {
          const double qq = -0.5 * (b + std::copysign(std::sqrt(disc), b));
          double r1 = qq / a, r2 = qq != 0.0 ? c / qq : r1;
          if (r1 > r2) std::swap(r1, r2);
          // Going down through zero: the smaller root of an upward parabola,
          // the larger of a downward one.
          s = a > 0.0 ? r1 : r2;
          if (a > 0.0 && r2 < 0.0) s = kInf;  // both behind: it grows from now on
        }
      }
      if (s < kInf) {
        const Flat f = classify_flat(t, q, w, std::max(s, 0.0));
        if (f.point) {
          ++stats_->point_collapse;  // no flip: edge events will take its vertices
        } else {
          take(s, f.kind, f.vertex);
          t.vertices_meet = f.vertices_meet;
        }
      }
    }
    if (t.kind == Kind::None) return;
    if (best < 0.0) {
      ++stats_->root_in_past;
      best = 0.0;
    }
    heap_.push({now_ + best, ti, t.version});
  }

  // The triangle is flat at now + s: the vertex between the other two (the
  // one opposite the longest side) reaches that side, a split where the side
  // is a wavefront edge, else a flip.
  //
  // Where all three vertices meet (the longest side at the collapse under
  // 1e-7 of the longest now, or under 1e-10 of the plan's extent) it is not
  // a flip or a split but a vertex event: in generic position never, in a
  // regular polygon everywhere (every vertex reaches the centre at once, and
  // a spoke triangle's area has a double root there, which rounding moves by
  // sqrt(ulp)). Such a collapse is set aside (`point`): the edge events of the
  // vertices' wavefront edges, at the same time, take the vertices.
  struct Flat {
    Kind kind;
    int vertex;
    bool vertices_meet;  // the shortest side is nothing: a vertex event, not generic
    bool point;          // all three meet
  };
  Flat classify_flat(const Tri& t, const dvec2* q, const dvec2* w, double s) const {
    dvec2 p[3];
    for (int i = 0; i < 3; ++i) p[i] = q[i] + w[i] * s;
    double shortest = kInf, longest = 0.0, longest_now = 0.0;
    int k = 0;
    for (int i = 0; i < 3; ++i) {
      const dvec2 d = p[(i + 2) % 3] - p[(i + 1) % 3];
      const double len = glm::dot(d, d);
      shortest = std::min(shortest, len);
      if (len > longest) longest = len, k = i;
      const dvec2 dn = q[(i + 2) % 3] - q[(i + 1) % 3];
      longest_now = std::max(longest_now, glm::dot(dn, dn));
    }
    const bool point = longest < 1e-14 * longest_now || longest < 1e-20 * extent_ * extent_;
    return {t.n[k] < 0 ? Kind::Split : Kind::Flip, k, shortest < 1e-24 * longest, point};
  }

  // Triangles of a fan around vertex `from`, starting beside triangle `start`
  // and walking counter-clockwise (ccw) or clockwise, get vertex `to`; their
  // indices go to touched_.
  void walk_fan(int start, int from, int to, bool ccw) {
    int cur = start, k = index_of(start, from);
    for (;;) {
      const int nx = tris_[static_cast<std::size_t>(cur)].n[(k + (ccw ? 1 : 2)) % 3];
      if (nx < 0) return;
      const int kk = index_of(nx, from);
      tris_[static_cast<std::size_t>(nx)].v[kk] = to;
      touched_.push_back(nx);
      ++stats_->fan_steps;
      cur = nx, k = kk;
    }
  }

  // How thin the new vertex's fan is: the nearest opposite side. Where
  // procex's sweep moves a vertex to its cluster's mean point by up to the
  // clustering distance, each fan triangle thinner than that may invert.
  void measure_fan(int vtx) {
    const dvec2 p = verts_[static_cast<std::size_t>(vtx)].at(now_);
    double thinnest = kInf;
    for (int ti : touched_) {
      const Tri& t = tris_[static_cast<std::size_t>(ti)];
      const int k = index_of(ti, vtx);
      if (t.v[k] != vtx) continue;
      const dvec2 a = verts_[static_cast<std::size_t>(t.v[(k + 1) % 3])].at(now_);
      const dvec2 b = verts_[static_cast<std::size_t>(t.v[(k + 2) % 3])].at(now_);
      const double len = glm::length(b - a);
      if (len > 0.0) thinnest = std::min(thinnest, std::abs(cross(b - a, p - a)) / len);
    }
    if (thinnest < 1e-8 * extent_) ++stats_->thin_fans[0];
    if (thinnest < 1e-6 * extent_) ++stats_->thin_fans[1];
  }

  void reschedule_touched() {
    for (int ti : touched_)
      if (tris_[static_cast<std::size_t>(ti)].alive) schedule(ti);
    touched_.clear();
  }

  int new_vertex(dvec2 p, int ea, int eb) {
    verts_.push_back({p, now_, velocity(ea, eb), ea, eb});
    return static_cast<int>(verts_.size() - 1);
  }

  void note_spoke_collapse(const Tri& t) {
    if (t.vertices_meet) ++stats_->spoke_collapse;
  }

  // Side i of triangle ti, the wavefront edge from u to w, has shrunk to a
  // point: u and w become one vertex z between the edges before u and after w.
  void edge_event(int ti, int i) {
    Tri& t = tris_[static_cast<std::size_t>(ti)];
    const int u = t.v[(i + 1) % 3], w = t.v[(i + 2) % 3];
    const int n1 = t.n[(i + 1) % 3];  // across (w, x)
    const int n2 = t.n[(i + 2) % 3];  // across (x, u)
    if (n1 < 0 && n2 < 0) return last_event(ti);
    ++stats_->edge;
    const KVertex ku = verts_[static_cast<std::size_t>(u)];
    const KVertex kw = verts_[static_cast<std::size_t>(w)];
    if (ku.eb != t.e[i] || kw.ea != t.e[i]) ++stats_->edge_id_mismatch;
    const dvec2 p = 0.5 * (ku.at(now_) + kw.at(now_));
    nodes_.push_back({p, now_});
    const int z = new_vertex(p, ku.ea, kw.eb);
    walk_fan(ti, u, z, /*ccw=*/true);   // u's fan runs from this side (u's edge b) ccw to its edge a
    walk_fan(ti, w, z, /*ccw=*/false);  // w's fan ends here (w's edge a)
    if (n1 >= 0 && n2 >= 0) {
      repoint(n1, ti, n2);
      repoint(n2, ti, n1);
    } else if (n1 >= 0) {
      make_wavefront(n1, ti, t.e[(i + 2) % 3]);
    } else {
      make_wavefront(n2, ti, t.e[(i + 1) % 3]);
    }
    t.alive = false;
    measure_fan(z);
    reschedule_touched();
  }

  // Vertex x = v[k] of triangle ti reaches the opposite side, part of the
  // wavefront edge e from u to w: x splits into x1 (its edge a, then e; the
  // fan on w's side) and x2 (e, then its edge b; the fan on u's side).
  void split_event(int ti, int k) {
    Tri& t = tris_[static_cast<std::size_t>(ti)];
    const int x = t.v[k];
    const int n1 = t.n[(k + 1) % 3];  // across (w, x)
    const int n2 = t.n[(k + 2) % 3];  // across (x, u)
    // A side beside x on the wavefront: x reaches e only at its shared end,
    // i.e. that side shrinks at the same time. Taken as that edge event.
    if (n1 < 0) {
      ++stats_->split_beside_corner;
      return edge_event(ti, (k + 1) % 3);
    }
    if (n2 < 0) {
      ++stats_->split_beside_corner;
      return edge_event(ti, (k + 2) % 3);
    }
    note_spoke_collapse(t);
    ++stats_->split;
    const int e = t.e[k];
    const KVertex kx = verts_[static_cast<std::size_t>(x)];
    const dvec2 p = kx.at(now_);
    nodes_.push_back({p, now_});
    const int x1 = new_vertex(p, kx.ea, e);
    const int x2 = new_vertex(p, e, kx.eb);
    walk_fan(ti, x, x1, /*ccw=*/true);
    walk_fan(ti, x, x2, /*ccw=*/false);
    make_wavefront(n1, ti, e);
    make_wavefront(n2, ti, e);
    tris_[static_cast<std::size_t>(ti)].alive = false;
    measure_fan(x1);
    measure_fan(x2);
    reschedule_touched();
  }

  // Vertex x = v[k] of triangle ti reaches the spoke (a, b); across it lies
  // triangle (y, b, a). The quadrilateral x, a, y, b gets the diagonal x-y.
  void flip_event(int ti, int k) {
    ++stats_->flip;
    Tri& t = tris_[static_cast<std::size_t>(ti)];
    note_spoke_collapse(t);
    const int ni = t.n[k];
    Tri& o = tris_[static_cast<std::size_t>(ni)];
    int j = 0;
    while (o.n[j] != ti) ++j;
    const int x = t.v[k], a = t.v[(k + 1) % 3], b = t.v[(k + 2) % 3], y = o.v[j];
    // Sides kept, with what lies across them (a triangle, or -1 and an edge).
    const int ta = t.n[(k + 2) % 3], ta_e = t.e[(k + 2) % 3];  // across (x, a)
    const int tb = t.n[(k + 1) % 3], tb_e = t.e[(k + 1) % 3];  // across (b, x)
    const int na = o.n[(j + 1) % 3], na_e = o.e[(j + 1) % 3];  // across (a, y)
    const int nb = o.n[(j + 2) % 3], nb_e = o.e[(j + 2) % 3];  // across (y, b)
    // t becomes (x, a, y), o becomes (x, y, b).
    t.v[0] = x, t.v[1] = a, t.v[2] = y;
    t.n[0] = na, t.e[0] = na_e;
    t.n[1] = ni, t.e[1] = -1;
    t.n[2] = ta, t.e[2] = ta_e;
    o.v[0] = x, o.v[1] = y, o.v[2] = b;
    o.n[0] = nb, o.e[0] = nb_e;
    o.n[1] = tb, o.e[1] = tb_e;
    o.n[2] = ti, o.e[2] = -1;
    repoint(na, ni, ti);
    repoint(tb, ti, ni);
    schedule(ti);
    schedule(ni);
  }

  // A triangle of three wavefront sides: its loop shrinks to a point.
  void last_event(int ti) {
    ++stats_->last;
    Tri& t = tris_[static_cast<std::size_t>(ti)];
    dvec2 p(0.0);
    for (int i = 0; i < 3; ++i) p += verts_[static_cast<std::size_t>(t.v[i])].at(now_) / 3.0;
    nodes_.push_back({p, now_});
    t.alive = false;
  }

  std::vector<dvec2> pts_;
  double extent_ = 0.0;
  std::vector<dvec2> normal_;  // per wavefront edge (the plan's edges)
  std::vector<KVertex> verts_;
  std::vector<Tri> tris_;
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> heap_;
  std::vector<int> touched_;
  std::vector<Node> nodes_;
  double now_ = 0.0;
  Stats* stats_ = nullptr;
};

// ---------------------------------------------------------------------------
// The driver.

struct SweepRun {
  double cpu_s = 0.0;
  std::vector<double> heights;  // roof vertices above 1e-9, sorted
  std::vector<glm::dvec3> roof;  // the same vertices, sorted by height
  std::string error;
};

SweepRun run_sweep(const procex::Footprint& footprint) {
  SweepRun r;
  const double start = cpu_seconds();
  try {
    const procex::Surface surface = procex::sweep(footprint);
    r.cpu_s = cpu_seconds() - start;
    for (const glm::dvec3& v : surface.vertices)
      if (v.z > 1e-9) r.heights.push_back(v.z), r.roof.push_back(v);
    std::sort(r.heights.begin(), r.heights.end());
    std::sort(r.roof.begin(), r.roof.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return a.z < b.z; });
  } catch (const std::exception& e) {
    r.cpu_s = cpu_seconds() - start;
    r.error = e.what();
  }
  return r;
}

// The largest distance from a value of `a` to the nearest of `b` (both sorted).
double nearest_gap(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (double x : a) {
    const auto it = std::lower_bound(b.begin(), b.end(), x);
    double d = kInf;
    if (it != b.end()) d = std::min(d, *it - x);
    if (it != b.begin()) d = std::min(d, x - *(it - 1));
    worst = std::max(worst, d);
  }
  return worst;
}

// How far each point of `a` is from the nearest of `b` (sorted by height),
// looking only within `window` in height: the largest such distance, and how
// many are farther than each of `limits` (or have none within the window).
struct Match {
  double worst = 0.0;
  std::size_t beyond[3] = {0, 0, 0};
};
constexpr double kMatchLimits[3] = {1e-9, 1e-7, 1e-5};
Match match(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b, double window, const char* label) {
  Match m;
  for (const glm::dvec3& p : a) {
    auto it = std::lower_bound(b.begin(), b.end(), p.z - window,
                               [](const glm::dvec3& q, double z) { return q.z < z; });
    double best = kInf, dz = 0.0;
    for (; it != b.end() && it->z <= p.z + window; ++it)
      if (glm::length(*it - p) < best) best = glm::length(*it - p), dz = it->z - p.z;
    if (best < kInf) m.worst = std::max(m.worst, best);
    if (best > 1e-5 && std::getenv("KT_PROBE_SHOW") != nullptr)
      std::fprintf(stderr, "    unmatched %s %.17g %.17g %.17g nearest %.3g m, %.3g m higher\n", label, p.x, p.y, p.z,
                   best, dz);
    for (int k = 0; k < 3; ++k)
      if (!(best <= kMatchLimits[k])) ++m.beyond[k];
  }
  return m;
}

int run_plan(const char* path, int runs, bool with_sweep, const char* nodes_path, double perturb) {
  const std::vector<procex::PolyShape> shapes = procex::read_polyjson_file(path);
  const procex::Footprint footprint = procex::prepare_footprint(procex::to_footprint(shapes.at(0), 45.0)).footprint;
  if (footprint.loops.size() != 1) {
    std::fprintf(stderr, "%s: %zu loops; the probe takes one\n", path, footprint.loops.size());
    return 1;
  }
  std::vector<dvec2> pts = footprint.loops[0].points;
  if (procex::twice_signed_area(pts) < 0.0) std::reverse(pts.begin(), pts.end());
  // --perturb EPS moves the probe's vertices (not the sweep's) by up to EPS:
  // how much of a difference from procex is the plan's own conditioning.
  if (perturb > 0.0) {
    std::uint64_t state = 0x9e3779b97f4a7c15ull;
    auto uniform = [&state] {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<double>(state >> 11) * 0x1.0p-53 * 2.0 - 1.0;
    };
    for (dvec2& p : pts) p += dvec2(uniform(), uniform()) * perturb;
  }
  const std::size_t n = pts.size();

  Stats kt;
  std::vector<double> kt_cdt, kt_events, sweep_cpu;
  std::vector<Node> nodes;
  SweepRun sw;
  double rss_after_probe = 0.0;
  for (int r = 0; r < runs; ++r) {
    {
      KineticTriangulation probe(pts);
      kt = probe.run();
      kt_cdt.push_back(kt.cdt_s);
      kt_events.push_back(kt.events_s);
      if (r == 0) nodes = probe.nodes();
    }
    if (r == 0) rss_after_probe = peak_rss_mb();
    if (with_sweep) {
      sw = run_sweep(footprint);
      sweep_cpu.push_back(sw.cpu_s);
    }
  }
  auto lo = [](const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); };

  std::printf("plan %s n=%zu\n", path, n);
  std::printf("  probe: cdt %.4f s, events %.4f s (min of %d), peak RSS after the probe %.1f MB, finished %s\n",
              lo(kt_cdt), lo(kt_events), runs, rss_after_probe, kt.finished ? "yes" : "NO");
  std::printf("  events: edge %zu, split %zu, flip %zu (%.3f per vertex), last %zu; nodes %zu (n - 2 = %zu)\n",
              kt.edge, kt.split, kt.flip, static_cast<double>(kt.flip) / static_cast<double>(n), kt.last, nodes.size(),
              n - 2);
  std::printf("  heap: pops %zu, stale %zu, collapses worked out %zu, fan steps %zu, vertices %zu, fastest %.3g\n",
              kt.pops, kt.stale, kt.rescheduled, kt.fan_steps, kt.vertices, kt.max_speed);
  std::printf("  degenerate: simultaneous %zu, root in past %zu, fast vertex %zu, spoke collapse %zu, point collapse set aside %zu, "
              "split beside corner %zu, edge id mismatch %zu, stuck %zu\n",
              kt.simultaneous, kt.root_in_past, kt.fast_vertex, kt.spoke_collapse, kt.point_collapse, kt.split_beside_corner,
              kt.edge_id_mismatch, kt.stuck);
  std::printf("  fans thinner than 1e-8 / 1e-6 of the extent at their vertex's event: %zu / %zu of %zu events\n",
              kt.thin_fans[0], kt.thin_fans[1], kt.edge + kt.split);
  std::vector<double> heights;
  double top = -kInf;
  for (const Node& nd : nodes) heights.push_back(nd.t), top = std::max(top, nd.t);
  std::sort(heights.begin(), heights.end());
  if (with_sweep) {
    if (!sw.error.empty()) {
      std::printf("  sweep: %.4f s, FAILED: %s\n", lo(sweep_cpu), sw.error.c_str());
    } else {
      double paired = 0.0;
      const std::size_t m = std::min(heights.size(), sw.heights.size());
      for (std::size_t i = 0; i < m; ++i) paired = std::max(paired, std::abs(heights[i] - sw.heights[i]));
      std::printf("  sweep: %.4f s (min of %d); nodes above 1e-9: procex %zu, probe %zu\n", lo(sweep_cpu), runs,
                  sw.heights.size(), heights.size());
      std::printf("  heights: paired in order max |diff| %.3g%s; nearest height: probe->procex %.3g, procex->probe %.3g; "
                  "highest probe %.12g procex %.12g (diff %.3g)\n",
                  paired, heights.size() == sw.heights.size() ? "" : " (counts differ: not meaningful)",
                  nearest_gap(heights, sw.heights), nearest_gap(sw.heights, heights), top,
                  sw.heights.empty() ? 0.0 : sw.heights.back(), sw.heights.empty() ? 0.0 : top - sw.heights.back());
      // Nodes matched by position (x, y, height) within 1e-4 m of height.
      std::vector<glm::dvec3> probe3;
      for (const Node& nd : nodes) probe3.emplace_back(nd.p.x, nd.p.y, nd.t);
      std::sort(probe3.begin(), probe3.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return a.z < b.z; });
      const Match pm = match(probe3, sw.roof, 1e-4, "probe"), qm = match(sw.roof, probe3, 1e-4, "procex");
      std::printf("  nodes by position: probe->nearest procex vertex max %.3g m, beyond 1e-9/1e-7/1e-5 m: %zu/%zu/%zu; "
                  "procex->nearest probe node max %.3g m, beyond: %zu/%zu/%zu\n",
                  pm.worst, pm.beyond[0], pm.beyond[1], pm.beyond[2], qm.worst, qm.beyond[0], qm.beyond[1],
                  qm.beyond[2]);
    }
  } else {
    std::printf("  highest node %.12g\n", top);
  }
  int status = kt.finished ? 0 : 2;
  if (nodes_path != nullptr) {
    FILE* f = std::fopen(nodes_path, "w");
    bool written = f != nullptr;
    if (f != nullptr) {
      for (const Node& nd : nodes) std::fprintf(f, "%.17g %.17g %.17g\n", nd.p.x, nd.p.y, nd.t);
      written = std::fclose(f) == 0 && written;
    }
    if (!written) {
      std::fprintf(stderr, "%s: cannot write the nodes to %s: %s\n", path, nodes_path, std::strerror(errno));
      status = 1;
    }
  }
  std::fflush(stdout);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 1;
  bool with_sweep = true;
  const char* nodes_path = nullptr;
  double perturb = 0.0;
  std::vector<const char*> plans;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--perturb" && i + 1 < argc) {
      perturb = std::atof(argv[++i]);
    } else if (a == "--no-sweep") {
      with_sweep = false;
    } else if (a == "--nodes" && i + 1 < argc) {
      nodes_path = argv[++i];
    } else {
      plans.push_back(argv[i]);
    }
  }
  if (plans.empty()) {
    std::fprintf(stderr, "usage: %s [--runs K] [--no-sweep] [--nodes FILE] [--perturb EPS] PLAN.json...\n", argv[0]);
    return 64;
  }
  int status = 0;
  for (const char* p : plans) {
    try {
      status = std::max(status, run_plan(p, runs, with_sweep, nodes_path, perturb));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", p, e.what());
      status = 1;
    }
  }
  return status;
}

#include "tests/support/cgal_skeleton.h"

#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_straight_skeleton_2.h>
#include <gmp.h>

#include "tests/support/sanitizers.h"

#if defined(PROCEX_ASAN)
#include <sanitizer/common_interface_defs.h>
#endif

namespace procex {
namespace {

struct PolygonWithHoles {
  std::vector<glm::dvec2> outer;
  std::vector<std::vector<glm::dvec2>> holes;
};

// A contour edge by its end points, the key from CGAL's contour halfedges back
// to footprint edge ids (CGAL keeps the input points exactly).
using EdgeKey = std::pair<std::pair<double, double>, std::pair<double, double>>;

EdgeKey edge_key(glm::dvec2 a, glm::dvec2 b) {
  std::pair<double, double> p{a.x, a.y}, q{b.x, b.y};
  if (q < p) std::swap(p, q);
  return {p, q};
}

bool point_in_loop(const Loop& loop, glm::dvec2 p) {
  bool inside = false;
  const auto& pts = loop.points;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    if ((pts[i].y > p.y) != (pts[j].y > p.y) &&
        p.x < (pts[j].x - pts[i].x) * (p.y - pts[i].y) / (pts[j].y - pts[i].y) + pts[i].x)
      inside = !inside;
  }
  return inside;
}

// Loop `inner` lies inside loop `outer` when most of its vertices do: loops
// may touch at a vertex (OSM courtyards), which a single vertex or a nudged
// edge midpoint can get wrong when features are 1e-7 apart.
bool loop_inside(const Loop& inner, const Loop& outer) {
  std::size_t inside = 0;
  for (const glm::dvec2& p : inner.points) inside += point_in_loop(outer, p) ? 1 : 0;
  return 2 * inside > inner.points.size();
}

// CGAL is given the footprint moved near the origin and its nodes are moved
// back: far from the origin (x = 1e9) even its exact-construction kernel
// builds a skeleton that differs from the one of the same plan at the origin
// (nodes metres apart where events coincide). The shift is a multiple of a
// power of two at least the footprint's extent, so subtracting it from a
// coordinate is exact and the plan CGAL sees is the plan it was given.
glm::dvec2 exact_origin(const Footprint& fp) {
  glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  for (const Loop& loop : fp.loops)
    for (const glm::dvec2& p : loop.points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(extent > 0.0) || !std::isfinite(extent)) return {0.0, 0.0};
  const double step = std::exp2(std::ceil(std::log2(extent)));
  const glm::dvec2 centre = 0.5 * lo + 0.5 * hi;
  return {std::round(centre.x / step) * step, std::round(centre.y / step) * step};
}

Footprint shifted(Footprint fp, glm::dvec2 origin) {
  for (Loop& loop : fp.loops)
    for (glm::dvec2& p : loop.points) p -= origin;
  return fp;
}

std::vector<PolygonWithHoles> split_by_nesting(const Footprint& fp) {
  const std::size_t n = fp.loops.size();
  std::vector<std::vector<std::size_t>> containers(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && loop_inside(fp.loops[i], fp.loops[j])) containers[i].push_back(j);

  std::vector<PolygonWithHoles> out;
  std::vector<std::size_t> polygon_of(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    if (containers[i].size() % 2 != 0) continue;
    polygon_of[i] = out.size();
    out.push_back({fp.loops[i].points, {}});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t depth = containers[i].size();
    if (depth % 2 == 0) continue;
    const auto parent = std::find_if(containers[i].begin(), containers[i].end(),
                                     [&](std::size_t j) { return containers[j].size() + 1 == depth; });
    if (parent == containers[i].end())
      throw std::runtime_error("cgal_skeleton: loop " + std::to_string(i) + " has no enclosing outer loop");
    out[polygon_of[*parent]].holes.push_back(fp.loops[i].points);
  }
  return out;
}

template <class Kernel>
CGAL::Polygon_2<Kernel> to_cgal(const std::vector<glm::dvec2>& loop) {
  CGAL::Polygon_2<Kernel> poly;
  for (const glm::dvec2& p : loop) poly.push_back(typename Kernel::Point_2(p.x, p.y));
  return poly;
}

template <class Kernel, class Visit>
void for_each_skeleton(const std::vector<PolygonWithHoles>& polygons, Visit&& visit) {
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const auto outer = to_cgal<Kernel>(polygons[i].outer);
    std::vector<CGAL::Polygon_2<Kernel>> holes;
    for (const auto& h : polygons[i].holes) holes.push_back(to_cgal<Kernel>(h));
    const auto ss = CGAL::create_interior_straight_skeleton_2(outer.vertices_begin(), outer.vertices_end(),
                                                              holes.begin(), holes.end(), Kernel());
    if (!ss)
      throw CgalNoSkeleton("CGAL create_interior_straight_skeleton_2 gave no skeleton for polygon " + std::to_string(i) +
                           " (" + std::to_string(outer.size()) + " outer vertices, " + std::to_string(holes.size()) +
                           " holes)");
    visit(*ss);
  }
}

// CGAL 5.5.1 (Debian 12's) can crash in Straight_skeleton_builder_2::
// MergeCoincidentNodes on plans with exactly coincident events (CGAL issue
// 7203, fixed in later releases), and whether it does depends on the heap's
// layout: the same plan passes in one process and crashes in another. The
// skeleton is built in a child process, so a crash is a CgalNoSkeleton the oracle
// weighs, not the end of the test run that met it.
template <class T>
void put_array(std::string& out, const std::vector<T>& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::size_t n = v.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  if (n > 0) out.append(reinterpret_cast<const char*>(v.data()), n * sizeof(T));
}

template <class T>
std::vector<T> get_array(const std::string& in, std::size_t& at) {
  std::size_t n = 0;
  if (in.size() - at < sizeof n) throw std::runtime_error("cgal_skeleton: the child's answer is cut short");
  std::memcpy(&n, in.data() + at, sizeof n);
  at += sizeof n;
  if ((in.size() - at) / sizeof(T) < n) throw std::runtime_error("cgal_skeleton: the child's answer is cut short");
  std::vector<T> v(n);
  if (n > 0) std::memcpy(v.data(), in.data() + at, n * sizeof(T));
  at += n * sizeof(T);
  return v;
}

// The child's exit status when an allocation failed under its memory cap.
constexpr int kOutOfMemoryExit = 4;

[[noreturn]] void out_of_memory() { _exit(kOutOfMemoryExit); }

// The child's exit status when AddressSanitizer caught a memory error: the
// use after free that makes CGAL 5.5.1 crash or loop in a plain build ends a
// sanitized child here, and is CGAL's crash like any other, not ours.
constexpr int kMemoryErrorExit = 5;

void report_memory_errors_as_crashes() {
#if defined(PROCEX_ASAN)
  __sanitizer_set_death_callback([] { _exit(kMemoryErrorExit); });
#endif
}

void* gmp_allocate(std::size_t n) {
  void* p = std::malloc(n);
  if (p == nullptr) out_of_memory();
  return p;
}
void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
  void* q = std::realloc(p, n);
  if (q == nullptr) out_of_memory();
  return q;
}
void gmp_free(void* p, std::size_t) { std::free(p); }

// The child's address space now, from /proc/self/statm (pages); 0 if unread.
std::size_t address_space() {
  std::size_t pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

// Caps the child at `memory` above what it inherits (RLIMIT_AS: the test
// process's own mappings count too). An allocation that fails under the
// cap, by operator new or by GMP (the exact kernel's numbers, which would
// otherwise abort like a crash), ends the child with kOutOfMemoryExit.
// AddressSanitizer reserves terabytes of address space up front and grows
// its shadow as it goes, so RLIMIT_AS cannot cap the child's own allocations
// there (a capped child failed or hung): a sanitized build runs it uncapped.
void cap_memory(std::size_t memory) {
  if (kSanitized) return;
  const rlim_t cap = address_space() + memory;
  const rlimit limit{cap, cap};
  setrlimit(RLIMIT_AS, &limit);
  std::set_new_handler(out_of_memory);
  mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
}

// Caps the child's CPU time: past `seconds` the kernel sends SIGXCPU, which
// ends it (CGAL does not catch it), and SIGKILL a second later in case
// anything does. CPU time, not wall time, so a loaded machine gives the same
// verdicts.
void cap_time(std::size_t seconds) {
  const rlim_t soft = seconds;
  const rlimit limit{soft, soft + 1};
  setrlimit(RLIMIT_CPU, &limit);
}

template <class Build>
CgalSkeleton in_child_process(std::size_t memory, std::size_t seconds, Build build) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("cgal_skeleton: pipe: ") + std::strerror(errno));
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("cgal_skeleton: fork: ") + std::strerror(errno));
  if (pid == 0) {
    // A test run stopped from outside (ctest's timeout, a shell's timeout)
    // must not leave a skeleton building on for minutes in an orphan.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(3);
    close(fds[0]);
    cap_memory(memory);
    cap_time(seconds);
    report_memory_errors_as_crashes();
    std::string answer;
    try {
      const CgalSkeleton s = build();
      answer = "S";
      // Pairs as plain numbers: std::pair is not trivially copyable.
      std::vector<std::array<std::int64_t, 2>> faces;
      for (const auto& [id, n] : s.faces_per_edge) faces.push_back({id, static_cast<std::int64_t>(n)});
      put_array(answer, s.nodes);
      put_array(answer, s.ridges);
      put_array(answer, faces);
    } catch (const CgalNoSkeleton& e) {
      answer = std::string("N") + e.what();
    } catch (const std::exception& e) {
      answer = std::string("E") + e.what();
    }
    for (std::size_t done = 0; done < answer.size();) {
      const ssize_t n = write(fds[1], answer.data() + done, answer.size() - done);
      if (n <= 0 && errno != EINTR) _exit(3);
      if (n > 0) done += static_cast<std::size_t>(n);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string answer;
  char buffer[1 << 16];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemoryExit)
    throw CgalOutOfMemory("CGAL's straight skeleton of this plan needs more than its cap of " +
                          std::to_string(memory >> 20) + " MB (kCgalChildMemory): no oracle for it");
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL))
    throw CgalNoSkeleton("CGAL's straight skeleton of this plan took more than its cap of " + std::to_string(seconds) +
                         " CPU seconds (cgal_child_seconds; CGAL 5.5.1 can loop for ever at events that coincide, "
                         "CGAL issue 7470)");
  if (WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) == kMemoryErrorExit))
    throw CgalNoSkeleton("CGAL's straight skeleton crashed on this plan (" +
                         std::string(WIFSIGNALED(status) ? strsignal(WTERMSIG(status))
                                                         : "AddressSanitizer caught a memory error") +
                         "; CGAL 5.5.1's MergeCoincidentNodes, CGAL issue 7203)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty())
    throw std::runtime_error("cgal_skeleton: the child building the skeleton gave no answer");
  if (answer[0] == 'N') throw CgalNoSkeleton(answer.substr(1));
  if (answer[0] == 'E') throw std::runtime_error(answer.substr(1));
  std::size_t at = 1;
  CgalSkeleton out;
  out.nodes = get_array<glm::dvec3>(answer, at);
  out.ridges = get_array<CgalRidge>(answer, at);
  for (const auto& [id, n] : get_array<std::array<std::int64_t, 2>>(answer, at))
    out.faces_per_edge.emplace_back(static_cast<std::int32_t>(id), static_cast<std::size_t>(n));
  return out;
}

}  // namespace

struct CgalSkeletonInput::Impl {
  glm::dvec2 origin;  // subtracted from the footprint (exact_origin)
  std::vector<PolygonWithHoles> polygons;
  std::map<EdgeKey, std::int32_t> edge_ids;  // by the shifted end points

  template <class Vertex>
  glm::dvec3 node(const Vertex& v) const {
    return {CGAL::to_double(v->point().x()) + origin.x, CGAL::to_double(v->point().y()) + origin.y,
            CGAL::to_double(v->time())};
  }

  template <class Kernel>
  CgalSkeleton skeleton() const;
};

CgalSkeletonInput::CgalSkeletonInput(const Footprint& footprint) : impl_(std::make_unique<Impl>()) {
  impl_->origin = exact_origin(footprint);
  const Footprint local = shifted(footprint, impl_->origin);
  impl_->polygons = split_by_nesting(local);
  for (const Loop& loop : local.loops)
    for (std::size_t i = 0; i < loop.points.size(); ++i)
      impl_->edge_ids[edge_key(loop.points[i], loop.points[(i + 1) % loop.points.size()])] = loop.edges[i].id;
}
CgalSkeletonInput::CgalSkeletonInput(CgalSkeletonInput&&) noexcept = default;
CgalSkeletonInput& CgalSkeletonInput::operator=(CgalSkeletonInput&&) noexcept = default;
CgalSkeletonInput::~CgalSkeletonInput() = default;

std::size_t CgalSkeletonInput::polygon_count() const { return impl_->polygons.size(); }

std::size_t CgalSkeletonInput::skeletonise() const {
  std::size_t vertices = 0;
  for_each_skeleton<CGAL::Exact_predicates_inexact_constructions_kernel>(
      impl_->polygons, [&](const auto& ss) { vertices += ss.size_of_vertices(); });
  return vertices;
}

template <class Kernel>
CgalSkeleton CgalSkeletonInput::Impl::skeleton() const {
  CgalSkeleton out;
  std::map<std::pair<std::int32_t, std::int32_t>, CgalRidge> longest;
  std::map<std::int32_t, std::size_t> faces;
  for (const auto& [key, id] : edge_ids) faces[id] = 0;
  for_each_skeleton<Kernel>(polygons, [&](const auto& ss) {
    for (auto v = ss.vertices_begin(); v != ss.vertices_end(); ++v)
      if (v->is_skeleton()) out.nodes.push_back(node(v));
    // A skeleton face's own halfedge is its contour edge.
    const auto face_edge = [&](const auto& face) {
      const auto h = face->halfedge();
      const auto a = h->vertex()->point(), b = h->opposite()->vertex()->point();
      const auto it = edge_ids.find(
          edge_key({CGAL::to_double(a.x()), CGAL::to_double(a.y())}, {CGAL::to_double(b.x()), CGAL::to_double(b.y())}));
      if (it == edge_ids.end()) throw std::runtime_error("cgal_skeleton: a contour edge is not a footprint edge");
      return it->second;
    };
    for (auto f = ss.faces_begin(); f != ss.faces_end(); ++f) ++faces[face_edge(f)];
    for (auto h = ss.halfedges_begin(); h != ss.halfedges_end(); ++h) {
      if (!h->is_bisector() || h->face() == nullptr || h->opposite()->face() == nullptr) continue;
      const std::int32_t i = face_edge(h->face()), j = face_edge(h->opposite()->face());
      if (i == j) continue;
      const CgalRidge r{std::min(i, j), std::max(i, j), node(h->opposite()->vertex()), node(h->vertex())};
      const auto [it, added] = longest.try_emplace({r.a, r.b}, r);
      if (!added && glm::distance(r.from, r.to) > glm::distance(it->second.from, it->second.to)) it->second = r;
    }
  });
  for (const auto& [pair, r] : longest) out.ridges.push_back(r);
  out.faces_per_edge.assign(faces.begin(), faces.end());
  return out;
}

std::size_t cgal_child_seconds(std::size_t vertices) {
  const std::size_t hundreds = vertices / 100;
  return (60 + hundreds * hundreds) * (kSanitized ? 20 : 1);
}

CgalSkeleton CgalSkeletonInput::skeleton(CgalConstructions constructions, std::size_t memory,
                                         std::optional<std::size_t> seconds) const {
  std::size_t vertices = 0;
  for (const PolygonWithHoles& p : impl_->polygons) {
    vertices += p.outer.size();
    for (const auto& hole : p.holes) vertices += hole.size();
  }
  return in_child_process(memory, seconds.value_or(cgal_child_seconds(vertices)), [&] {
    return constructions == CgalConstructions::Exact
               ? impl_->skeleton<CGAL::Exact_predicates_exact_constructions_kernel>()
               : impl_->skeleton<CGAL::Exact_predicates_inexact_constructions_kernel>();
  });
}

std::vector<std::pair<std::int32_t, std::int32_t>> ridges_longer_than(const CgalSkeleton& skeleton, double length,
                                                                      double rise) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  const glm::dvec3 scale(1.0, 1.0, rise);
  for (const CgalRidge& r : skeleton.ridges)
    if (glm::distance(r.from * scale, r.to * scale) > length) out.emplace_back(r.a, r.b);
  return out;
}

}  // namespace procex

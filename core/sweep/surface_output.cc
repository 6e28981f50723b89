#include "core/sweep/surface_output.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/geom/error.h"

namespace procex::engine {
namespace {

struct FaceFrame {
  glm::dvec3 u, w;  // in-plane axes; (u, w, outward) is right-handed
  glm::dvec2 to2d(glm::dvec3 p) const { return {glm::dot(p, u), glm::dot(p, w)}; }
};

FaceFrame frame_of(const FaceGroup& f) {
  const glm::dvec3 n = f.outward;
  const glm::dvec3 helper = std::abs(n.z) < 0.9 ? glm::dvec3{0, 0, 1} : glm::dvec3{1, 0, 0};
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
  return {u, glm::cross(n, u)};
}

double signed_area(const std::vector<glm::dvec2>& pts) {
  double a = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) a += cross(pts[i], pts[(i + 1) % pts.size()]);
  return 0.5 * a;
}

bool inside(const std::vector<glm::dvec2>& poly, glm::dvec2 q) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y > q.y) != (poly[j].y > q.y) &&
        q.x < (poly[j].x - poly[i].x) * (q.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  }
  return in;
}

[[noreturn]] void open_face(const FaceGroup& f, std::uint32_t v, const glm::dvec3& p) {
  std::ostringstream msg;
  msg << "sweep: the boundary of " << (f.kind == FaceKind::Side ? "the face of edge " : "a horizontal face ")
      << (f.kind == FaceKind::Side ? std::to_string(f.source_edge) : std::string())
      << " does not close at vertex " << v << " (" << p.x << ", " << p.y << ", " << p.z << ")";
  throw SweepError(msg.str(), p.z, {f.source_edge});
}

// A chained loop that passes a vertex twice (two parts of a face touching
// there, the sharpest turn leading into the other part) is two loops.
void split_at_repeats(std::vector<std::uint32_t> loop, std::vector<std::vector<std::uint32_t>>& out) {
  std::map<std::uint32_t, std::size_t> seen;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto [it, fresh] = seen.try_emplace(loop[i], i);
    if (fresh) continue;
    const auto first = loop.begin() + static_cast<std::ptrdiff_t>(it->second);
    const auto again = loop.begin() + static_cast<std::ptrdiff_t>(i);
    split_at_repeats({first, again}, out);
    loop.erase(first, again);
    return split_at_repeats(std::move(loop), out);
  }
  out.push_back(std::move(loop));
}

// Chains a face's half-edges into closed loops. Where the face touches itself
// at a vertex, the loop takes the sharpest turn, so each loop stays simple.
std::vector<std::vector<std::uint32_t>> chain_loops(const State& st, const FaceGroup& f) {
  // Opposite half-edges inside one face are a zero-width seam: drop both.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const HalfEdge& h : f.half_edges)
    if (h.from != h.to) ++count[{h.from, h.to}];
  std::vector<HalfEdge> hs;
  for (auto& [key, n] : count) {
    auto back = count.find({key.second, key.first});
    const int cancel = back == count.end() ? 0 : std::min(n, back->second);
    for (int i = cancel; i < n; ++i) hs.push_back({key.first, key.second});
  }
  if (hs.empty()) return {};
  const FaceFrame fr = frame_of(f);
  auto pos = [&](std::uint32_t v) { return fr.to2d(st.vertices[v]); };
  std::multimap<std::uint32_t, int> out;
  for (int i = 0; i < static_cast<int>(hs.size()); ++i) out.emplace(hs[i].from, i);
  std::vector<char> used(hs.size(), 0);
  std::vector<std::vector<std::uint32_t>> loops;
  for (int start = 0; start < static_cast<int>(hs.size()); ++start) {
    if (used[start]) continue;
    std::vector<std::uint32_t> loop;
    int h = start;
    while (true) {
      used[h] = 1;
      loop.push_back(hs[h].from);
      const std::uint32_t v = hs[h].to;
      const glm::dvec2 back = pos(hs[h].from) - pos(v);
      const double back_angle = std::atan2(back.y, back.x);
      int best = -1;
      double best_turn = 1e300;
      auto [lo, hi] = out.equal_range(v);
      for (auto it = lo; it != hi; ++it) {
        if (used[it->second] && it->second != start) continue;
        const glm::dvec2 d = pos(hs[it->second].to) - pos(v);
        // Clockwise angle from the way we came back to the candidate.
        double turn = back_angle - std::atan2(d.y, d.x);
        while (turn <= 0.0) turn += 2.0 * M_PI;
        while (turn > 2.0 * M_PI) turn -= 2.0 * M_PI;
        if (turn < best_turn) {
          best_turn = turn;
          best = it->second;
        }
      }
      if (best < 0) open_face(f, v, st.vertices[v]);
      if (best == start) break;
      h = best;
    }
    split_at_repeats(std::move(loop), loops);
  }
  return loops;
}

}  // namespace

Surface build_surface(const State& st) {
  Surface s;
  for (const FaceGroup& f : st.faces) {
    const FaceFrame fr = frame_of(f);
    std::vector<std::vector<std::uint32_t>> outers, holes;
    std::vector<std::vector<glm::dvec2>> outer_pts;
    std::vector<double> outer_area;
    for (auto& loop : chain_loops(st, f)) {
      if (loop.size() < 3) continue;
      std::vector<glm::dvec2> pts;
      for (auto v : loop) pts.push_back(fr.to2d(st.vertices[v]));
      const double a = signed_area(pts);
      if (a > 0.0) {
        outers.push_back(std::move(loop));
        outer_pts.push_back(std::move(pts));
        outer_area.push_back(a);
      } else {
        holes.push_back(std::move(loop));
      }
    }
    std::vector<SurfaceFace> made(outers.size());
    for (std::size_t i = 0; i < outers.size(); ++i) made[i] = {f.kind, f.source_edge, {outers[i]}, f.tag};
    for (auto& hole : holes) {
      // A hole belongs to the smallest outer loop around it.
      int best = -1;
      const glm::dvec2 q = fr.to2d(st.vertices[hole[0]]);
      for (std::size_t i = 0; i < outers.size(); ++i)
        if (inside(outer_pts[i], q) && (best < 0 || outer_area[i] < outer_area[best])) best = static_cast<int>(i);
      if (best < 0) {
        // A clockwise loop with nothing around it: a sliver of no area.
        continue;
      }
      made[best].loops.push_back(std::move(hole));
    }
    for (auto& m : made) s.faces.push_back(std::move(m));
  }
  // Vertices no face uses (a plan edit's sliver absorbed by the face it grew
  // into, loops of no area) are left out, the rest keep their order.
  constexpr std::uint32_t kUnused = UINT32_MAX;
  std::vector<std::uint32_t> index(st.vertices.size(), kUnused);
  for (const SurfaceFace& f : s.faces)
    for (const auto& loop : f.loops)
      for (std::uint32_t v : loop) index[v] = 0;
  s.vertices.clear();
  for (std::size_t v = 0; v < index.size(); ++v)
    if (index[v] != kUnused) {
      index[v] = static_cast<std::uint32_t>(s.vertices.size());
      s.vertices.push_back(st.vertices[v]);
    }
  for (SurfaceFace& f : s.faces)
    for (auto& loop : f.loops)
      for (std::uint32_t& v : loop) v = index[v];
  return s;
}

void check_closed(const Surface& surface) {
  auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; };
  auto at = [&](std::uint32_t v) {
    const glm::dvec3 p = surface.vertices[v];
    std::ostringstream out;
    out << "vertex " << v << " (" << p.x << ", " << p.y << ", " << p.z << ")";
    return out.str();
  };
  auto fail = [&](std::uint32_t v, const std::string& what) {
    throw SweepError("sweep: the surface is not closed at " + at(v) + ": " + what, surface.vertices[v].z, {});
  };
  // Each half-edge v -> a, with the vertex before v in its loop.
  std::unordered_map<std::uint64_t, std::uint32_t> before;
  std::unordered_map<std::uint32_t, int> leaving;  // vertex -> half-edges leaving it
  for (const SurfaceFace& f : surface.faces)
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const std::uint32_t v = loop[i], a = loop[(i + 1) % loop.size()];
        if (!before.try_emplace(key(v, a), loop[(i + loop.size() - 1) % loop.size()]).second)
          fail(v, "two faces run the same way along its edge to " + at(a));
        ++leaving[v];
      }
  for (const auto& [k, b] : before)
    if (!before.count(key(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k >> 32))))
      fail(static_cast<std::uint32_t>(k >> 32),
           "no face runs back along its edge to " + at(static_cast<std::uint32_t>(k)));
  // Round a vertex, the faces must form one fan: from v -> a, the face on
  // its right holds v -> b, where b comes before v in the loop of v -> a.
  std::unordered_map<std::uint32_t, char> walked;
  for (const auto& [k, b0] : before) {
    const auto v = static_cast<std::uint32_t>(k >> 32);
    if (!walked.try_emplace(v, 1).second) continue;
    int fan = 0;
    std::uint32_t a = static_cast<std::uint32_t>(k);
    do {
      ++fan;
      a = before.at(key(v, a));
    } while (a != static_cast<std::uint32_t>(k) && fan <= leaving[v]);
    if (fan != leaving[v]) fail(v, "the faces round it form more than one fan");
  }
}

}  // namespace procex::engine

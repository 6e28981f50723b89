#include "core/sweep/sweep_state.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace procex::engine {

int State::add_edge(glm::dvec2 point, double z0, glm::dvec2 dir, double k, std::int32_t source_id) {
  Edge e;
  e.plane = Plane::through(point, z0, dir, k);
  e.dir = dir;
  e.source_id = source_id;
  e.face = static_cast<int>(faces.size());
  FaceGroup f;
  f.kind = FaceKind::Side;
  f.source_edge = source_id;
  // The face's gradient (n, -k) points inward and down; outward is its opposite.
  f.outward = glm::normalize(glm::dvec3{-e.plane.n.x, -e.plane.n.y, k});
  f.origin = glm::dvec3{point, z0};
  faces.push_back(std::move(f));
  if (k < 0.0) any_outward = true;
  edges.push_back(std::move(e));
  return static_cast<int>(edges.size()) - 1;
}

int State::add_corner(int prev_edge, int next_edge, std::uint32_t origin) {
  Corner c;
  c.prev_edge = prev_edge;
  c.next_edge = next_edge;
  c.origin = origin;
  const Edge& a = edges[prev_edge];
  const Edge& b = edges[next_edge];
  // Parallel, same direction, same plane: the corner slides perpendicular to them.
  if (std::abs(cross(a.dir, b.dir)) < Tolerances::parallel_sin && glm::dot(a.dir, b.dir) > 0.0 &&
      std::abs(a.plane.k - b.plane.k) <= Tolerances::same_slope * (1.0 + std::abs(a.plane.k))) {
    c.guide = Plane::vertical(glm::dvec2(vertices[origin]), a.dir);
  }
  const int id = static_cast<int>(corners.size());
  corners.push_back(c);
  edges[next_edge].spans.push_back(id);
  return id;
}

std::uint32_t State::add_vertex(glm::dvec3 p) {
  vertices.push_back(p);
  return static_cast<std::uint32_t>(vertices.size() - 1);
}

glm::dvec2 State::position(int c, double z) const {
  if (auto p = meet2(plane_before(c), edges[corners[c].next_edge].plane, z, Tolerances::parallel_sin)) return *p;
  // Anti-parallel edges (a ridge or a spike): the corner does not move in the
  // plan any more; it only exists at the height it was made.
  return glm::dvec2(vertices[corners[c].origin]);
}

bool State::reflex(int c) const {
  const Corner& k = corners[c];
  return cross(edges[k.prev_edge].dir, edges[k.next_edge].dir) <= Tolerances::parallel_sin;
}

void State::emit_trajectory(int c, std::uint32_t v) {
  const Corner& k = corners[c];
  if (v == k.origin) return;
  // Seen from outside, the face of prev_edge has this corner on its right side
  // (going up), the face of next_edge has it on its left side (going down).
  faces[edges[k.prev_edge].face].half_edges.push_back({k.origin, v});
  faces[edges[k.next_edge].face].half_edges.push_back({v, k.origin});
}

void State::emit_top(int e, std::uint32_t vs, std::uint32_t vt) {
  if (vs == vt) return;
  faces[edges[e].face].half_edges.push_back({vt, vs});
}

std::uint32_t State::vertex_now(int c) {
  const Corner& k = corners[c];
  const glm::dvec3& o = vertices[k.origin];
  if (std::abs(o.z - height) <= tol_.height()) return k.origin;
  const std::uint32_t v = add_vertex({position(c, height), height});
  emit_trajectory(c, v);
  return v;
}

const std::vector<int>& State::spans(int e) {
  auto& s = edges[e].spans;
  s.erase(std::remove_if(s.begin(), s.end(),
                         [&](int c) { return !corners[c].alive || corners[c].next_edge != e; }),
          s.end());
  return s;
}

}  // namespace procex::engine

// Property checks on a sweep Surface, independent of OpenMesh: every directed
// boundary edge meets its reverse exactly once (closed and consistently
// oriented), every face is planar, and the enclosed volume by the divergence
// theorem. Used to test the engine on its own terms. Positions are taken
// relative to the surface's first vertex: far from the origin (a building at
// (5e5, 5e6)) cross products of raw coordinates cancel to millimetres.
#pragma once

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "core/mesh/surface.h"

namespace procex::testing {

struct SurfaceCheck {
  bool closed = true;
  bool planar = true;
  double volume = 0.0;
  double max_height = 0.0;
  std::string problem;
};

inline SurfaceCheck check_surface(const Surface& s, double tolerance) {
  SurfaceCheck r;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  const glm::dvec3 origin = s.vertices.empty() ? glm::dvec3{0.0} : s.vertices.front();
  auto at = [&](std::uint32_t v) { return s.vertices[v] - origin; };
  for (std::size_t fi = 0; fi < s.faces.size(); ++fi) {
    const auto& f = s.faces[fi];
    glm::dvec3 normal{0.0}, centroid{0.0};
    std::size_t count = 0;
    for (const auto& loop : f.loops) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3 a = at(loop[i]), b = at(loop[(i + 1) % loop.size()]);
        normal += glm::cross(a, b);
        centroid += a;
        ++count;
        ++directed[{loop[i], loop[(i + 1) % loop.size()]}];
        // Tetrahedra (origin, loop[0], a, b): positive for outward-facing faces.
        r.volume += glm::dot(a, glm::cross(b, at(loop[0]))) / 6.0;
        r.max_height = std::max(r.max_height, s.vertices[loop[i]].z);
      }
    }
    centroid /= static_cast<double>(count);
    const double len = glm::length(normal);
    if (len == 0.0) {
      r.planar = false;
      r.problem += "face " + std::to_string(fi) + " has no area; ";
      continue;
    }
    normal /= len;
    for (const auto& loop : f.loops)
      for (auto v : loop)
        if (std::abs(glm::dot(at(v) - centroid, normal)) > tolerance) {
          r.planar = false;
          r.problem += "face " + std::to_string(fi) + " (edge " + std::to_string(f.source_edge) + ") not planar; ";
          break;
        }
  }
  for (const auto& [key, n] : directed) {
    auto back = directed.find({key.second, key.first});
    if (n != 1 || back == directed.end() || back->second != 1) {
      r.closed = false;
      std::ostringstream msg;
      msg << "edge " << key.first << "->" << key.second << " used " << n << "x, reverse "
          << (back == directed.end() ? 0 : back->second) << "x; ";
      if (r.problem.size() < 2000) r.problem += msg.str();
    }
  }
  return r;
}

}  // namespace procex::testing

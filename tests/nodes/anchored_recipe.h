// What the anchored-recipe tests share: a sample recipe loaded into a graph
// to edit and evaluate, footprint edges as walls, and where a placed mesh
// lies in a wall's coordinates.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/values.h"

namespace procex::test {

namespace fs = std::filesystem;

inline const fs::path kSamples = PROCEX_SAMPLES;

// One footprint edge as a wall: from a to b, outward normal n (CCW loops).
struct Wall {
  glm::dvec2 a, b;
  double length() const { return glm::distance(a, b); }
  glm::dvec2 dir() const { return (b - a) / length(); }
  glm::dvec2 normal() const { return {dir().y, -dir().x}; }
};

inline std::vector<Wall> walls_of(const std::vector<Vec2>& points) {
  std::vector<Wall> out;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec2 p = points[k], q = points[(k + 1) % points.size()];
    out.push_back({{p.x, p.y}, {q.x, q.y}});
  }
  return out;
}

// Where an instance's mesh lies in the wall's coordinates: along the edge
// from its start, out of the wall plane, and height.
struct Extent {
  double along_lo = 1e300, along_hi = -1e300, out_lo = 1e300, out_hi = -1e300, z_lo = 1e300, z_hi = -1e300;
};

inline Extent extent_on(const Wall& w, const PlacementResult& placed, const Instance& in) {
  Extent e;
  const Mesh& m = *placed.meshes.at(in.mesh).mesh;
  for (const auto v : m.vertices()) {
    const auto p = m.point(v);
    const glm::dvec4 q = in.transform * glm::dvec4(p[0], p[1], p[2], 1.0);
    const double along = glm::dot(glm::dvec2(q) - w.a, w.dir()), out = glm::dot(glm::dvec2(q) - w.a, w.normal());
    e.along_lo = std::min(e.along_lo, along), e.along_hi = std::max(e.along_hi, along);
    e.out_lo = std::min(e.out_lo, out), e.out_hi = std::max(e.out_hi, out);
    e.z_lo = std::min(e.z_lo, q.z), e.z_hi = std::max(e.z_hi, q.z);
  }
  return e;
}

struct Recipe {
  Graph g;
  ResultCache cache{256 << 20};
  Evaluator ev{cache, "anchored recipes test"};

  explicit Recipe(const std::string& name) : g(load_pxg(kSamples / (name + ".pxg"))) {}

  NodeId node(const std::string& type, const std::string& param = {}, const std::string& value = {}) const {
    for (const auto& [id, n] : g.nodes())
      if (n.type && n.decl().type_name() == type &&
          (param.empty() || n.params[*n.decl().param_index(param)].get<std::string>() == value))
        return id;
    ADD_FAILURE() << "no " << type << " node";
    return 0;
  }
  template <class T>
  void set(NodeId id, const std::string& param, T v) {
    ASSERT_TRUE(g.set_param(id, param, Value::make(std::move(v))));
  }
  const std::vector<Vec2>& plan() const {
    const Node& n = *g.node(node("Footprint Polygon"));
    return n.params[*n.decl().param_index("points")].get<std::vector<Vec2>>();
  }
  EvalResult run() { return ev.evaluate(g, {}, {"mesh"}, options()); }
  // The value on output `port` of node `id` (from the cache after run()).
  Value port(NodeId id, std::uint32_t port) {
    const PortRef ref{id, port};
    const EvalResult r = ev.evaluate_ports(g, {}, std::span<const PortRef>(&ref, 1), options());
    EXPECT_TRUE(r.ok());
    return r.outputs.at(0).value;
  }
  static EvalOptions options() {
    EvalOptions o;
    o.folder = kSamples;
    return o;
  }
};

inline std::string messages(const EvalResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += d.to_string() + "\n";
  return out;
}

inline const TaggedMesh& building(const EvalResult& r) {
  EXPECT_TRUE(r.ok()) << messages(r);
  return r.output("mesh")->get<MeshSet>().parts.at(0);
}

}  // namespace procex::test

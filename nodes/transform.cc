// Transform: scales, turns about the vertical and moves meshes.
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t translate, rotate, scale;
};
Params par;

bool is_identity(const std::vector<Value>& params) {
  const Vec3& t = params[par.translate].get<Vec3>();
  return t == Vec3{} && params[par.rotate].get<double>() == 0.0 && params[par.scale].get<double>() == 1.0;
}

std::optional<std::size_t> pass(const std::vector<Value>& params, std::size_t) {
  return is_identity(params) ? std::optional<std::size_t>(0) : std::nullopt;
}

void declare(NodeDecl& d) {
  d.doc("Scales every mesh uniformly about the origin, turns it about the vertical axis, then moves it, with "
        "the meshes placed on it and its resolved anchors. The identity hands the input on untouched.")
      .category("Geometry");
  d.input<MeshSet>("mesh");
  par.translate = d.param<Vec3>("translate").default_value(Vec3{}).unit("m").doc("x, y, z offset").index();
  par.rotate = d.param<double>("rotate").default_value(0.0).range(-360, 360).unit("deg").doc("counter-clockwise about +z").index();
  par.scale = d.param<double>("scale").default_value(1.0).range(0.001, 1000).doc("uniform scale factor").index();
  d.output<MeshSet>("mesh");
  d.pass_through(pass);
}

void evaluate(EvalContext& ctx) {
  const Vec3& t = ctx.param<Vec3>(par.translate);
  const double a = ctx.param<double>(par.rotate) * M_PI / 180.0, s = ctx.param<double>(par.scale);
  // Column-major: x' = c x - n y + t.x, y' = n x + c y + t.y, z' = s z + t.z.
  const double c = std::cos(a) * s, n = std::sin(a) * s;
  const glm::dmat4 m(c, n, 0, 0, -n, c, 0, 0, 0, 0, s, 0, t.x, t.y, t.z, 1);
  const auto point = [&](const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); };
  // Directions turn only (the scale is uniform and positive).
  const auto turn = [&](const glm::dvec3& d) { return glm::dvec3(m * glm::dvec4(d, 0.0)) / s; };
  MeshSet out = ctx.input<MeshSet>(0);
  for (TaggedMesh& part : out.parts) {
    auto mesh = std::make_shared<Mesh>(*part.mesh);
    for (const auto v : mesh->vertices()) {
      Mesh::Point& p = mesh->point(v);
      const glm::dvec3 q = point({p[0], p[1], p[2]});
      p = Mesh::Point(q.x, q.y, q.z);
    }
    part.mesh = std::move(mesh);
    for (Instance& in : part.placed.instances) in.transform = m * in.transform;
    for (ResolvedAnchor& r : part.anchors) {
      r.frame.origin = point(r.frame.origin);
      r.frame.along = turn(r.frame.along), r.frame.up = turn(r.frame.up), r.frame.normal = turn(r.frame.normal);
      r.span_from = point(r.span_from), r.span_to = point(r.span_to);
    }
    if (part.tiles) {  // moved tiles are new ones: the input's are shared
      std::vector<FacadeTile> tiles = *part.tiles;
      for (FacadeTile& t : tiles) {  // sizes scale with the mesh
        t.frame.origin = point(t.frame.origin);
        t.frame.along = turn(t.frame.along), t.frame.up = turn(t.frame.up), t.frame.normal = turn(t.frame.normal);
        t.width *= s, t.height *= s;
      }
      part.tiles = std::make_shared<const std::vector<FacadeTile>>(std::move(tiles));
    }
  }
  ctx.set_output(0, std::move(out));
}

}  // namespace
PROCEX_REGISTER_NODE("Transform", 1, declare, evaluate);
}  // namespace procex

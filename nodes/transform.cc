// Transform: scales, turns about the vertical and moves meshes.
#include <cmath>

#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

bool is_identity(const std::vector<Value>& params) {
  const Vec3& t = params[0].get<Vec3>();
  return t == Vec3{} && params[1].get<double>() == 0.0 && params[2].get<double>() == 1.0;
}

std::optional<std::size_t> pass(const std::vector<Value>& params, std::size_t) {
  return is_identity(params) ? std::optional<std::size_t>(0) : std::nullopt;
}

void declare(NodeDecl& d) {
  d.doc("Scales every mesh uniformly about the origin, turns it about the vertical axis, then moves it. "
        "The identity hands the input on untouched.")
      .category("Geometry");
  d.input<MeshSet>("mesh");
  d.param<Vec3>("translate").default_value(Vec3{}).unit("m").doc("x, y, z offset");
  d.param<double>("rotate").default_value(0.0).range(-360, 360).unit("deg").doc("counter-clockwise about +z");
  d.param<double>("scale").default_value(1.0).range(0.001, 1000).doc("uniform scale factor");
  d.output<MeshSet>("mesh");
  d.pass_through(pass);
}

void evaluate(EvalContext& ctx) {
  const Vec3& t = ctx.param<Vec3>(0);
  const double a = ctx.param<double>(1) * M_PI / 180.0, s = ctx.param<double>(2);
  const double c = std::cos(a) * s, n = std::sin(a) * s;
  MeshSet out = ctx.input<MeshSet>(0);
  for (TaggedMesh& part : out.parts) {
    auto mesh = std::make_shared<Mesh>(*part.mesh);
    for (const auto v : mesh->vertices()) {
      Mesh::Point& p = mesh->point(v);
      p = Mesh::Point(c * p[0] - n * p[1] + t.x, n * p[0] + c * p[1] + t.y, s * p[2] + t.z);
    }
    part.mesh = std::move(mesh);
  }
  ctx.set_output(0, std::move(out));
}

}  // namespace
PROCEX_REGISTER_NODE("Transform", 1, declare, evaluate);
}  // namespace procex

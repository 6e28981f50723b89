// The recipes of issue 15: the barn's five sizes typed once and its roof run
// past its flush walls, the cottage's hipped L run out all round and over its valley, and the
// set-back tower's windows only where its walls are, checked against the faces.
#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "core/mesh/validate.h"
#include "core/placement/face_cover.h"
#include "graph/pxg.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
const fs::path kSamples = PROCEX_SAMPLES;

const MeshSet& mesh_of(const EvalResult& r) {
  const Value* v = r.output("mesh");
  if (!v) throw std::runtime_error("no mesh: " + (r.diagnostics.empty() ? std::string() : r.diagnostics[0].to_string()));
  return v->get<MeshSet>();
}

double top_of(const Mesh& m) {
  double top = -HUGE_VAL;
  for (auto v : m.vertices()) top = std::max(top, m.point(v)[2]);
  return top;
}

TEST(BarnSample, EachSizeTypedOnceFollowsEverywhere) {
  Graph g = load_pxg(kSamples / "barn.pxg");
  const MeshSet a = mesh_of(test::evaluate_mesh(g, kSamples));
  ASSERT_EQ(a.parts.size(), 2u);  // the barn, then its roof slab
  for (const TaggedMesh& part : a.parts) EXPECT_TRUE(validate(*part.mesh).ok());
  // Wall height and overhang move the walls, the eaves and the verges (two nodes) together: still closed.
  ASSERT_TRUE(g.set_exposed("wall_height", Value::make(6.0)));
  ASSERT_TRUE(g.set_exposed("overhang", Value::make(1.2)));
  ASSERT_TRUE(g.set_exposed("width", Value::make(16.0)));
  const MeshSet b = mesh_of(test::evaluate_mesh(g, kSamples));
  ASSERT_EQ(b.parts.size(), 2u);
  for (const TaggedMesh& part : b.parts) EXPECT_TRUE(validate(*part.mesh).ok());
  const auto extent = [](const Mesh& m) {
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (auto v : m.vertices()) lo = glm::min(lo, glm::dvec2(m.point(v)[0], m.point(v)[1])), hi = glm::max(hi, glm::dvec2(m.point(v)[0], m.point(v)[1]));
    return hi - lo;
  };
  // The walls stand flush at 16 x 24 m; the eaves and the verges both reach 1.2 m past them.
  EXPECT_NEAR(extent(*b.parts[0].mesh).x, 16, 1e-6);
  EXPECT_NEAR(extent(*b.parts[0].mesh).y, 24, 1e-6);
  EXPECT_NEAR(extent(*b.parts[1].mesh).x, 16 + 2 * 1.2, 1e-6);
  EXPECT_NEAR(extent(*b.parts[1].mesh).y, 24 + 2 * 1.2, 1e-6);
  // The ridge of a 50-degree roof over the 16 m walls from 6 m, and the slab's 0.25 m on it.
  const double ridge = 6 + 16.0 / 2 / std::tan(50 * M_PI / 180);
  EXPECT_NEAR(top_of(*b.parts[0].mesh), ridge, 1e-6);
  EXPECT_NEAR(top_of(*b.parts[1].mesh), ridge + 0.25 / std::sin(50 * M_PI / 180), 1e-6);
}

TEST(CottageSample, HippedLRunsOutByTheEaveAllRoundAndAcrossTheValley) {
  Graph g = load_pxg(kSamples / "cottage.pxg");
  ASSERT_TRUE(g.set_exposed("eave", Value::make(0.7)));
  const MeshSet m = mesh_of(test::evaluate_mesh(g, kSamples));
  ASSERT_EQ(m.parts.size(), 2u);
  for (const TaggedMesh& part : m.parts) EXPECT_TRUE(validate(*part.mesh).ok());
  // Every roof edge of a hip roof is level: eaves on all six sides, 0.7 m out,
  // so the slab is 0.18 m square to slopes of 1 / tan(38 deg) over the L
  // (11 x 9 m, wings 5 m wide: 75 m2, 40 m round) run out by 0.7, which
  // adds 0.7^2 at each of its five outward corners and takes it at the inward one.
  EXPECT_NEAR(validate(*m.parts[1].mesh).volume, 0.18 / std::sin(38 * M_PI / 180) * (75 + 0.7 * 40 + 0.49 * (5 - 1)), 1e-6);
}

TEST(SetbackTowerSample, WindowsOnlyWhereTheWallsAre) {
  const Graph g = load_pxg(kSamples / "setback_tower.pxg");
  const EvalResult r = test::evaluate_mesh(g, kSamples);
  const MeshSet& set = mesh_of(r);
  ASSERT_EQ(set.parts.size(), 1u);
  const TaggedMesh& part = set.parts[0];
  EXPECT_TRUE(validate(*part.mesh).ok());
  EXPECT_NEAR(top_of(*part.mesh), 69, 1e-9);
  // The tiles are checked against the walls before the openings are cut into them.
  Graph uncut = g;
  ASSERT_TRUE(uncut.set_param(8, "cut", Value::make(false)));
  const EvalResult whole = test::evaluate_mesh(uncut, kSamples);
  const Mesh& walls = *mesh_of(whole).parts[0].mesh;
  const FaceCover cover(walls);
  std::size_t tiles = 0;
  for (const FacadeTile& a : tiles_of(part)) {
    ASSERT_EQ(a.name, "tile");
    ++tiles;
    // The tile lies on its edge's faces in its plane, checked point by point against the mesh's faces too.
    EXPECT_TRUE(cover.covers(a.edge_id, a.frame, {-a.width / 2, 0}, {a.width / 2, a.height}));
    EXPECT_LE(a.frame.origin.z + a.height, 69 + 1e-9);
    const auto faces = cover.faces_in_plane(a.edge_id, a.frame);
    double face_top = -HUGE_VAL, face_bottom = HUGE_VAL;
    for (const auto& f : faces)
      for (const glm::dvec2& p : f) face_top = std::max(face_top, p.y), face_bottom = std::min(face_bottom, p.y);
    EXPECT_LE(a.height, face_top + 1e-9) << "tile above its wall on edge " << a.edge_id;
    EXPECT_GE(0.0, face_bottom - 1e-9) << "tile below its wall on edge " << a.edge_id;
  }
  EXPECT_GT(tiles, 100u);
  // One window per tile, fitted into it.
  ASSERT_EQ(part.placed.instances.size(), tiles);
  // Each window's opening (its tile less the 0.4 m margin) is cut 0.25 m deep: four reveals and a back each,
  // and the tower loses exactly their volume against the same recipe without the cut.
  std::size_t reveals = 0;
  for (std::size_t f = 0; f < part.face_tags.size(); ++f) reveals += face_tag(part, f) == "reveal";
  EXPECT_EQ(reveals, 5 * tiles);
  double recesses = 0;
  for (const FacadeTile& a : tiles_of(part)) recesses += (a.width - 0.8) * (a.height - 0.8) * 0.25;
  EXPECT_NEAR(validate(walls).volume - validate(*part.mesh).volume, recesses, 1e-6);
}

}  // namespace
}  // namespace procex

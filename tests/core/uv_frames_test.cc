// Texture coordinates in metres on a swept house: a tiling facade texture
// runs on round the corners of the footprint, stands upright on walls, runs
// up the roof from the eave, keeps its scale everywhere and is never mirrored.
#include "core/mesh/uv_frames.h"

#include <cmath>
#include <map>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/polygon3.h"
#include "core/sweep/sweep.h"

namespace procex {
namespace {

glm::dvec3 point(const Mesh& mesh, Mesh::VertexHandle v) {
  const Mesh::Point& p = mesh.point(v);
  return {p[0], p[1], p[2]};
}

glm::dvec3 unit_normal(const Mesh& mesh, Mesh::FaceHandle f) {
  std::vector<glm::dvec3> pts;
  for (const auto v : mesh.fv_range(f)) pts.push_back(point(mesh, v));
  return glm::normalize(newell_normal(pts));
}

//   (0,10) +-----------+ (12,10)
//          |           |          an L: walls 3 m, then a 40 degree roof
//   (0, 4) |     +-----+ (12,4)   (with an overhang of 0.5 m below the eave)
//          |     |
//    (0,0) +-----+ (6,0)
Mesh house() {
  Footprint fp = make_footprint({{{0, 0}, {6, 0}, {6, 4}, {12, 4}, {12, 10}, {0, 10}}}, 45);
  const double rise = 6.5 * std::tan(40.0 * M_PI / 180.0);
  fp.profiles.push_back({"house", {{0, 0}, {0, 3}, {0.5, 3}, {-6, 3 + rise}}, {"wall", "soffit", "roof"}});
  for (auto& e : fp.loops[0].edges) e.profile = 0;
  return build_mesh(sweep(fp));
}

class UvFrames : public ::testing::Test {
 protected:
  Mesh mesh_ = house();
  std::vector<UvFrame> frames_ = face_uv_frames(mesh_);
  const std::string& tag(Mesh::FaceHandle f) const { return face_tag(mesh_, f); }
};

TEST_F(UvFrames, MetresOnEveryFaceRightHandedSeenFromOutside) {
  ASSERT_EQ(frames_.size(), mesh_.n_faces());
  for (const auto f : mesh_.faces()) {
    SCOPED_TRACE("face " + std::to_string(f.idx()) + " (" + tag(f) + ")");
    const UvFrame& t = frames_[static_cast<std::size_t>(f.idx())];
    EXPECT_NEAR(glm::length(t.u), 1.0, 1e-12);  // one unit of u or v is one metre on the face
    EXPECT_NEAR(glm::length(t.v), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(t.u, t.v), 0.0, 1e-12);
    const glm::dvec3 n = unit_normal(mesh_, f);
    EXPECT_NEAR(glm::dot(t.u, n), 0.0, 1e-9);  // both in the face's plane
    EXPECT_NEAR(glm::dot(t.v, n), 0.0, 1e-9);
    EXPECT_NEAR(glm::dot(glm::cross(t.u, t.v), n), 1.0, 1e-9);  // not mirrored
  }
}

TEST_F(UvFrames, WallsRunOnRoundTheFootprintWithVTheHeight) {
  // Where two walls meet, they give the shared vertex the same u (except
  // where the loop closes, at perimeter 44 = 0).
  std::map<int, std::vector<double>> u_at;
  int walls = 0;
  for (const auto f : mesh_.faces()) {
    if (tag(f) != "wall") continue;
    ++walls;
    const UvFrame& t = frames_[static_cast<std::size_t>(f.idx())];
    EXPECT_NEAR(std::abs(t.u.z), 0.0, 1e-12);
    for (const auto v : mesh_.fv_range(f)) {
      const glm::dvec2 uv = t.at(point(mesh_, v));
      EXPECT_NEAR(uv.y, point(mesh_, v).z, 1e-9);  // v is the height
      EXPECT_GE(uv.x, -1e-9);
      EXPECT_LE(uv.x, 44.0 + 1e-9);
      u_at[v.idx()].push_back(uv.x);
    }
  }
  EXPECT_EQ(walls, 6);
  int corners = 0;
  for (const auto& [v, us] : u_at) {
    if (us.size() < 2) continue;
    ++corners;
    const bool loop_start = std::abs(us[0] - us[1]) > 43.0;
    if (!loop_start) {
      EXPECT_NEAR(us[0], us[1], 1e-9) << "vertex " << v;
    }
  }
  EXPECT_EQ(corners, 12);  // six corners at the foot, six at the top of the walls
}

TEST_F(UvFrames, RoofsTakeUAlongTheEaveAndVUpTheSlope) {
  int roofs = 0;
  for (const auto f : mesh_.faces()) {
    if (tag(f) != "roof") continue;
    ++roofs;
    const UvFrame& t = frames_[static_cast<std::size_t>(f.idx())];
    EXPECT_NEAR(t.u.z, 0.0, 1e-9);  // the eave is level
    EXPECT_NEAR(t.v.z, std::sin(40.0 * M_PI / 180.0), 1e-9);  // up the 40 degree slope
    // v runs on from the eave: the lowest corner has v = its height (3 m).
    double lowest = INFINITY;
    for (const auto v : mesh_.fv_range(f)) lowest = std::min(lowest, t.at(point(mesh_, v)).y);
    EXPECT_NEAR(lowest, 3.0, 1e-9);
  }
  EXPECT_EQ(roofs, 6);
}

TEST_F(UvFrames, HorizontalFacesTakePlanCoordinatesUnmirrored) {
  int flat = 0;
  for (const auto f : mesh_.faces()) {
    const glm::dvec3 n = unit_normal(mesh_, f);
    if (std::abs(n.z) < 1.0 - 1e-12) continue;
    ++flat;
    const UvFrame& t = frames_[static_cast<std::size_t>(f.idx())];
    for (const auto v : mesh_.fv_range(f)) {
      const glm::dvec2 uv = t.at(point(mesh_, v));
      EXPECT_EQ(uv.x, point(mesh_, v).x);
      EXPECT_EQ(uv.y, n.z > 0 ? point(mesh_, v).y : -point(mesh_, v).y);  // a soffit or base is seen from below
    }
  }
  EXPECT_GE(flat, 2);  // the footprint and the soffit round the eave
}

}  // namespace
}  // namespace procex

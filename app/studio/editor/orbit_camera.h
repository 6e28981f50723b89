// orbit_camera.h -- the 3D preview's camera: orbits a target point (z up),
// pans in the view plane, zooms by distance.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace procex::studio {

class OrbitCamera {
 public:
  // Degrees; yaw around +z, pitch above the ground plane.
  float yaw = -50.0f, pitch = 30.0f;
  float distance = 30.0f;
  glm::vec3 target{0.0f};  // in the preview's frame (PreviewMesh::origin)
  float fov_deg = 40.0f;

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;

  // Mouse drags in pixels.
  void orbit(float dx, float dy);
  void pan(float dx, float dy, float viewport_height);
  // Positive steps zoom in (mouse wheel).
  void zoom(float steps);
  // Looks at the box from the current direction so that it fills the view.
  void frame(const glm::vec3& min, const glm::vec3& max);
};

}  // namespace procex::studio

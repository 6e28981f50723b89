#include "app/studio/editor/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace procex::studio {

glm::vec3 OrbitCamera::eye() const {
  const float y = glm::radians(yaw), p = glm::radians(pitch);
  return target + distance * glm::vec3(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p));
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), target, glm::vec3(0, 0, 1)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  // Near and far follow the distance so that depth precision suits any scale.
  return glm::perspective(glm::radians(fov_deg), std::max(aspect, 1e-3f), distance * 0.01f, distance * 100.0f);
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw -= dx * 0.4f;
  pitch = std::clamp(pitch + dy * 0.4f, -89.0f, 89.0f);
}

void OrbitCamera::pan(float dx, float dy, float viewport_height) {
  const glm::vec3 forward = glm::normalize(target - eye());
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 0, 1)));
  const glm::vec3 up = glm::cross(right, forward);
  // One pixel moves the target by the size of a pixel at the target's depth.
  const float pixel = 2.0f * distance * std::tan(glm::radians(fov_deg) * 0.5f) / std::max(viewport_height, 1.0f);
  target += (-dx * right + dy * up) * pixel;
}

void OrbitCamera::zoom(float steps) { distance = std::clamp(distance * std::pow(0.88f, steps), 1e-3f, 1e7f); }

void OrbitCamera::frame(const glm::vec3& min, const glm::vec3& max) {
  target = 0.5f * (min + max);
  const float radius = std::max(0.5f * glm::length(max - min), 1e-2f);
  distance = radius / std::sin(glm::radians(fov_deg) * 0.5f) * 1.05f;
}

}  // namespace procex::studio

#include "camera.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace snell::viewer {
namespace {

constexpr float kMaxElevation = glm::radians(89.0f);

/// Any unit vector perpendicular to the unit `u`.
glm::vec3 perpendicular(const glm::vec3& u) {
  const glm::vec3 a = std::fabs(u.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  return glm::normalize(glm::cross(u, a));
}

} // namespace

CameraController::CameraController(const CameraDesc& home) : home_(home), camera_(home) {}

void CameraController::reset() {
  camera_ = home_;
}

void CameraController::look_at(const glm::vec3& eye, const glm::vec3& target) {
  if (eye == target) {
    return;
  }
  camera_.eye = eye;
  camera_.target = target;
}

glm::vec3 CameraController::up_axis() const {
  const float len = glm::length(camera_.up);
  return len > 0.0f ? camera_.up / len : glm::vec3(0, 1, 0);
}

glm::vec3 CameraController::turn(const glm::vec3& direction, float yaw, float pitch) const {
  const glm::vec3 u = up_axis();
  const float elevation = std::asin(std::clamp(glm::dot(direction, u), -1.0f, 1.0f));
  glm::vec3 h = direction - glm::dot(direction, u) * u;
  h = glm::length(h) > 1e-6f ? glm::normalize(h) : perpendicular(u);
  // Yaw: h turned about u (Rodrigues' formula for h perpendicular to u).
  h = h * std::cos(yaw) + glm::cross(u, h) * std::sin(yaw);
  const float e = std::clamp(elevation + pitch, -kMaxElevation, kMaxElevation);
  return glm::normalize(std::cos(e) * h + std::sin(e) * u);
}

void CameraController::orbit(float yaw, float pitch) {
  const float d = distance();
  if (!(d > 0.0f)) {
    return;
  }
  const glm::vec3 from_target = (camera_.eye - camera_.target) / d;
  camera_.eye = camera_.target + turn(from_target, yaw, pitch) * d;
}

void CameraController::look(float yaw, float pitch) {
  const float d = distance();
  if (!(d > 0.0f)) {
    return;
  }
  const glm::vec3 forward = (camera_.target - camera_.eye) / d;
  camera_.target = camera_.eye + turn(forward, yaw, pitch) * d;
}

void CameraController::pan(float dx, float dy) {
  const float d = distance();
  if (!(d > 0.0f)) {
    return;
  }
  const glm::vec3 forward = (camera_.target - camera_.eye) / d;
  glm::vec3 right = glm::cross(forward, up_axis());
  right = glm::length(right) > 1e-6f ? glm::normalize(right) : perpendicular(forward);
  const glm::vec3 screen_up = glm::cross(right, forward);
  const float view_height = 2.0f * d * std::tan(0.5f * camera_.yfov);
  const glm::vec3 shift = (-dx * right - dy * screen_up) * view_height;
  camera_.eye += shift;
  camera_.target += shift;
}

void CameraController::zoom(float steps) {
  const float d = distance();
  if (!(d > 0.0f)) {
    return;
  }
  const float home_distance = glm::length(home_.eye - home_.target);
  const float wanted = d * std::pow(0.85f, steps);
  const float lo = min_distance();
  const float hi = std::max({1000.0f * home_distance, d, lo});
  const float next = std::clamp(wanted, lo, hi);
  camera_.eye = camera_.target + (camera_.eye - camera_.target) / d * next;
}

void CameraController::fly(float right, float up, float forward) {
  const float d = distance();
  if (!(d > 0.0f)) {
    return;
  }
  const glm::vec3 f = (camera_.target - camera_.eye) / d;
  glm::vec3 r = glm::cross(f, up_axis());
  r = glm::length(r) > 1e-6f ? glm::normalize(r) : perpendicular(f);
  const glm::vec3 move = right * r + up * up_axis() + forward * f;
  camera_.eye += move;
  camera_.target += move;
}

float CameraController::distance() const {
  return glm::length(camera_.target - camera_.eye);
}

float CameraController::min_distance() const {
  const float home_distance = glm::length(home_.eye - home_.target);
  return std::max(0.01f * home_distance, 2.0f * camera_.z_near);
}

float CameraController::fly_speed() const {
  return std::max(0.25f * glm::length(home_.eye - home_.target), 0.1f);
}

} // namespace snell::viewer

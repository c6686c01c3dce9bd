// The viewer's camera controls over a snell::CameraDesc: orbit around the target, pan, zoom
// (dolly toward the target), fly (move and look), reset. Pure math, no window: the viewer maps
// mouse and keys onto these calls, scripts call them directly, and tests check them on the CPU.
#pragma once

#include <snell/scene.hpp>

#include <glm/vec3.hpp>

namespace snell::viewer {

class CameraController {
public:
  /// `home` is the camera reset() returns to (the scene's camera, with --eye/--target/--fov).
  explicit CameraController(const CameraDesc& home = {});

  /// The camera now.
  [[nodiscard]] const CameraDesc& camera() const { return camera_; }
  /// The camera reset() returns to.
  [[nodiscard]] const CameraDesc& home() const { return home_; }
  /// Back to home().
  void reset();
  /// Places the camera (a script's `camera` action). `eye` == `target` is ignored.
  void look_at(const glm::vec3& eye, const glm::vec3& target);

  /// Turns the eye around the target: `yaw` about the up axis, `pitch` about the camera's
  /// right axis (radians; positive pitch raises the eye). The elevation stays within 89 degrees
  /// of the horizon, so the view never flips over the pole. The distance is kept.
  void orbit(float yaw, float pitch);
  /// Moves eye and target in the view plane by `dx`, `dy` in units of the view's height at the
  /// target's distance (a drag across the whole window height moves the target out of view):
  /// positive dx moves the scene right on screen, positive dy up.
  void pan(float dx, float dy);
  /// Moves the eye toward the target: the distance is multiplied by 0.85^steps (a wheel notch
  /// is one step; negative steps move away), kept within [min_distance(), 1000 x home's].
  void zoom(float steps);
  /// Turns the view direction about the eye (mouse look): the target moves, the eye stays.
  /// Same angle conventions and pitch limit as orbit().
  void look(float yaw, float pitch);
  /// Moves eye and target together by `right`, `up`, `forward` world units along the camera's
  /// axes (forward is the view direction, up the world up).
  void fly(float right, float up, float forward);

  /// Eye-to-target distance.
  [[nodiscard]] float distance() const;
  /// The smallest distance zoom() reaches (a hundredth of home's, at least twice z_near).
  [[nodiscard]] float min_distance() const;
  /// World units per second that fly keys move at: a quarter of home's eye-target distance.
  [[nodiscard]] float fly_speed() const;

private:
  /// `direction` (unit, from the pivot) turned by yaw about up and pitch about the right axis,
  /// its elevation clamped to +-89 degrees.
  [[nodiscard]] glm::vec3 turn(const glm::vec3& direction, float yaw, float pitch) const;
  [[nodiscard]] glm::vec3 up_axis() const;
  CameraDesc home_;
  CameraDesc camera_;
};

} // namespace snell::viewer

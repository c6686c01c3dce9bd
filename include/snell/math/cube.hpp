// Snell math: cube maps (dynamic environment capture, seed 002) in Vulkan's conventions.
#pragma once

#include "conventions.hpp"
#include "projection.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>

namespace snell {

/// Cube faces in Vulkan's array-layer order (layer = the enum value).
enum class CubeFace : std::uint8_t { pos_x, neg_x, pos_y, neg_y, pos_z, neg_z };

/// A cube-map texel address: the face (layer) and the texture coordinate on it, uv in [0,1]^2
/// with v = 0 on the first row of the layer.
struct CubeTexel {
  CubeFace face = CubeFace::pos_x; ///< Face / array layer. Default +X.
  glm::vec2 uv{0.5f};              ///< Coordinate on the face, [0,1]^2. Default the centre.
};

/// The face and texel a direction samples, by the face-selection table of the Vulkan
/// specification ("Cube Map Face Selection"): the major axis picks the face, then
/// `u = 0.5 sc/|ma| + 0.5`, `v = 0.5 tc/|ma| + 0.5` with
///
/// | face | sc  | tc  |      | face | sc  | tc  |
/// |------|-----|-----|------|------|-----|-----|
/// | +X   | -z  | -y  |      | -X   | +z  | -y  |
/// | +Y   | +x  | +z  |      | -Y   | +x  | -z  |
/// | +Z   | +x  | -y  |      | -Z   | -x  | -y  |
///
/// `dir` need not be normalised. Ties between equal-magnitude axes (cube edges and corners,
/// where the specification leaves the choice to the implementation) go to X, then Y, then Z.
/// The zero vector gives the centre of +X.
[[nodiscard]] inline CubeTexel direction_to_cube(glm::vec3 dir) noexcept {
  const float ax = std::fabs(dir.x);
  const float ay = std::fabs(dir.y);
  const float az = std::fabs(dir.z);
  CubeFace face;
  float sc;
  float tc;
  float ma;
  if (ax >= ay && ax >= az) {
    ma = ax;
    face = dir.x >= 0.0f ? CubeFace::pos_x : CubeFace::neg_x;
    sc = dir.x >= 0.0f ? -dir.z : dir.z;
    tc = -dir.y;
  } else if (ay >= az) {
    ma = ay;
    face = dir.y >= 0.0f ? CubeFace::pos_y : CubeFace::neg_y;
    sc = dir.x;
    tc = dir.y >= 0.0f ? dir.z : -dir.z;
  } else {
    ma = az;
    face = dir.z >= 0.0f ? CubeFace::pos_z : CubeFace::neg_z;
    sc = dir.z >= 0.0f ? dir.x : -dir.x;
    tc = -dir.y;
  }
  if (!(ma > 0.0f)) {
    return CubeTexel{CubeFace::pos_x, glm::vec2(0.5f)};
  }
  return CubeTexel{face, glm::vec2(0.5f * sc / ma + 0.5f, 0.5f * tc / ma + 0.5f)};
}

/// The unit direction that samples `uv` on `face`: the inverse of `direction_to_cube`
/// (`direction_to_cube(cube_to_direction(f, uv)) == {f, uv}` for uv inside the face).
/// uv outside [0,1]^2 extrapolates the face plane.
[[nodiscard]] inline glm::vec3 cube_to_direction(CubeFace face, glm::vec2 uv) noexcept {
  const float sc = 2.0f * uv.x - 1.0f;
  const float tc = 2.0f * uv.y - 1.0f;
  glm::vec3 d(1.0f, 0.0f, 0.0f);
  switch (face) {
  case CubeFace::pos_x:
    d = glm::vec3(1.0f, -tc, -sc);
    break;
  case CubeFace::neg_x:
    d = glm::vec3(-1.0f, -tc, sc);
    break;
  case CubeFace::pos_y:
    d = glm::vec3(sc, 1.0f, tc);
    break;
  case CubeFace::neg_y:
    d = glm::vec3(sc, -1.0f, -tc);
    break;
  case CubeFace::pos_z:
    d = glm::vec3(sc, -tc, 1.0f);
    break;
  case CubeFace::neg_z:
    d = glm::vec3(-sc, -tc, -1.0f);
    break;
  }
  return glm::normalize(d);
}

/// The forward (look) direction of a face: its major axis.
[[nodiscard]] inline glm::vec3 cube_face_forward(CubeFace face) noexcept {
  return cube_to_direction(face, glm::vec2(0.5f));
}

/// The up vector of a face camera (the `up` given to `look_at`): the world direction of
/// increasing v on that face, -Y for the four side faces, +Z for +Y and -Z for -Y (the
/// classic cube-map table). The first row of a layer lies toward `-cube_face_up(face)`.
[[nodiscard]] inline glm::vec3 cube_face_up(CubeFace face) noexcept {
  switch (face) {
  case CubeFace::pos_y:
    return glm::vec3(0.0f, 0.0f, 1.0f);
  case CubeFace::neg_y:
    return glm::vec3(0.0f, 0.0f, -1.0f);
  default:
    return glm::vec3(0.0f, -1.0f, 0.0f);
  }
}

/// View matrix of the camera at `center` that renders `face`. With `cube_face_projection` and a
/// standard (positive-height, not flipped) Vulkan viewport, a direction `d` lands at
/// `0.5 * ndc.xy + 0.5 == direction_to_cube(d).uv` on that face, so a sampler reads the capture
/// back where it belongs. Seen as pictures, the side faces have row 0 toward world +Y but are
/// mirrored left-right compared with a photo taken along the same axis: that is the cube-map
/// convention (the sampler looks from the inside), not a bug. Right-handed, determinant +1; a
/// pipeline drawing a face must use the opposite front face of a y-flipped main view.
[[nodiscard]] inline glm::mat4 cube_face_view(glm::vec3 center, CubeFace face) noexcept {
  const glm::vec3 forward = cube_face_forward(face);
  return look_at(center, center + forward, cube_face_up(face));
}

/// The 90-degree, aspect-1 projection of a cube face (clip y *not* flipped; see
/// `cube_face_view`). `z_near` > 0, `z_far` > `z_near` or +infinity.
[[nodiscard]] inline glm::mat4 cube_face_projection(float z_near, float z_far,
                                                    DepthRange range) noexcept {
  return perspective(glm::half_pi<float>(), 1.0f, z_near, z_far, range);
}

} // namespace snell

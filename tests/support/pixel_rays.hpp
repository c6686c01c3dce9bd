// Test support, header-only: the eye ray of a pixel and rays against boxes, traced on the CPU to
// predict what a frame shows (reflections, refractions, silhouettes) independently of shaders.
#pragma once

#include <snell/scene_source.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace snell::test {

/// A ray: origin and unit direction.
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 dir{0.0f, 0.0f, -1.0f};
};

/// The eye ray through pixel position `px` (pixels, (0, 0) the top-left corner, so a pixel's
/// centre is (x + 0.5, y + 0.5)) of a `width` x `height` frame of `view`.
inline Ray pixel_ray(const SceneView& view, std::uint32_t width, std::uint32_t height,
                     glm::vec2 px) {
  const glm::mat4 inv = glm::inverse(view.proj * view.view);
  const glm::vec2 ndc =
      px / glm::vec2(static_cast<float>(width), static_cast<float>(height)) * 2.0f - 1.0f;
  const glm::vec4 a = inv * glm::vec4(ndc, 0.0f, 1.0f);
  const glm::vec4 b = inv * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 o = glm::vec3(a) / a.w;
  return {o, glm::normalize(glm::vec3(b) / b.w - o)};
}

/// Distance along the ray o + t d (t >= 0) to the box lo..hi, or a negative value when it misses.
inline float ray_box(glm::vec3 o, glm::vec3 d, glm::vec3 lo, glm::vec3 hi) {
  float t0 = 0.0f, t1 = 1e30f;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-9f) {
      if (o[k] < lo[k] || o[k] > hi[k]) {
        return -1.0f;
      }
      continue;
    }
    float a = (lo[k] - o[k]) / d[k], b = (hi[k] - o[k]) / d[k];
    if (a > b) {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1 ? t0 : -1.0f;
}

} // namespace snell::test

// Shared by the dynamic_cubemap tests: rays against boxes and spheres, traced on the CPU to
// predict what the probe's surface shows, independently of the shaders.
#pragma once

#include <snell/frame.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace snell::test {

/// Where the ray o + t d (unit d) meets the box `lo..hi`, if it does (t >= 0).
inline bool hits_box(glm::vec3 o, glm::vec3 d, glm::vec3 lo, glm::vec3 hi) {
  float t0 = 0.0f, t1 = 1e30f;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-9f) {
      if (o[k] < lo[k] || o[k] > hi[k]) {
        return false;
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
  return t0 <= t1;
}

/// Calls fn(x, y, p, d) for every pixel (x, y) of a width x height `view` whose eye ray, unit
/// direction d, meets the sphere (centre `c`, radius `r`); p is the nearer hit.
template <class F>
void for_each_sphere_pixel(const SceneView& view, std::uint32_t width, std::uint32_t height,
                           glm::vec3 c, float r, F&& fn) {
  const glm::mat4 inv = glm::inverse(view.proj * view.view);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const glm::vec2 ndc((static_cast<float>(x) + 0.5f) / static_cast<float>(width) * 2.0f - 1.0f,
                          (static_cast<float>(y) + 0.5f) / static_cast<float>(height) * 2.0f -
                              1.0f);
      const glm::vec4 a = inv * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::vec4 b = inv * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 o = glm::vec3(a) / a.w;
      const glm::vec3 d = glm::normalize(glm::vec3(b) / b.w - o);
      // |o + t d - c|^2 = r^2.
      const glm::vec3 oc = o - c;
      const float bq = glm::dot(oc, d);
      const float disc = bq * bq - (glm::dot(oc, oc) - r * r);
      if (disc > 0.0f) {
        fn(x, y, o + d * (-bq - std::sqrt(disc)), d);
      }
    }
  }
}

/// True when pixel `i` (RGBA8 index) of `image` is the red marker: red above `min_red`.
inline bool is_red(const Image& image, std::size_t i, int min_red) {
  return image.rgba8[i] > min_red && image.rgba8[i + 1] < 60 && image.rgba8[i + 2] < 60;
}

} // namespace snell::test

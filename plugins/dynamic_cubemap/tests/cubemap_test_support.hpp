// Shared by the dynamic_cubemap tests: rays against boxes and spheres, traced on the CPU to
// predict what the probe's surface shows, independently of the shaders.
#pragma once

#include "frame_rig.hpp"
#include "pixel_rays.hpp"

#include <snell/builtin_scenes.hpp>

#include <snell/frame.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace snell::test {

/// True when the ray o + t d (t >= 0) meets the box `lo..hi`.
inline bool hits_box(glm::vec3 o, glm::vec3 d, glm::vec3 lo, glm::vec3 hi) {
  return ray_box(o, d, lo, hi) >= 0.0f;
}

/// Calls fn(x, y, p, d) for every pixel (x, y) of a width x height `view` whose eye ray, unit
/// direction d, meets the sphere (centre `c`, radius `r`); p is the nearer hit.
template <class F>
void for_each_sphere_pixel(const SceneView& view, std::uint32_t width, std::uint32_t height,
                           glm::vec3 c, float r, F&& fn) {
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const Ray ray = pixel_ray(view, width, height,
                                glm::vec2(static_cast<float>(x), static_cast<float>(y)) + 0.5f);
      const glm::vec3 o = ray.origin;
      const glm::vec3 d = ray.dir;
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

/// Sets `rig` up with the built-in spheres scene, its camera, a `width` x `height` frame.
inline void init_spheres_rig(Context& ctx, FrameRig& rig, std::uint32_t width,
                             std::uint32_t height) {
  auto scene = make_builtin_scene("spheres");
  REQUIRE(scene.has_value());
  rig.scene = std::move(*scene);
  rig.camera = rig.scene.cameras.front();
  rig.width = width;
  rig.height = height;
  rig.init_frame(ctx);
}

} // namespace snell::test

// Shared by the mirror tests: a frame rig with mirrors, and the CPU ray tracing that predicts
// what a mirror shows (the eye ray meets the plane inside the mirror, reflects, meets a box),
// independently of the shaders.
#pragma once

#include "frame_rig.hpp"
#include "pixel_rays.hpp"

#include <snell/mirror.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace snell::test {

/// A dark scene (test::empty_dark_scene), 320 x 240 linear RGBA8, and mirrors made for it.
struct MirrorRig : FrameRig {
  std::vector<std::unique_ptr<MirrorEffect>> mirrors;

  MirrorRig() {
    scene = empty_dark_scene();
    width = 320;
    height = 240;
  }
  /// Creates a mirror with `p` (REQUIREs success) after init_frame().
  MirrorEffect& add(Context& ctx, const MirrorParams& p) {
    auto created = create_mirror(effect_info(ctx));
    REQUIRE_MESSAGE(created.has_value(), (created ? std::string() : created.error().message));
    auto set = (*created)->set_params(p);
    REQUIRE_MESSAGE(set.has_value(), (set ? std::string() : set.error().message));
    mirrors.push_back(std::move(*created));
    return *mirrors.back();
  }
  /// One frame with every mirror.
  Image render_mirrors() {
    std::vector<Effect*> list;
    for (auto& m : mirrors) {
      list.push_back(m.get());
    }
    return render_effects(list);
  }
};

/// A rectangle mirror as the effect places it: centre, unit normal, unit up, size.
struct Rect {
  glm::vec3 center{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  glm::vec2 size{2.0f, 2.0f};
};

/// The unit eye ray through the centre of pixel (x, y) of `view` (w x h).
inline void pixel_ray(const SceneView& view, std::uint32_t w, std::uint32_t h, std::uint32_t x,
                      std::uint32_t y, glm::vec3& origin, glm::vec3& dir) {
  const Ray ray =
      pixel_ray(view, w, h, glm::vec2(static_cast<float>(x), static_cast<float>(y)) + 0.5f);
  origin = ray.origin;
  dir = ray.dir;
}

/// Where the ray meets the rectangle (distance along it, and the hit), if it does from the
/// reflecting side.
inline bool ray_rect(glm::vec3 o, glm::vec3 d, const Rect& r, float& t, glm::vec3& hit) {
  const float denom = glm::dot(d, r.normal);
  if (denom >= -1e-6f) {
    return false; // parallel, or arriving from behind
  }
  t = glm::dot(r.center - o, r.normal) / denom;
  if (t <= 0.0f) {
    return false;
  }
  hit = o + t * d;
  const glm::vec3 right = glm::cross(r.up, r.normal);
  const glm::vec3 local = hit - r.center;
  return std::abs(glm::dot(local, right)) <= 0.5f * r.size.x &&
         std::abs(glm::dot(local, r.up)) <= 0.5f * r.size.y;
}

/// Centroids of the pixels predicted to show box lo..hi in mirror `r` (the eye ray meets the
/// mirror first, its reflection meets the box) and of the pixels among those candidates
/// (the eye ray meets the mirror first) that `is_marker` says show it.
struct Centroids {
  glm::vec2 predicted{0.0f}, observed{0.0f};
  int predicted_count = 0, observed_count = 0;
};

template <class IsMarker>
Centroids mirror_centroids(const Image& image, const SceneView& view, const Rect& r, glm::vec3 lo,
                           glm::vec3 hi, IsMarker&& is_marker) {
  Centroids c;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      glm::vec3 o, d, hit;
      pixel_ray(view, image.width, image.height, x, y, o, d);
      float t = 0.0f;
      if (!ray_rect(o, d, r, t, hit)) {
        continue;
      }
      const float direct = ray_box(o, d, lo, hi);
      if (direct >= 0.0f && direct < t) {
        continue; // the box itself stands in front of the mirror here
      }
      const glm::vec3 bounced = glm::reflect(d, r.normal);
      if (ray_box(hit, bounced, lo, hi) >= 0.0f) {
        c.predicted += glm::vec2(x, y);
        ++c.predicted_count;
      }
      const std::size_t i = (std::size_t{y} * image.width + x) * 4;
      if (is_marker(image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2])) {
        c.observed += glm::vec2(x, y);
        ++c.observed_count;
      }
    }
  }
  c.predicted /= static_cast<float>(std::max(c.predicted_count, 1));
  c.observed /= static_cast<float>(std::max(c.observed_count, 1));
  return c;
}

inline MirrorParams rect_params(const Rect& r) {
  MirrorParams p;
  p.center = r.center;
  p.normal = r.normal;
  p.up = r.up;
  p.size = r.size;
  return p;
}

} // namespace snell::test

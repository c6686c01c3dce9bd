// The built-in textures of glass and ice, generated in code (no asset files): deterministic,
// tileable (every pattern is periodic over the image), RGBA8.
#include "glass_internal.hpp"

#include <snell/builtin_scenes.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace snell::detail {
namespace {

/// Value noise with `cells` cells across the unit square, periodic over it (smooth, [0, 1]).
float periodic_noise(float u, float v, int cells, std::uint32_t seed) {
  const float x = u * static_cast<float>(cells), y = v * static_cast<float>(cells);
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  auto at = [&](int i, int j) {
    const auto wi = static_cast<std::uint32_t>(((i % cells) + cells) % cells);
    const auto wj = static_cast<std::uint32_t>(((j % cells) + cells) % cells);
    return unit_hash(wi, wj, seed);
  };
  const float sx = fx * fx * (3.0f - 2.0f * fx), sy = fy * fy * (3.0f - 2.0f * fy);
  const float a = glm::mix(at(x0, y0), at(x0 + 1, y0), sx);
  const float b = glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), sx);
  return glm::mix(a, b, sy);
}

/// Three octaves of periodic value noise, [0, 1].
float fbm(float u, float v, int cells, std::uint32_t seed) {
  return 0.57f * periodic_noise(u, v, cells, seed) +
         0.29f * periodic_noise(u, v, cells * 2, seed + 1) +
         0.14f * periodic_noise(u, v, cells * 4, seed + 2);
}

/// Frost crystals: a periodic Voronoi diagram of `cells` x `cells` jittered points. Returns
/// the nearest cell's index and the distance to the cell border (in cell units, >= 0).
struct Voronoi {
  std::uint32_t cell = 0;
  float border = 0.0f;
};

Voronoi voronoi(float u, float v, int cells, std::uint32_t seed) {
  const float x = u * static_cast<float>(cells), y = v * static_cast<float>(cells);
  const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
  float best = 1e9f, second = 1e9f;
  std::uint32_t best_cell = 0;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      const int gx = cx + i, gy = cy + j;
      const auto wx = static_cast<std::uint32_t>(((gx % cells) + cells) % cells);
      const auto wy = static_cast<std::uint32_t>(((gy % cells) + cells) % cells);
      const float px = static_cast<float>(gx) + unit_hash(wx, wy, seed);
      const float py = static_cast<float>(gy) + unit_hash(wx, wy, seed + 7);
      const float d = std::hypot(px - x, py - y);
      if (d < best) {
        second = best;
        best = d;
        best_cell = wy * static_cast<std::uint32_t>(cells) + wx;
      } else if (d < second) {
        second = d;
      }
    }
  }
  // Half the difference of the two nearest distances approximates the distance to the border.
  return {best_cell, 0.5f * (second - best)};
}

void put(Image& image, std::uint32_t x, std::uint32_t y, glm::vec3 c) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
  for (int k = 0; k < 3; ++k) {
    image.rgba8[i + static_cast<std::size_t>(k)] =
        static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255.0f));
  }
  image.rgba8[i + 3] = 255;
}

Image blank(const char* name, std::uint32_t size, bool srgb) {
  Image image;
  image.name = name;
  image.width = size;
  image.height = size;
  image.srgb = srgb;
  image.rgba8.assign(static_cast<std::size_t>(size) * size * 4, 255);
  return image;
}

/// Calls `f(u, v)` for each pixel centre and stores its colour.
template <class F> void fill(Image& image, F&& f) {
  const auto n = static_cast<float>(image.width);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      put(image, x, y, f((static_cast<float>(x) + 0.5f) / n, (static_cast<float>(y) + 0.5f) / n));
    }
  }
}

} // namespace

Result<Image> builtin_glass_normal_map(GlassKind kind, std::uint32_t size) {
  if (kind == GlassKind::glass) {
    // Drawn float glass: long, low waves (slope at most 0.3).
    auto image = make_noise_normal_map(size, 0.3f, 11u);
    if (image) {
      image->name = "glass waviness";
    }
    return image;
  }
  // Ice: each frost crystal is a flat facet tilted up to ~25 degrees, with fine noise on top;
  // the normal bends toward the border so the crystals' edges catch the light.
  Image image = blank("ice frost normals", size, false);
  fill(image, [](float u, float v) {
    const Voronoi c = voronoi(u, v, 9, 41u);
    const float a = 6.2831853f * unit_hash(c.cell, 3u, 43u);
    const float tilt = 0.45f * unit_hash(c.cell, 5u, 47u);
    glm::vec2 slope = tilt * glm::vec2(std::cos(a), std::sin(a));
    slope += 0.25f * glm::vec2(fbm(u, v, 16, 53u) - 0.5f, fbm(u, v, 16, 59u) - 0.5f);
    slope *= 1.0f + 1.5f * std::exp(-c.border * 12.0f);
    return glm::normalize(glm::vec3(slope, 1.0f)) * 0.5f + 0.5f;
  });
  return image;
}

Result<Image> builtin_glass_color(GlassKind kind, std::uint32_t size) {
  Image image = blank(kind == GlassKind::glass ? "glass smudges" : "ice frost", size, true);
  if (kind == GlassKind::glass) {
    // Pale blue-grey glass with soft streaks (the seed's glass texture is a tinted, smudged
    // pane; this is a procedural stand-in).
    fill(image, [](float u, float v) {
      const float streak = fbm(u * 0.5f + v, v, 4, 61u);
      const float smudge = fbm(u, v, 6, 67u);
      const float k = 0.75f + 0.2f * streak - 0.15f * smudge;
      return k * glm::vec3(0.80f, 0.88f, 0.92f);
    });
  } else {
    // White-blue frost, brighter at crystal borders and in drifts.
    fill(image, [](float u, float v) {
      const Voronoi c = voronoi(u, v, 9, 41u);
      const float edge = std::exp(-c.border * 10.0f);
      const float drift = fbm(u, v, 5, 71u);
      const float k = 0.62f + 0.25f * drift + 0.35f * edge;
      return glm::min(k * glm::vec3(0.84f, 0.92f, 0.98f), glm::vec3(1.0f));
    });
  }
  return image;
}

} // namespace snell::detail

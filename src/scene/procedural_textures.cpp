// Procedural textures for the built-in scenes: checker, bricks/tiles, ripple normal map.
// Everything is computed from integer pixel coordinates and a seeded integer hash, so the
// output is deterministic, and tileable patterns are periodic in whole pixels.
#include <snell/builtin_scenes.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

namespace snell {
namespace {

constexpr float pi = 3.14159265358979f;

std::string fmt(float value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string fmt(glm::vec3 c) {
  return "(" + fmt(c.x) + ", " + fmt(c.y) + ", " + fmt(c.z) + ")";
}

Error bad(const char* function, const std::string& what) {
  return fail(ErrorCode::invalid_argument, std::string(function) + ": " + what);
}

std::optional<Error> check_size(const char* function, std::uint32_t size) {
  if (size < 1 || size > max_procedural_image_size) {
    return bad(function, "size = " + std::to_string(size) + " is out of range [1, " +
                             std::to_string(max_procedural_image_size) + "]");
  }
  return std::nullopt;
}

bool is_unit_colour(glm::vec3 c) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(c[i]) || c[i] < 0.0f || c[i] > 1.0f) {
      return false;
    }
  }
  return true;
}

std::optional<Error> check_colour(const char* function, const char* name, glm::vec3 c) {
  if (!is_unit_colour(c)) {
    return bad(function, std::string(name) + " = " + fmt(c) + " has a component outside [0, 1]");
  }
  return std::nullopt;
}

Image blank_image(std::string name, std::uint32_t size, bool srgb) {
  Image image;
  image.name = std::move(name);
  image.width = size;
  image.height = size;
  image.rgba8.assign(static_cast<std::size_t>(size) * size * 4u, 255u);
  image.srgb = srgb;
  return image;
}

std::uint8_t to_byte(float c) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

void put(Image& image, std::uint32_t x, std::uint32_t y, glm::vec3 c) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4u;
  image.rgba8[i + 0] = to_byte(c.r);
  image.rgba8[i + 1] = to_byte(c.g);
  image.rgba8[i + 2] = to_byte(c.b);
}

// A small integer hash (lowbias32): good avalanche, identical on every platform.
std::uint32_t hash(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float unit(std::uint32_t a, std::uint32_t b = 0, std::uint32_t c = 0) {
  return unit_hash(a, b, c);
}

} // namespace

float unit_hash(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const std::uint32_t h = hash(a ^ hash(b ^ hash(c + 0x9e3779b9u)));
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

Result<Image> make_checker_image(std::uint32_t size, std::uint32_t cells, glm::vec3 a,
                                 glm::vec3 b) {
  constexpr const char* fn = "make_checker_image";
  if (auto e = check_size(fn, size)) {
    return *e;
  }
  if (cells < 1 || cells > size) {
    return bad(fn, "cells = " + std::to_string(cells) +
                       " is out of range [1, size = " + std::to_string(size) + "]");
  }
  if (auto e = check_colour(fn, "a", a)) {
    return *e;
  }
  if (auto e = check_colour(fn, "b", b)) {
    return *e;
  }
  Image image = blank_image("checker", size, true);
  for (std::uint32_t y = 0; y < size; ++y) {
    const std::uint64_t cy = std::uint64_t{y} * cells / size;
    for (std::uint32_t x = 0; x < size; ++x) {
      const std::uint64_t cx = std::uint64_t{x} * cells / size;
      put(image, x, y, (cx + cy) % 2 == 0 ? a : b);
    }
  }
  return image;
}

Result<Image> make_brick_image(std::uint32_t size, const BrickPattern& p) {
  constexpr const char* fn = "make_brick_image";
  if (auto e = check_size(fn, size)) {
    return *e;
  }
  if (p.columns < 1 || size < 4u * p.columns) {
    return bad(fn, "pattern.columns = " + std::to_string(p.columns) +
                       " must be >= 1 and <= size/4 = " + std::to_string(size / 4));
  }
  if (p.rows < 2 || p.rows % 2 != 0 || size < 4u * p.rows) {
    return bad(fn, "pattern.rows = " + std::to_string(p.rows) +
                       " must be even, >= 2 and <= size/4 = " + std::to_string(size / 4));
  }
  if (!(p.row_offset >= 0.0f && p.row_offset < 1.0f)) {
    return bad(fn, "pattern.row_offset = " + fmt(p.row_offset) + " is out of range [0, 1)");
  }
  if (!(p.mortar >= 0.0f && p.mortar < 0.5f)) {
    return bad(fn, "pattern.mortar = " + fmt(p.mortar) + " is out of range [0, 0.5)");
  }
  if (!(p.variation >= 0.0f && p.variation <= 1.0f)) {
    return bad(fn, "pattern.variation = " + fmt(p.variation) + " is out of range [0, 1]");
  }
  if (auto e = check_colour(fn, "pattern.brick", p.brick)) {
    return *e;
  }
  if (auto e = check_colour(fn, "pattern.joint", p.joint)) {
    return *e;
  }
  Image image = blank_image("bricks", size, true);
  const float brick_w = static_cast<float>(size) / static_cast<float>(p.columns); // pixels
  const float brick_h = static_cast<float>(size) / static_cast<float>(p.rows);
  const float half_joint = 0.5f * p.mortar * brick_h; // pixels, same width both ways
  for (std::uint32_t y = 0; y < size; ++y) {
    const float fy = (static_cast<float>(y) + 0.5f) / brick_h;
    const auto row = static_cast<std::uint32_t>(fy);
    const float ly = fy - static_cast<float>(row);
    const float shift = (row % 2 == 1) ? p.row_offset : 0.0f;
    for (std::uint32_t x = 0; x < size; ++x) {
      const float fx = (static_cast<float>(x) + 0.5f) / brick_w + shift;
      const auto col_unwrapped = static_cast<std::uint32_t>(fx);
      const float lx = fx - static_cast<float>(col_unwrapped);
      const std::uint32_t col = col_unwrapped % p.columns; // wraps: the row is periodic
      const float edge =
          std::min(std::min(lx, 1.0f - lx) * brick_w, std::min(ly, 1.0f - ly) * brick_h);
      glm::vec3 c;
      if (edge < half_joint) {
        c = p.joint * (1.0f - 0.08f * unit(p.seed, x, y + 7919u * size));
      } else {
        const float jitter = p.variation * (2.0f * unit(p.seed, row, col) - 1.0f);
        const float grain = 0.25f * p.variation * (2.0f * unit(p.seed + 1u, x, y) - 1.0f);
        c = p.brick * (1.0f + jitter + grain);
      }
      put(image, x, y, c);
    }
  }
  return image;
}

Result<Image> make_noise_normal_map(std::uint32_t size, float strength, std::uint32_t seed) {
  constexpr const char* fn = "make_noise_normal_map";
  if (auto e = check_size(fn, size)) {
    return *e;
  }
  if (!(std::isfinite(strength) && strength >= 0.0f && strength <= 16.0f)) {
    return bad(fn, "strength = " + fmt(strength) + " is out of range [0, 16]");
  }
  // Waves sin(2pi (fx u + fy v) + phase) with integer (fx, fy) repeat exactly over the unit
  // square, which makes the map tileable. Amplitude ~ 1/|f| gives every wave the same slope,
  // a gentle spectrum; the amplitudes are normalised so the slopes sum to 1 (|grad h| <= 1).
  struct Wave {
    float fx, fy, amplitude, phase;
  };
  constexpr int wave_count = 16;
  Wave waves[wave_count];
  float slope_sum = 0.0f;
  for (int k = 0; k < wave_count; ++k) {
    const auto ku = static_cast<std::uint32_t>(k);
    int fx = 0, fy = 0;
    for (std::uint32_t attempt = 0; fx == 0 && fy == 0; ++attempt) {
      fx = static_cast<int>(unit(seed, ku, 2 * attempt) * 17.0f) - 8;
      fy = static_cast<int>(unit(seed, ku, 2 * attempt + 1) * 17.0f) - 8;
    }
    const float f = std::sqrt(static_cast<float>(fx * fx + fy * fy));
    waves[k] = {static_cast<float>(fx), static_cast<float>(fy), 1.0f / f,
                2.0f * pi * unit(seed, ku, 1000u)};
    slope_sum += 2.0f * pi * f * waves[k].amplitude;
  }
  Image image = blank_image("noise_normal", size, false);
  for (std::uint32_t y = 0; y < size; ++y) {
    const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
    for (std::uint32_t x = 0; x < size; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
      float dh_du = 0.0f, dh_dv = 0.0f;
      for (const Wave& w : waves) {
        const float c =
            w.amplitude * 2.0f * pi * std::cos(2.0f * pi * (w.fx * u + w.fy * v) + w.phase);
        dh_du += c * w.fx;
        dh_dv += c * w.fy;
      }
      dh_du *= strength / slope_sum;
      dh_dv *= strength / slope_sum;
      // v grows downward while the normal map's +Y points up: d/dv_up = -d/dv.
      const glm::vec3 n = glm::normalize(glm::vec3(-dh_du, dh_dv, 1.0f));
      put(image, x, y, n * 0.5f + 0.5f);
    }
  }
  return image;
}

} // namespace snell

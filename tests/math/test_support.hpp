// Shared helpers of the math tests: deterministic random inputs and tolerant comparisons.
#pragma once

#include <snell/math.hpp>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <random>

namespace snell::test {

/// A fixed-seed generator: every run tests the same inputs, so failures reproduce.
class Random {
public:
  explicit Random(unsigned seed) : engine_(seed) {}
  float uniform(float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(engine_);
  }
  glm::vec3 vec3(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  /// A uniformly distributed unit vector.
  glm::vec3 unit() {
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
      const glm::vec3 v(n(engine_), n(engine_), n(engine_));
      const float len = glm::length(v);
      if (len > 1e-3f) {
        return v / len;
      }
    }
  }

private:
  std::mt19937 engine_;
};

inline bool near(float a, float b, float tol) {
  return std::fabs(a - b) <= tol;
}

inline bool near(glm::vec3 a, glm::vec3 b, float tol) {
  return near(a.x, b.x, tol) && near(a.y, b.y, tol) && near(a.z, b.z, tol);
}

inline bool near(const glm::mat4& a, const glm::mat4& b, float tol) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!near(a[c][r], b[c][r], tol)) {
        return false;
      }
    }
  }
  return true;
}

inline glm::vec3 transform_point(const glm::mat4& m, glm::vec3 p) {
  const glm::vec4 h = m * glm::vec4(p, 1.0f);
  return glm::vec3(h) / h.w;
}

} // namespace snell::test

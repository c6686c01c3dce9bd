#include "test_support.hpp"

#include <limits>

using namespace snell;
using snell::test::near;

namespace {
constexpr DepthRange kRanges[] = {DepthRange::zero_to_one, DepthRange::minus_one_to_one,
                                  DepthRange::one_to_zero};
constexpr float kInf = std::numeric_limits<float>::infinity();

float ndc_depth(const glm::mat4& proj, float view_distance) {
  const glm::vec4 c = proj * glm::vec4(0.3f, -0.2f, -view_distance, 1.0f);
  return c.z / c.w;
}
} // namespace

TEST_CASE("depth range constants") {
  CHECK(near_depth(DepthRange::zero_to_one) == 0.0f);
  CHECK(far_depth(DepthRange::zero_to_one) == 1.0f);
  CHECK(near_depth(DepthRange::minus_one_to_one) == -1.0f);
  CHECK(far_depth(DepthRange::minus_one_to_one) == 1.0f);
  CHECK(near_depth(DepthRange::one_to_zero) == 1.0f);
  CHECK(far_depth(DepthRange::one_to_zero) == 0.0f);
  CHECK(depth_range_of(ClipConvention::opengl) == DepthRange::minus_one_to_one);
  CHECK(depth_range_of(ClipConvention::vulkan) == DepthRange::zero_to_one);
  CHECK(depth_range_of(ClipConvention::d3d) == DepthRange::zero_to_one);
}

TEST_CASE("perspective maps near and far to the range's depths, monotonically") {
  for (const DepthRange range : kRanges) {
    CAPTURE(static_cast<int>(range));
    const glm::mat4 p = perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f, range);
    CHECK(ndc_depth(p, 0.1f) == doctest::Approx(near_depth(range)).epsilon(1e-4));
    CHECK(ndc_depth(p, 100.0f) == doctest::Approx(far_depth(range)).epsilon(1e-4));
    const float mid = ndc_depth(p, 10.0f);
    CHECK(std::min(near_depth(range), far_depth(range)) < mid);
    CHECK(mid < std::max(near_depth(range), far_depth(range)));
    // The field of view: a point at the top edge of the view lands at NDC y = 1, clip w = distance.
    const glm::vec4 top = p * glm::vec4(0.0f, std::tan(glm::radians(30.0f)) * 5.0f, -5.0f, 1.0f);
    CHECK(top.y / top.w == doctest::Approx(1.0f));
    CHECK(top.w == doctest::Approx(5.0f));

    const glm::mat4 inf = perspective(glm::radians(60.0f), 1.0f, 0.1f, kInf, range);
    CHECK(ndc_depth(inf, 0.1f) == doctest::Approx(near_depth(range)).epsilon(1e-5));
    CHECK(ndc_depth(inf, 1e7f) == doctest::Approx(far_depth(range)).epsilon(1e-4));
    // The infinite matrix is the limit of finite ones.
    const glm::mat4 huge = perspective(glm::radians(60.0f), 1.0f, 0.1f, 1e9f, range);
    CHECK(near(inf, huge, 1e-5f));
  }
}

TEST_CASE("perspective ignores GLM_FORCE_DEPTH_ZERO_TO_ONE") {
  // This file is compiled with and without the macro; the result must not change.
  const glm::mat4 p = perspective(glm::radians(90.0f), 1.0f, 1.0f, 3.0f, DepthRange::zero_to_one);
  CHECK(p[2][2] == doctest::Approx(-1.5f));
  CHECK(p[3][2] == doctest::Approx(-1.5f));
  const glm::mat4 gl =
      perspective(glm::radians(90.0f), 1.0f, 1.0f, 3.0f, DepthRange::minus_one_to_one);
  CHECK(gl[2][2] == doctest::Approx(-2.0f));
  CHECK(gl[3][2] == doctest::Approx(-3.0f));
}

TEST_CASE("flip_clip_y negates clip y only and is an involution") {
  const glm::mat4 p = perspective(glm::radians(70.0f), 1.5f, 0.5f, 50.0f, DepthRange::zero_to_one);
  const glm::mat4 f = flip_clip_y(p);
  CHECK(f[1][1] == -p[1][1]);
  CHECK(flip_clip_y(f) == p);
  const glm::vec4 v(1.0f, 2.0f, -7.0f, 1.0f);
  const glm::vec4 a = p * v;
  const glm::vec4 b = f * v;
  CHECK(b.x == a.x);
  CHECK(b.y == -a.y);
  CHECK(b.z == a.z);
  CHECK(b.w == a.w);
}

TEST_CASE("look_at: right-handed orthonormal view, target on the -Z axis") {
  test::Random rng(20);
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 eye = rng.vec3(-10, 10);
    const glm::vec3 target = rng.vec3(-10, 10);
    const glm::mat4 v = look_at(eye, target, {0, 1, 0});
    CHECK(glm::determinant(v) == doctest::Approx(1.0f).epsilon(1e-4));
    CHECK(near(test::transform_point(v, eye), glm::vec3(0), 1e-4f));
    const glm::vec3 t = test::transform_point(v, target);
    CHECK(near(t.x, 0.0f, 1e-4f));
    CHECK(near(t.y, 0.0f, 1e-4f));
    CHECK(t.z == doctest::Approx(-glm::length(target - eye)).epsilon(1e-4));
    // World up stays in the upper half of the view.
    CHECK(glm::vec3(v * glm::vec4(0, 1, 0, 0)).y >= -1e-6f);
  }
  // Looking straight down: up parallel to the view direction still gives a valid view.
  const glm::mat4 down = look_at({0, 10, 0}, {0, 0, 0}, {0, 1, 0});
  CHECK(glm::determinant(down) == doctest::Approx(1.0f).epsilon(1e-5));
  const glm::mat4 same = look_at({1, 2, 3}, {1, 2, 3}, {0, 1, 0});
  CHECK(glm::determinant(same) == doctest::Approx(1.0f).epsilon(1e-5));
}

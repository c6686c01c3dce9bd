// Axis-aligned boxes and the conservative culling tests, each checked against brute force over
// the box's corners or random points inside it (independently of the functions under test).
#include "test_support.hpp"

#include <algorithm>

using namespace snell;
using snell::test::near;

namespace {

glm::mat4 random_affine(test::Random& rng) {
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c) {
    m[c] = glm::vec4(rng.vec3(-2.0f, 2.0f), 0.0f);
  }
  m[3] = glm::vec4(rng.vec3(-10.0f, 10.0f), 1.0f);
  return m;
}

Aabb random_box(test::Random& rng) {
  const glm::vec3 a = rng.vec3(-8.0f, 8.0f);
  const glm::vec3 b = rng.vec3(-8.0f, 8.0f);
  return Aabb{glm::min(a, b), glm::max(a, b)};
}

glm::vec3 point_in(const Aabb& box, test::Random& rng) {
  return {rng.uniform(box.min.x, box.max.x), rng.uniform(box.min.y, box.max.y),
          rng.uniform(box.min.z, box.max.z)};
}

/// Inside the clip volume restricted to `rect` (NDC), depth [0, 1]: the definition.
bool inside_clip(glm::vec4 c, glm::vec4 rect) {
  return c.w > 0.0f && c.x >= rect.x * c.w && c.x <= rect.z * c.w && c.y >= rect.y * c.w &&
         c.y <= rect.w * c.w && c.z >= 0.0f && c.z <= c.w;
}

} // namespace

TEST_CASE("Aabb: the default box is empty, expand grows it to hold its points") {
  Aabb box;
  CHECK(is_empty(box));
  box = expand(box, {1, 2, 3});
  CHECK_FALSE(is_empty(box));
  CHECK(box.min == glm::vec3(1, 2, 3));
  box = expand(box, {-1, 5, 0});
  CHECK(box.min == glm::vec3(-1, 2, 0));
  CHECK(box.max == glm::vec3(1, 5, 3));
  CHECK(corner(box, 0) == box.min);
  CHECK(corner(box, 7) == box.max);
  CHECK(corner(box, 5) == glm::vec3(1, 2, 3));
}

TEST_CASE("transform_aabb: exactly the bounds of the eight transformed corners") {
  test::Random rng(11);
  for (int i = 0; i < 500; ++i) {
    const Aabb box = random_box(rng);
    const glm::mat4 m = random_affine(rng);
    Aabb brute;
    for (int k = 0; k < 8; ++k) {
      brute = expand(brute, glm::vec3(m * glm::vec4(corner(box, k), 1.0f)));
    }
    const Aabb t = transform_aabb(box, m);
    CHECK(near(t.min, brute.min, 1e-4f));
    CHECK(near(t.max, brute.max, 1e-4f));
  }
  CHECK(is_empty(transform_aabb(Aabb{}, glm::mat4(2.0f))));
}

TEST_CASE("aabb_below_plane: true exactly when every corner is on the negative side") {
  test::Random rng(12);
  int below = 0;
  for (int i = 0; i < 2000; ++i) {
    const Aabb box = random_box(rng);
    const Plane plane{rng.unit() * rng.uniform(0.1f, 3.0f), rng.uniform(-10.0f, 10.0f)};
    bool all_below = true;
    for (int k = 0; k < 8; ++k) {
      all_below = all_below && glm::dot(plane.normal, corner(box, k)) + plane.d < 0.0f;
    }
    CHECK(aabb_below_plane(box, plane) == all_below);
    below += all_below ? 1 : 0;
  }
  CHECK(below > 200); // both outcomes are exercised
  CHECK(aabb_below_plane(Aabb{}, Plane{}));
  CHECK_FALSE(aabb_below_plane(Aabb{{-1, -1, -1}, {1, 1, 1}}, Plane{{0, 0, 0}, -5.0f}));
}

TEST_CASE("aabb_outside_clip: never rejects a box with a visible point (random views)") {
  test::Random rng(13);
  int rejected = 0;
  int kept = 0;
  for (int i = 0; i < 600; ++i) {
    const glm::mat4 proj = flip_clip_y(perspective(rng.uniform(0.3f, 2.0f), rng.uniform(0.5f, 2.0f),
                                                   0.1f, 50.0f, DepthRange::zero_to_one));
    const glm::mat4 view = look_at(rng.vec3(-10, 10), rng.vec3(-3, 3), {0, 1, 0});
    const glm::vec2 lo(rng.uniform(-1.0f, 0.5f), rng.uniform(-1.0f, 0.5f));
    const glm::vec4 rect(lo, lo + glm::vec2(rng.uniform(0.1f, 1.0f), rng.uniform(0.1f, 1.0f)));
    const Aabb box = random_box(rng);
    const glm::mat4 vp = proj * view;
    const bool outside = aabb_outside_clip(box, vp, rect, DepthRange::zero_to_one);
    int visible = 0;
    for (int k = 0; k < 200; ++k) {
      visible += inside_clip(vp * glm::vec4(point_in(box, rng), 1.0f), rect) ? 1 : 0;
    }
    if (outside) {
      ++rejected;
      CHECK(visible == 0);
    } else {
      ++kept;
    }
  }
  // Both outcomes occur, so the soundness check above is not vacuous.
  CHECK(rejected > 50);
  CHECK(kept > 50);
}

TEST_CASE("aabb_outside_clip: behind the eye, beside a scissor rectangle, beyond far") {
  const glm::mat4 proj =
      flip_clip_y(perspective(glm::radians(60.0f), 1.0f, 0.1f, 20.0f, DepthRange::zero_to_one));
  const glm::mat4 view = look_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0});
  const glm::mat4 vp = proj * view;
  const glm::vec4 full(-1, -1, 1, 1);
  const Aabb ahead{{-0.5f, -0.5f, -5.5f}, {0.5f, 0.5f, -4.5f}};
  const Aabb behind{{-0.5f, -0.5f, 4.5f}, {0.5f, 0.5f, 5.5f}};
  const Aabb beyond{{-0.5f, -0.5f, -40.0f}, {0.5f, 0.5f, -30.0f}};
  const Aabb around_eye{{-1, -1, -1}, {1, 1, 1}};
  CHECK_FALSE(aabb_outside_clip(ahead, vp, full, DepthRange::zero_to_one));
  CHECK(aabb_outside_clip(behind, vp, full, DepthRange::zero_to_one));
  CHECK(aabb_outside_clip(beyond, vp, full, DepthRange::zero_to_one));
  CHECK_FALSE(aabb_outside_clip(around_eye, vp, full, DepthRange::zero_to_one));
  // The box ahead projects around the centre: a scissor over the right quarter excludes it.
  CHECK(aabb_outside_clip(ahead, vp, {0.5f, -1.0f, 1.0f, 1.0f}, DepthRange::zero_to_one));
  CHECK_FALSE(aabb_outside_clip(ahead, vp, {-0.1f, -0.1f, 0.1f, 0.1f}, DepthRange::zero_to_one));
  CHECK(aabb_outside_clip(Aabb{}, vp, full, DepthRange::zero_to_one));
  // An OpenGL-style depth range keeps -w <= z: the same box ahead is kept there too.
  const glm::mat4 gl =
      perspective(glm::radians(60.0f), 1.0f, 0.1f, 20.0f, DepthRange::minus_one_to_one) * view;
  CHECK_FALSE(aabb_outside_clip(ahead, gl, full, DepthRange::minus_one_to_one));
  CHECK(aabb_outside_clip(behind, gl, full, DepthRange::minus_one_to_one));
}

TEST_CASE("aabb_outside_clip: an oblique near plane culls what lies below the water") {
  // The reflection pass of water at y = 1: the mirrored camera with the water plane as its
  // oblique near plane removes a box entirely below the water and keeps one above it.
  const Plane water{{0, 1, 0}, -1.0f};
  const glm::mat4 view = reflect_view(look_at({0, 4, 6}, {0, 0, 0}, {0, 1, 0}), water);
  const glm::mat4 proj = flip_clip_y(
      perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f, DepthRange::zero_to_one));
  const glm::mat4 oblique =
      oblique_projection(proj, to_vec4(transform_plane(water, view)), DepthRange::zero_to_one);
  const glm::mat4 vp = oblique * view;
  const glm::vec4 full(-1, -1, 1, 1);
  const Aabb below{{-1, -2, -1}, {1, 0.9f, 1}};
  const Aabb above{{-1, 1.1f, -1}, {1, 2, 1}};
  CHECK(aabb_outside_clip(below, vp, full, DepthRange::zero_to_one));
  CHECK_FALSE(aabb_outside_clip(above, vp, full, DepthRange::zero_to_one));
  CHECK_FALSE(aabb_outside_clip(below, proj * view, full, DepthRange::zero_to_one));
}

#include "test_support.hpp"

#include <glm/gtc/matrix_transform.hpp>

using namespace snell;
using snell::test::near;

TEST_CASE("reflection_matrix: determinant -1, involution, plane fixed, mirror equidistant") {
  test::Random rng(10);
  for (int i = 0; i < 2000; ++i) {
    // Unnormalised input on purpose: reflection_matrix normalises.
    const Plane plane{rng.unit() * rng.uniform(0.1f, 10.0f), rng.uniform(-50.0f, 50.0f)};
    const glm::mat4 r = reflection_matrix(plane);
    CHECK(glm::determinant(r) == doctest::Approx(-1.0f).epsilon(1e-4));
    const Plane unit = normalize(plane);
    // Float error scales with the translation part, 2|d|.
    CHECK(near(r * r, glm::mat4(1.0f), 1e-5f * (1.0f + std::fabs(unit.d))));

    const glm::vec3 on_plane = -unit.d * unit.normal + glm::cross(unit.normal, rng.vec3(-5, 5));
    CHECK(near(test::transform_point(r, on_plane), on_plane, 1e-3f));

    const glm::vec3 p = rng.vec3(-30, 30);
    const glm::vec3 m = test::transform_point(r, p);
    // Equidistant on opposite sides, and the segment p-m is along the normal.
    CHECK(signed_distance(unit, m) == doctest::Approx(-signed_distance(unit, p)).epsilon(1e-3));
    CHECK(glm::length(glm::cross(m - p, unit.normal)) <= 1e-3f * (1.0f + glm::length(m - p)));
    CHECK(near(reflect_point(plane, p), m, 1e-3f));
    // Directions mirror like GLSL reflect.
    const glm::vec3 v = rng.unit();
    CHECK(near(reflect_direction(plane, v), glm::reflect(v, unit.normal), 1e-5f));
  }
}

TEST_CASE("reflection across the water plane y = h maps y to 2h - y") {
  const Plane water{{0, 1, 0}, -2.0f};
  const glm::mat4 r = reflection_matrix(water);
  CHECK(near(test::transform_point(r, {1.0f, 5.0f, -3.0f}), {1.0f, -1.0f, -3.0f}, 1e-6f));
  CHECK(near(test::transform_point(r, {0.0f, 2.0f, 7.0f}), {0.0f, 2.0f, 7.0f}, 1e-6f));
}

TEST_CASE("degenerate plane reflects nothing") {
  const Plane zero{{0, 0, 0}, 1.0f};
  CHECK(reflection_matrix(zero) == glm::mat4(1.0f));
  CHECK(reflect_point(zero, {1, 2, 3}) == glm::vec3(1, 2, 3));
}

TEST_CASE("reflect_view: the mirrored camera sees p where the camera sees p's mirror image") {
  test::Random rng(11);
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 eye = rng.vec3(-10, 10) + glm::vec3(0, 12, 0);
    const glm::mat4 view = look_at(eye, rng.vec3(-5, 5), {0, 1, 0});
    const Plane plane = plane_from_point_normal({0, rng.uniform(-2.0f, 2.0f), 0}, {0, 1, 0});
    const glm::mat4 mirrored = reflect_view(view, plane);
    CHECK(glm::determinant(mirrored) == doctest::Approx(-1.0f).epsilon(1e-3));
    const glm::vec3 p = rng.vec3(-10, 10);
    CHECK(near(test::transform_point(mirrored, p),
               test::transform_point(view, reflect_point(plane, p)), 1e-3f));
    // The mirrored eye: the point that the mirrored view maps to the origin.
    const glm::vec3 mirrored_eye = test::transform_point(glm::inverse(mirrored), glm::vec3(0));
    CHECK(near(mirrored_eye, reflect_point(plane, eye), 1e-3f));
  }
}

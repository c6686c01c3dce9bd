#include "test_support.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

using namespace snell;
using snell::test::near;

TEST_CASE("Plane defaults to y = 0 with +Y normal") {
  const Plane p;
  CHECK(p.normal == glm::vec3(0, 1, 0));
  CHECK(p.d == 0.0f);
  CHECK_FALSE(is_degenerate(p));
}

TEST_CASE("water plane y = h is {(0,1,0), -h}") {
  const Plane water = plane_from_point_normal({3.0f, 2.5f, -7.0f}, {0.0f, 4.0f, 0.0f});
  CHECK(near(water.normal, {0, 1, 0}, 1e-7f));
  CHECK(water.d == doctest::Approx(-2.5f));
  CHECK(signed_distance(water, {0.0f, 3.5f, 0.0f}) == doctest::Approx(1.0f));
  CHECK(signed_distance(water, {9.0f, 0.5f, 9.0f}) == doctest::Approx(-2.0f));
  CHECK(to_vec4(water) == glm::vec4(0.0f, 1.0f, 0.0f, water.d));
}

TEST_CASE("plane_from_point_normal: the point lies on the plane, normal is unit") {
  test::Random rng(1);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 point = rng.vec3(-100, 100);
    const glm::vec3 normal = rng.unit() * rng.uniform(0.01f, 50.0f);
    const Plane p = plane_from_point_normal(point, normal);
    CHECK(glm::length(p.normal) == doctest::Approx(1.0f).epsilon(1e-6));
    CHECK(near(signed_distance(p, point), 0.0f, 1e-4f));
    // Positive side is where the normal points.
    CHECK(signed_distance(p, point + normal) > 0.0f);
  }
}

TEST_CASE("degenerate planes are explicit, never NaN") {
  const Plane zero = plane_from_point_normal({1, 2, 3}, {0, 0, 0});
  CHECK(is_degenerate(zero));
  CHECK(zero.normal == glm::vec3(0));
  CHECK(zero.d == 0.0f);
  CHECK(is_degenerate(normalize(zero)));
  CHECK(is_degenerate(Plane{{std::numeric_limits<float>::quiet_NaN(), 1, 0}, 0}));
  CHECK(is_degenerate(Plane{{0, 1, 0}, std::numeric_limits<float>::infinity()}));
  CHECK(is_degenerate(transform_plane(zero, glm::mat4(1.0f))));
  // A singular transform (projection onto a plane) cannot map planes.
  glm::mat4 singular(1.0f);
  singular[1][1] = 0.0f;
  CHECK(is_degenerate(transform_plane(Plane{}, singular)));
}

TEST_CASE("normalize keeps the point set and scales the offset") {
  const Plane p = normalize(Plane{{0.0f, 0.0f, 2.0f}, 4.0f});
  CHECK(near(p.normal, {0, 0, 1}, 1e-7f));
  CHECK(p.d == doctest::Approx(2.0f));
  const Plane q = plane_from_vec4({0.0f, 0.0f, 2.0f, 4.0f});
  CHECK(q.normal == glm::vec3(0, 0, 2));
}

TEST_CASE("transform_plane agrees with transforming three points of the plane") {
  test::Random rng(2);
  for (int i = 0; i < 2000; ++i) {
    const Plane plane = plane_from_point_normal(rng.vec3(-10, 10), rng.unit());
    // A random affine transform with non-uniform scale and shear (not a rotation only), so the
    // inverse-transpose matters.
    glm::mat4 m(1.0f);
    m = glm::translate(m, rng.vec3(-20, 20));
    m = glm::rotate(m, rng.uniform(0.0f, 6.28f), rng.unit());
    m = glm::scale(
        m, glm::vec3(rng.uniform(0.2f, 5.0f), rng.uniform(0.2f, 5.0f), rng.uniform(-5.0f, -0.2f)));
    m[1][0] += rng.uniform(-0.5f, 0.5f);
    const Plane moved = transform_plane(plane, m);
    REQUIRE_FALSE(is_degenerate(moved));
    CHECK(glm::length(moved.normal) == doctest::Approx(1.0f).epsilon(1e-5));

    // Three points of the plane: an origin and two tangent directions.
    const glm::vec3 n = plane.normal;
    const glm::vec3 t1 = glm::normalize(
        glm::cross(n, std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 t2 = glm::cross(n, t1);
    const glm::vec3 o = -plane.d * n;
    for (const glm::vec3 p : {o, o + 3.0f * t1, o - 2.0f * t2}) {
      const glm::vec3 q = test::transform_point(m, p);
      CHECK(near(signed_distance(moved, q), 0.0f, 2e-3f * (1.0f + glm::length(q))));
    }
    // Orientation: a point on the positive side stays on the positive side.
    CHECK(signed_distance(moved, test::transform_point(m, o + n)) > 0.0f);
  }
}

#include "test_support.hpp"

using namespace snell;
using snell::test::near;

namespace {
constexpr CubeFace kFaces[] = {CubeFace::pos_x, CubeFace::neg_x, CubeFace::pos_y,
                               CubeFace::neg_y, CubeFace::pos_z, CubeFace::neg_z};
}

TEST_CASE("CubeFace values are Vulkan array layers") {
  CHECK(static_cast<int>(CubeFace::pos_x) == 0);
  CHECK(static_cast<int>(CubeFace::neg_x) == 1);
  CHECK(static_cast<int>(CubeFace::pos_y) == 2);
  CHECK(static_cast<int>(CubeFace::neg_y) == 3);
  CHECK(static_cast<int>(CubeFace::pos_z) == 4);
  CHECK(static_cast<int>(CubeFace::neg_z) == 5);
  const CubeTexel t;
  CHECK(t.face == CubeFace::pos_x);
  CHECK(t.uv == glm::vec2(0.5f));
}

TEST_CASE("direction_to_cube follows the Vulkan face-selection table") {
  struct Row {
    glm::vec3 dir;
    CubeFace face;
    glm::vec2 uv;
  };
  // Directions with components (major, 0.5, 0.25) permuted: sc and tc read off the table.
  const Row rows[] = {
      {{1.0f, 0.5f, 0.25f}, CubeFace::pos_x, {0.5f * -0.25f + 0.5f, 0.5f * -0.5f + 0.5f}},
      {{-1.0f, 0.5f, 0.25f}, CubeFace::neg_x, {0.5f * 0.25f + 0.5f, 0.5f * -0.5f + 0.5f}},
      {{0.5f, 1.0f, 0.25f}, CubeFace::pos_y, {0.5f * 0.5f + 0.5f, 0.5f * 0.25f + 0.5f}},
      {{0.5f, -1.0f, 0.25f}, CubeFace::neg_y, {0.5f * 0.5f + 0.5f, 0.5f * -0.25f + 0.5f}},
      {{0.5f, 0.25f, 1.0f}, CubeFace::pos_z, {0.5f * 0.5f + 0.5f, 0.5f * -0.25f + 0.5f}},
      {{0.5f, 0.25f, -1.0f}, CubeFace::neg_z, {0.5f * -0.5f + 0.5f, 0.5f * -0.25f + 0.5f}},
  };
  for (const Row& row : rows) {
    const CubeTexel t = direction_to_cube(row.dir * 3.0f); // length does not matter
    CHECK(t.face == row.face);
    CHECK(near(t.uv.x, row.uv.x, 1e-6f));
    CHECK(near(t.uv.y, row.uv.y, 1e-6f));
  }
  CHECK(direction_to_cube(glm::vec3(0)).face == CubeFace::pos_x);
  CHECK(direction_to_cube({1, 1, 1}).face == CubeFace::pos_x); // ties: X, then Y, then Z
  CHECK(direction_to_cube({0, -1, 1}).face == CubeFace::neg_y);
}

TEST_CASE("10,000 random directions round-trip through direction_to_cube / cube_to_direction") {
  test::Random rng(60);
  int per_face[6] = {};
  for (int i = 0; i < 10000; ++i) {
    const glm::vec3 d = rng.unit();
    const CubeTexel t = direction_to_cube(d);
    CHECK(t.uv.x >= 0.0f);
    CHECK(t.uv.x <= 1.0f);
    CHECK(t.uv.y >= 0.0f);
    CHECK(t.uv.y <= 1.0f);
    CHECK(near(cube_to_direction(t.face, t.uv), d, 1e-5f));
    ++per_face[static_cast<int>(t.face)];
  }
  for (const int n : per_face) {
    CHECK(n > 1300); // each face gets about 1/6
  }
  // And the other way: texel -> direction -> texel.
  for (const CubeFace f : kFaces) {
    for (int i = 0; i < 500; ++i) {
      const glm::vec2 uv(rng.uniform(0.001f, 0.999f), rng.uniform(0.001f, 0.999f));
      const CubeTexel t = direction_to_cube(cube_to_direction(f, uv));
      CHECK(t.face == f);
      CHECK(near(t.uv.x, uv.x, 1e-5f));
      CHECK(near(t.uv.y, uv.y, 1e-5f));
    }
  }
}

TEST_CASE("each face's view + projection lands directions where direction_to_cube says") {
  test::Random rng(61);
  const glm::vec3 center(1.5f, -2.0f, 0.75f);
  for (const DepthRange range :
       {DepthRange::zero_to_one, DepthRange::minus_one_to_one, DepthRange::one_to_zero}) {
    const glm::mat4 proj = cube_face_projection(0.1f, 100.0f, range);
    for (const CubeFace f : kFaces) {
      const glm::mat4 vp = proj * cube_face_view(center, f);
      CHECK(glm::determinant(cube_face_view(center, f)) == doctest::Approx(1.0f).epsilon(1e-5));
      // The face's centre direction lands on the centre of the image.
      const glm::vec4 c = vp * glm::vec4(center + 5.0f * cube_face_forward(f), 1.0f);
      CHECK(near(c.x / c.w, 0.0f, 1e-6f));
      CHECK(near(c.y / c.w, 0.0f, 1e-6f));
      CHECK(cube_face_forward(f) == cube_to_direction(f, glm::vec2(0.5f)));
    }
    for (int i = 0; i < 3000; ++i) {
      const glm::vec3 d = rng.unit();
      const CubeTexel t = direction_to_cube(d);
      const glm::vec4 c = proj * cube_face_view(center, t.face) *
                          glm::vec4(center + rng.uniform(0.5f, 50.0f) * d, 1.0f);
      REQUIRE(c.w > 0.0f);
      const glm::vec2 uv = 0.5f * glm::vec2(c.x, c.y) / c.w + 0.5f; // standard viewport
      CHECK(near(uv.x, t.uv.x, 1e-5f));
      CHECK(near(uv.y, t.uv.y, 1e-5f));
      // ... and lies inside that face's frustum.
      CHECK(std::fabs(c.z / c.w - 0.5f * (near_depth(range) + far_depth(range))) <=
            0.5f * std::fabs(far_depth(range) - near_depth(range)) + 1e-5f);
    }
  }
}

TEST_CASE("a flipped projection puts captures in the wrong place on every face") {
  // Documents the design note: negating [1][1] mirrors every face vertically, and negating the
  // up vectors as well does not repair it (that also mirrors x).
  const glm::mat4 proj = cube_face_projection(0.1f, 10.0f, DepthRange::zero_to_one);
  const glm::mat4 flipped = flip_clip_y(proj);
  test::Random rng(62);
  for (const CubeFace f : kFaces) {
    int wrong_flipped = 0;
    int wrong_negated_up = 0;
    for (int i = 0; i < 200; ++i) {
      const glm::vec2 uv(rng.uniform(0.05f, 0.45f), rng.uniform(0.05f, 0.45f)); // off-centre
      const glm::vec3 d = cube_to_direction(f, uv);
      const glm::vec4 a = flipped * cube_face_view(glm::vec3(0), f) * glm::vec4(d, 1.0f);
      const glm::vec2 ua = 0.5f * glm::vec2(a) / a.w + 0.5f;
      wrong_flipped += !(near(ua.x, uv.x, 1e-3f) && near(ua.y, uv.y, 1e-3f));
      const glm::mat4 neg_up_view = look_at(glm::vec3(0), cube_face_forward(f), -cube_face_up(f));
      const glm::vec4 b = flipped * neg_up_view * glm::vec4(d, 1.0f);
      const glm::vec2 ub = 0.5f * glm::vec2(b) / b.w + 0.5f;
      wrong_negated_up += !(near(ub.x, uv.x, 1e-3f) && near(ub.y, uv.y, 1e-3f));
    }
    CHECK(wrong_flipped == 200);
    CHECK(wrong_negated_up == 200);
  }
}

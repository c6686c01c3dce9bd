#include "test_support.hpp"

using namespace snell;
using snell::test::near;

namespace {
constexpr ClipConvention kConventions[] = {ClipConvention::vulkan, ClipConvention::opengl,
                                           ClipConvention::d3d};
}

TEST_CASE("project_to_uv: the seeds' D3D formula x/w/2+0.5, -y/w/2+0.5") {
  const glm::vec4 clip(1.0f, 2.0f, 0.5f, 4.0f);
  const glm::vec2 uv = project_to_uv(clip, ClipConvention::d3d);
  CHECK(uv.x == doctest::Approx(1.0f / 4.0f / 2.0f + 0.5f));
  CHECK(uv.y == doctest::Approx(-2.0f / 4.0f / 2.0f + 0.5f));
}

TEST_CASE("project_to_uv: frustum corners land on texture corners per convention") {
  // Vulkan, standard viewport: NDC y = -1 is the first row (v = 0).
  CHECK(project_to_uv({-1, -1, 0, 1}, ClipConvention::vulkan) == glm::vec2(0, 0));
  CHECK(project_to_uv({1, 1, 0, 1}, ClipConvention::vulkan) == glm::vec2(1, 1));
  // OpenGL: NDC y = -1 is window row 0, t = 0.
  CHECK(project_to_uv({-1, -1, 0, 1}, ClipConvention::opengl) == glm::vec2(0, 0));
  // D3D: NDC y = +1 is the top row, v = 0.
  CHECK(project_to_uv({-1, 1, 0, 1}, ClipConvention::d3d) == glm::vec2(0, 0));
  CHECK(project_to_uv({0, 0, 0, 3}, ClipConvention::d3d) == glm::vec2(0.5f, 0.5f));
}

TEST_CASE("clip_to_uv agrees with project_to_uv and maps depth to [0,1]") {
  test::Random rng(40);
  for (const ClipConvention conv : kConventions) {
    const glm::mat4 b = clip_to_uv(conv);
    const DepthRange range = depth_range_of(conv);
    for (int i = 0; i < 1000; ++i) {
      const float w = rng.uniform(0.1f, 100.0f);
      const float ndc_z = rng.uniform(std::min(near_depth(range), far_depth(range)), 1.0f);
      const glm::vec4 clip(rng.uniform(-1, 1) * w, rng.uniform(-1, 1) * w, ndc_z * w, w);
      const glm::vec4 t = b * clip;
      const glm::vec2 uv = project_to_uv(clip, conv);
      CHECK(near(t.x / t.w, uv.x, 1e-5f));
      CHECK(near(t.y / t.w, uv.y, 1e-5f));
      CHECK(t.w == doctest::Approx(w));
      const float depth01 = t.z / t.w;
      CHECK(depth01 >= -1e-5f);
      CHECK(depth01 <= 1.0f + 1e-5f);
      const float expected = conv == ClipConvention::opengl ? 0.5f * ndc_z + 0.5f : ndc_z;
      CHECK(near(depth01, expected, 1e-5f));
    }
  }
}

TEST_CASE("projective lookup of a point seen by the camera that rendered the texture") {
  // A point on the image's top edge (world up with a y-flipped Vulkan projection) reads row 0.
  const glm::mat4 view = look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  const glm::mat4 proj =
      flip_clip_y(perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f, DepthRange::zero_to_one));
  const glm::vec4 top = proj * view * glm::vec4(0.0f, 5.0f, 0.0f, 1.0f); // 45 degrees up
  const glm::vec2 uv = project_to_uv(top, ClipConvention::vulkan);
  CHECK(uv.x == doctest::Approx(0.5f));
  CHECK(near(uv.y, 0.0f, 1e-6f));
}

// Cube capture: six coloured markers on the six axes land on their faces where
// direction_to_cube predicts, with the per-face path and the multiview path.
#include "cube_markers.hpp"

#include <snell/math.hpp>
#include <snell/toolkit/scene_pass.hpp>

using namespace snell;

namespace {

void check_faces(Context& ctx, const CubeTarget& cube, const std::array<glm::vec3, 6>& offsets,
                 const char* name) {
  test::check_marker_faces(
      [&](std::uint32_t f) {
        auto image = read_cube_face_rgba8(ctx, cube, f);
        REQUIRE(image.has_value());
        test::save_png(*image, std::string(name) + "_face" + std::to_string(f));
        return *image;
      },
      static_cast<float>(cube.size()), offsets);
}

} // namespace

TEST_CASE("cube capture: per-face passes put each marker where direction_to_cube says") {
  test::GpuFixture gpu;
  const glm::vec3 center(0.5f, 1.0f, -0.25f);
  std::array<glm::vec3, 6> offsets;
  const Scene scene = test::six_marker_scene(center, offsets);
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());
  auto cube = CubeTarget::create(
      gpu.ctx(), CubeTargetDesc{.size = 64, .color = ColorFormat::rgba8_unorm, .mips = true});
  REQUIRE(cube.has_value());
  const glm::mat4 proj = cube_face_projection(0.1f, 50.0f, DepthRange::zero_to_one);
  const float clear[4] = {0, 0, 0, 1};
  Result<void> drawn;
  REQUIRE(gpu.ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    cube->begin_capture(cmd);
    for (std::uint32_t f = 0; f < 6; ++f) {
      SceneView v;
      v.view = cube_face_view(center, static_cast<CubeFace>(f));
      v.proj = proj;
      v.eye = center;
      v.layer_mask = layer::all;
      v.flip_front_face = needs_front_face_flip(v.view, v.proj);
      v.extent = {cube->size(), cube->size()};
      v.color_format = to_vk_format(cube->color_format());
      cube->begin_face(cmd, f, clear);
      if (auto r = renderer->draw_scene(cmd, v); !r) {
        drawn = r;
      }
      cube->end_face(cmd);
    }
    cube->end_capture(cmd);
  }));
  CHECK_MESSAGE(drawn.has_value(), drawn.error().message);
  check_faces(gpu.ctx(), *cube, offsets, "cube_per_face");
}

TEST_CASE("cube capture: one multiview pass matches the per-face result") {
  test::GpuFixture gpu;
  const glm::vec3 center(0.0f, 0.0f, 0.0f);
  std::array<glm::vec3, 6> offsets;
  const Scene scene = test::six_marker_scene(center, offsets);
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());
  auto cube = CubeTarget::create(
      gpu.ctx(), CubeTargetDesc{.size = 64, .color = ColorFormat::rgba8_unorm, .mips = false});
  REQUIRE(cube.has_value());
  const glm::mat4 proj = cube_face_projection(0.1f, 50.0f, DepthRange::zero_to_one);
  SceneView v;
  v.proj = proj;
  v.eye = center;
  v.layer_mask = layer::all;
  // Every face view has det +1 and an unflipped projection: one front face for all six.
  v.flip_front_face = needs_front_face_flip(cube_face_view(center, CubeFace::pos_x), proj);
  v.view_mask = 0x3F;
  for (std::size_t f = 0; f < 6; ++f) {
    v.multiview_view_proj[f] = proj * cube_face_view(center, static_cast<CubeFace>(f));
  }
  v.extent = {cube->size(), cube->size()};
  v.color_format = to_vk_format(cube->color_format());
  const float clear[4] = {0, 0, 0, 1};
  Result<void> drawn;
  REQUIRE(gpu.ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    cube->begin_capture(cmd);
    cube->begin_multiview(cmd, clear);
    drawn = renderer->draw_scene(cmd, v);
    cube->end_multiview(cmd);
    cube->end_capture(cmd);
  }));
  CHECK_MESSAGE(drawn.has_value(), drawn.error().message);
  check_faces(gpu.ctx(), *cube, offsets, "cube_multiview");
}

TEST_CASE("cube capture: the toolkit's record_cube_capture, multiview and six passes alike") {
  test::GpuFixture gpu;
  const glm::vec3 center(0.25f, -0.5f, 0.5f);
  std::array<glm::vec3, 6> offsets;
  const Scene scene = test::six_marker_scene(center, offsets);
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());
  for (const CubeCaptureMode mode : {CubeCaptureMode::multiview, CubeCaptureMode::six_pass}) {
    auto cube = CubeTarget::create(gpu.ctx(), CubeTargetDesc{.size = 64, .mips = true});
    REQUIRE(cube.has_value());
    // Samplable before the first capture: cleared, no validation message on readback.
    auto fresh = read_cube_face_rgba8(gpu.ctx(), *cube, 2);
    REQUIRE(fresh.has_value());
    CHECK(test::find_color(*fresh, {0, 0, 0}, 1).count == 64 * 64);
    CubeCapture capture;
    capture.name = "cube";
    capture.center = center;
    capture.z_near = 0.1f;
    capture.z_far = 50.0f;
    capture.layer_mask = layer::all;
    capture.mode = mode;
    Result<void> drawn;
    REQUIRE(gpu.ctx().submit_and_wait(
        [&](VkCommandBuffer cmd) { drawn = record_cube_capture(cmd, *renderer, *cube, capture); }));
    REQUIRE_MESSAGE(drawn.has_value(), drawn.error().message);
    check_faces(gpu.ctx(), *cube, offsets,
                mode == CubeCaptureMode::multiview ? "toolkit_multiview" : "toolkit_six_pass");
  }
  CubeCapture bad;
  bad.z_near = 1.0f;
  bad.z_far = 0.5f;
  auto cube = CubeTarget::create(gpu.ctx(), CubeTargetDesc{.size = 8});
  REQUIRE(cube.has_value());
  Result<void> refused;
  REQUIRE(gpu.ctx().submit_and_wait(
      [&](VkCommandBuffer cmd) { refused = record_cube_capture(cmd, *renderer, *cube, bad); }));
  REQUIRE_FALSE(refused.has_value());
  CHECK(refused.error().message.find("z_near") != std::string::npos);
}

// The out-of-tree plugin's own test: a red marker above the mirror appears where its mirror
// image projects (computed here from the plane, independently of the shader).
#include "gpu_fixture.hpp"

#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/math.hpp>

using namespace snell;

TEST_CASE("probe_mirror: registered with the built-in effects, the marker's mirror image probe") {
  test::GpuFixture gpu;
  EffectRegistry registry;
  REQUIRE(register_builtin_effects(registry).has_value());
  Scene scene = test::empty_dark_scene();
  const glm::vec3 marker(0.5f, 1.0f, -0.5f);
  test::add_object(
      scene, test::make_box_mesh(glm::vec3(0.15f), test::add_emissive_material(scene, {1, 0, 0})),
      marker, layer::reflected); // only in the reflection
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());
  const std::uint32_t w = 160, h = 120;
  auto frame = FrameRenderer::create(
      gpu.ctx(), FrameDesc{.width = w, .height = h, .color = ColorFormat::rgba8_unorm});
  REQUIRE(frame.has_value());
  EffectCreateInfo info;
  info.context = &gpu.ctx();
  info.color_format = frame->target().vk_color_format();
  auto mirror = registry.create("probe_mirror", info);
  REQUIRE_MESSAGE(mirror.has_value(), mirror.error().message);
  CameraDesc camera;
  camera.eye = {0.0f, 3.0f, 4.0f};
  camera.target = {0.0f, 0.0f, 0.0f};
  Effect* effects[] = {mirror->get()};
  auto stats = frame->render(*renderer, camera, 0.0f, effects);
  REQUIRE_MESSAGE(stats.has_value(), stats.error().message);
  REQUIRE(stats->effect_errors.empty());
  auto image = frame->read_color();
  REQUIRE(image.has_value());
  const SceneView view = make_main_view(camera, w, h);
  const glm::vec3 image_point = reflect_point(Plane{{0, 1, 0}, 0.0f}, marker);
  const glm::vec2 expected = test::predict_pixel(view.proj * view.view, image_point, w, h);
  const test::Blob red = test::find_color(*image, {1, 0, 0});
  CAPTURE(expected);
  CAPTURE(red.centroid);
  REQUIRE(red.count > 4);
  CHECK(glm::length(red.centroid - expected) <= 2.0f);
}

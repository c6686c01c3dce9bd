// Glass reflecting a probe (ProbeDirectory): with a dynamic_cubemap probe published, the pane's
// reflection is the probe's capture instead of the analytic sky (lavapipe, validation on).
#include "glass_fixture.hpp"

#include <snell/dynamic_cubemap.hpp>
#include <snell/probe_directory.hpp>

using namespace snell;

// Fails if the glass ignores a published probe (the reflection stays the black sky), samples
// it along a wrong direction (misses the red wall behind the camera that the mirror direction
// of every pane pixel points at), or keeps using it after the probe is gone.
TEST_CASE("glass: the Fresnel reflection uses the nearest published probe") {
  test::GpuFixture gpu;
  test::GlassRig rig;
  rig.scene = test::glass_test_scene(); // black sky and wall
  const int red = test::add_emissive_material(rig.scene, {1.0f, 0.0f, 0.0f});
  // Behind the camera: only a reflection can show it.
  test::add_object(rig.scene, test::make_box_mesh({6.0f, 6.0f, 0.1f}, red), {0.0f, 0.0f, 10.0f});
  rig.camera.eye = {0.0f, 0.0f, 4.0f};
  rig.camera.target = {0.0f, 0.0f, 0.0f};
  rig.init(gpu.ctx());
  GlassParams g;
  g.center = {0.0f, 0.0f, 0.0f};
  g.size = {2.0f, 2.0f};
  g.normal = {0.0f, 0.0f, 1.0f};
  g.debug_view = GlassDebugView::reflection;
  rig.set(g);
  // A pane pixel away from the probe's own (tiny) sphere: the mirror direction there is
  // reflect(P - eye, +z), within 5 degrees of +z, which meets the red wall from the probe.
  const glm::vec3 on_pane(0.4f, 0.3f, 0.0f);
  const glm::vec2 px = test::predict_pixel(rig.view_proj(), on_pane, rig.width, rig.height);
  const auto red_at = [&](const Image& image) {
    const std::size_t i =
        (static_cast<std::size_t>(px.y) * image.width + static_cast<std::size_t>(px.x)) * 4;
    return glm::ivec3(image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2]);
  };
  const glm::ivec3 sky = red_at(rig.render());
  CAPTURE(sky);
  CHECK(sky.r < 30);

  auto created = create_dynamic_cubemap(rig.effect_info(gpu.ctx()));
  GLASS_REQUIRE_OK(created);
  std::unique_ptr<DynamicCubemapEffect> probe = std::move(*created);
  DynamicCubemapParams p;
  p.center = {0.0f, 0.0f, 0.5f};
  p.radius = 0.01f;
  GLASS_REQUIRE_OK(probe->set_params(p));
  Effect* both[] = {probe.get(), rig.glass.get()};
  const glm::ivec3 probed = red_at(rig.render_effects(both));
  CAPTURE(probed);
  CHECK(rig.probes.size() == 1);
  CHECK(probed.r > 150);
  CHECK(probed.g < 40);

  // The probe builds its mip chain for its first capture, then only when asked: smooth glass
  // does not ask (one level published), rough glass does (every level, from the next capture).
  (void)rig.render_effects(both);
  REQUIRE(rig.probes.nearest(p.center) != nullptr);
  CHECK(rig.probes.nearest(p.center)->mip_levels == 1);
  g.roughness = 0.3f;
  rig.set(g);
  (void)rig.render_effects(both); // glass asks during this frame's draw
  (void)rig.render_effects(both); // the probe's next capture builds the chain
  CHECK(rig.probes.nearest(p.center)->mip_levels > 1);

  probe.reset(); // withdrawn: the sky again
  CHECK(rig.probes.size() == 0);
  const glm::ivec3 after = red_at(rig.render());
  CAPTURE(after);
  CHECK(after.r < 30);
}

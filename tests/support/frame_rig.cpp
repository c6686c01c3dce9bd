#include "frame_rig.hpp"

namespace snell::test {

void FrameRig::init_frame(Context& ctx) {
  auto r = SceneRenderer::create(ctx, scene);
  REQUIRE_MESSAGE(r.has_value(), (r ? std::string() : r.error().message));
  renderer.emplace(std::move(*r));
  auto f = FrameRenderer::create(ctx, FrameDesc{.width = width, .height = height, .color = color});
  REQUIRE_MESSAGE(f.has_value(), (f ? std::string() : f.error().message));
  frame.emplace(std::move(*f));
}

EffectCreateInfo FrameRig::effect_info(Context& ctx) {
  EffectCreateInfo info;
  info.context = &ctx;
  info.color_format = frame->target().vk_color_format();
  info.depth_format = frame->target().depth_format();
  info.scene = &scene;
  info.probes = &probes;
  return info;
}

Image FrameRig::render_effects(Span<Effect* const> effects, float time) {
  auto stats = frame->render(*renderer, camera, time, effects, scene.light);
  REQUIRE_MESSAGE(stats.has_value(), (stats ? std::string() : stats.error().message));
  const std::string effect_error =
      stats->effect_errors.empty() ? std::string() : stats->effect_errors.front().message;
  REQUIRE_MESSAGE(stats->effect_errors.empty(), effect_error);
  last_stats = *stats;
  auto image = frame->read_color();
  REQUIRE_MESSAGE(image.has_value(), (image ? std::string() : image.error().message));
  return *image;
}

SceneView FrameRig::main_view() const {
  return make_main_view(camera, width, height);
}

} // namespace snell::test

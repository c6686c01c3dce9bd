// A C++17 host against the installed package: only host-facing headers (no plugin toolkit, no
// C++20), a context on lavapipe, a built-in scene, and water created by name through the
// registry and rendered for one frame. Compiled with -std=c++17 -Wall -Wextra -Wpedantic -Werror.
#include <snell/builtin_scenes.hpp>
#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/scene_renderer.hpp>
#include <snell/water.hpp>

#include <cstdio>
#include <memory>
#include <string>

#if __cplusplus >= 202002L
#error "this consumer must be compiled as C++17"
#endif

namespace {

int fail(const char* what, const snell::Error& e) {
  std::printf("FAIL: %s: %s\n", what, e.message.c_str());
  return 1;
}

} // namespace

int main() {
  snell::ContextDesc cd;
  cd.device = "lavapipe";
  cd.validation = true;
  auto ctx = snell::Context::create(cd);
  if (!ctx) {
    return fail("Context::create", ctx.error());
  }
  auto scene = snell::make_builtin_scene("pool");
  if (!scene) {
    return fail("make_builtin_scene", scene.error());
  }
  auto renderer = snell::SceneRenderer::create(*ctx, *scene);
  if (!renderer) {
    return fail("SceneRenderer::create", renderer.error());
  }
  snell::FrameDesc fd;
  fd.width = 160;
  fd.height = 90;
  auto frame = snell::FrameRenderer::create(*ctx, fd);
  if (!frame) {
    return fail("FrameRenderer::create", frame.error());
  }
  snell::EffectRegistry registry;
  if (auto r = snell::register_builtin_effects(registry); !r) {
    return fail("register_builtin_effects", r.error());
  }
  snell::EffectCreateInfo info;
  info.context = &*ctx;
  info.color_format = frame->target().vk_color_format();
  info.scene = &*scene;
  auto water = registry.create("water", info);
  if (!water) {
    return fail("registry.create(\"water\")", water.error());
  }
  if (auto r = (*water)->set_param("wave_height", 0.5f); !r) {
    return fail("set_param", r.error());
  }
  snell::Effect* effects[] = {water->get()};
  auto stats = frame->render(*renderer, scene->cameras.front(), 0.0f, effects, scene->light);
  if (!stats) {
    return fail("render", stats.error());
  }
  if (!stats->effect_errors.empty()) {
    return fail("water", stats->effect_errors.front());
  }
  if (ctx->validation_error_count() != 0) {
    std::printf("FAIL: %u validation error(s)\n", ctx->validation_error_count());
    return 1;
  }
  std::printf("ok  : a C++17 host rendered water from the registry (%.2f ms GPU, %u snapshot)\n",
              stats->gpu_ms, stats->snapshot_copies);
  return 0;
}

// Test support: what an effect test renders with: a scene, Snell's scene renderer and a
// FrameRenderer. Each plugin's fixture derives its rig from it and adds its effect.
#pragma once

#include "gpu_fixture.hpp"

#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/probe_directory.hpp>
#include <snell/scene_renderer.hpp>

#include <optional>

namespace snell::test {

/// A scene, its renderer and a frame of width x height in `color`.
struct FrameRig {
  Scene scene;
  std::optional<SceneRenderer> renderer;
  std::optional<FrameRenderer> frame;
  FrameStats last_stats; ///< Of the last render_effects().
  ProbeDirectory probes; ///< Handed to effects (EffectCreateInfo::probes).
  CameraDesc camera;
  std::uint32_t width = 256, height = 192;
  ColorFormat color = ColorFormat::rgba8_unorm;

  /// Builds the renderer and the frame; call after scene, camera, size and colour are set.
  void init_frame(Context& ctx);
  /// The create info of an effect drawn into this frame: context, formats, scene, probes.
  [[nodiscard]] EffectCreateInfo effect_info(Context& ctx);
  /// One frame with `effects` (none: the opaque scene) at `time` seconds, read back as RGBA8;
  /// REQUIREs that the frame and every effect succeeded.
  Image render_effects(Span<Effect* const> effects, float time = 0.0f);
  /// The main view the frame uses.
  [[nodiscard]] SceneView main_view() const;
};

} // namespace snell::test

// Snell runtime: frame orchestration for the embedded default host (the CLI and samples):
// offscreen passes, the main pass (scene + effect surfaces), debug thumbnails (seed 004's
// debug window), GPU timestamps, and readback.
#pragma once

#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/images.hpp>
#include <snell/scene.hpp>
#include <snell/scene_source.hpp>

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace snell {

/// Parameters of FrameRenderer::create.
struct FrameDesc {
  std::uint32_t width = 1280;                  ///< Output width in pixels, 1..16384. Default 1280.
  std::uint32_t height = 720;                  ///< Output height in pixels, 1..16384. Default 720.
  ColorFormat color = ColorFormat::rgba8_srgb; ///< Output format. Default rgba8_srgb.
  bool debug_targets = false; ///< Composite thumbnails into the corners. Default false.
};

/// What one rendered frame cost.
struct FrameStats {
  std::vector<PassTime> passes; ///< GPU time of each pass, in order ("frame" is the whole).
  double gpu_ms = 0.0;          ///< GPU time of the whole frame (timestamps).
  double cpu_ms = 0.0;          ///< Wall time from recording to the fence signalling.
};

/// Callbacks through which effects join a frame (issue-4 plugins use them).
struct FrameHooks {
  /// Offscreen passes before the main pass (may call back into the scene source).
  std::function<void(VkCommandBuffer, GpuTimer&, const SceneView& main_view)> offscreen;
  /// Draws inside the main rendering, after the scene.
  std::function<void(VkCommandBuffer, const SceneView& main_view)> in_main;
  /// Extra debug thumbnails, asked for after the main pass (effects create targets lazily).
  std::function<std::vector<DebugTarget>()> debug_targets;
};

/// The main view of a camera for a `width` x `height` output: y-flipped Vulkan projection with
/// depth [0,1] (docs/conventions.md).
[[nodiscard]] SceneView make_main_view(const CameraDesc& camera, std::uint32_t width,
                                       std::uint32_t height);

/// Records, submits and times frames into an owned output target.
class FrameRenderer {
public:
  [[nodiscard]] static Result<FrameRenderer> create(const Context& ctx, const FrameDesc& desc);
  FrameRenderer(FrameRenderer&&) noexcept;
  FrameRenderer& operator=(FrameRenderer&&) noexcept;
  ~FrameRenderer();

  /// Renders one frame of `source` seen by `camera` at `time` seconds and waits for it.
  [[nodiscard]] Result<FrameStats> render(SceneSource& source, const CameraDesc& camera, float time,
                                          const FrameHooks& hooks = {});
  /// Renders one frame with effects: each effect's update() and record_passes() (offscreen,
  /// drawing `source`), the main pass (scene, then each effect's record_draw()), and the
  /// effects' debug targets as thumbnails when enabled. The first effect error is returned.
  [[nodiscard]] Result<FrameStats> render(SceneSource& source, const CameraDesc& camera, float time,
                                          std::span<Effect* const> effects,
                                          const DirectionalLight& light);
  /// The output after render().
  [[nodiscard]] const RenderTarget& target() const;
  /// Reads the output back (RGBA8, sRGB-encoded for the default format).
  [[nodiscard]] Result<Image> read_color() const;

  struct Impl;

private:
  explicit FrameRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace snell

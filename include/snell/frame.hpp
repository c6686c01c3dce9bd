// Snell runtime: frame orchestration for the embedded default host (the CLI and samples):
// offscreen passes, the opaque scene, the scene snapshot, effect surfaces, debug thumbnails
// (seed 004's debug window), GPU timestamps, and readback.
#pragma once

#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/gpu_timer.hpp>
#include <snell/images.hpp>
#include <snell/scene.hpp>
#include <snell/scene_source.hpp>
#include <snell/span.hpp>

#include <memory>
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

/// What one rendered frame cost and what went wrong in it.
struct FrameStats {
  std::vector<PassTime> passes{};    ///< GPU time of each pass, in order ("frame" is the whole).
  double gpu_ms = 0.0;               ///< GPU time of the whole frame (timestamps).
  double cpu_ms = 0.0;               ///< Wall time from recording to the fence signalling.
  std::uint64_t frame_index = 0;     ///< The FrameInfo::frame_index this frame used (1, 2, ...).
  std::uint32_t snapshot_copies = 0; ///< Scene snapshots copied this frame (0 or 1).
  /// Effects skipped this frame because update(), record_passes() or record_draw() failed:
  /// "<type>: <message>" each (code and VkResult kept). The rest of the frame was rendered.
  std::vector<Error> effect_errors{};
};

/// The main view of a camera for a `width` x `height` output: y-flipped Vulkan projection with
/// depth [0,1] (docs/conventions.md).
[[nodiscard]] SceneView make_main_view(const CameraDesc& camera, std::uint32_t width,
                                       std::uint32_t height);

/// Records, submits and times frames into an owned output target, in the frame phases of
/// DESIGN.md: effects' offscreen passes → opaque scene → scene snapshot (once, when an effect
/// wants it) → effect surfaces → debug overlay. Each frame is waited for before render() returns
/// (one frame in flight; effects may still be created with more).
class FrameRenderer {
public:
  [[nodiscard]] static Result<FrameRenderer> create(const Context& ctx, const FrameDesc& desc);
  FrameRenderer(FrameRenderer&&) noexcept;
  FrameRenderer& operator=(FrameRenderer&&) noexcept;
  ~FrameRenderer();

  /// Renders one frame of `source` seen by `camera` at `time` seconds, with `effects` (may be
  /// empty), and waits for it. An effect whose update / record_passes / record_draw fails is
  /// skipped for the rest of the frame and reported in FrameStats::effect_errors. When
  /// `source` is a SceneRenderer, the objects effects draw themselves (Effect::drawn_objects)
  /// are hidden from it. Errors: the scene's own draw failed, or a Vulkan call failed.
  [[nodiscard]] Result<FrameStats> render(SceneSource& source, const CameraDesc& camera, float time,
                                          Span<Effect* const> effects = {},
                                          const DirectionalLight& light = {});
  /// The output after render().
  [[nodiscard]] const RenderTarget& target() const;
  /// Reads the output back (RGBA8, sRGB-encoded for the default format).
  [[nodiscard]] Result<Image> read_color() const;

private:
  struct Impl;
  explicit FrameRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace snell

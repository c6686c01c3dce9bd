// Snell runtime: the embedded default host's forward renderer (a SceneSource).
#pragma once

#include <snell/context.hpp>
#include <snell/scene.hpp>
#include <snell/scene_source.hpp>
#include <snell/span.hpp>

#include <memory>

namespace snell {

/// What the last draw_scene call drew.
struct SceneDrawStats {
  std::uint32_t drawn = 0;  ///< Objects drawn. Default 0.
  std::uint32_t culled = 0; ///< Objects of the view's layers skipped as invisible. Default 0.
};

/// Draws a Scene: ambient + Lambert + normalised Blinn-Phong from one directional light,
/// base colour / normal / emissive textures, alpha mask, and a gradient sky drawn behind
/// everything. Honours SceneView's clip plane (gl_ClipDistance), layer mask, front-face flip
/// and multiview. Pipelines are created lazily per (colour format, depth format, view mask).
/// Textures are sampled trilinearly, with 8x anisotropy on GPUs and none on CPU devices
/// (lavapipe), where anisotropic filtering triples the frame time.
///
/// Culling: an object whose world bounds lie entirely below the view's clip plane, or (single
/// views) entirely outside the view's frustum restricted to `SceneView::scissor`, is not drawn.
/// An oblique projection's near plane is the clip plane, so a mirrored pass skips everything
/// under the mirror; a pass scissored to a small rectangle skips what projects beside it.
///
/// Per-view data lives in a ring of `kMaxViewsInFlight` uniform blocks: at most that many
/// draw_scene calls may be recorded between two waits on the GPU.
class SceneRenderer : public SceneSource {
public:
  static constexpr std::uint32_t kMaxViewsInFlight = 256;

  /// Uploads `scene` (meshes, textures) to the GPU. The scene is copied; the renderer keeps
  /// no reference to it. Errors name the mesh or image that failed.
  [[nodiscard]] static Result<SceneRenderer> create(const Context& ctx, const Scene& scene);

  SceneRenderer(SceneRenderer&&) noexcept;
  SceneRenderer& operator=(SceneRenderer&&) noexcept;
  ~SceneRenderer() override;

  /// Draws the objects in `view.layer_mask` that are not hidden, then the sky. Errors: a
  /// pipeline for the view's formats / view mask cannot be created (vulkan_error).
  [[nodiscard]] Result<void> draw_scene(VkCommandBuffer cmd, const SceneView& view) override;
  /// Leaves out these objects (indices into scene().objects) from now on, in every view: the
  /// ones effects draw with their own shading (Effect::drawn_objects). Out-of-range indices are
  /// ignored. Replaces the previous set; an empty span shows everything again.
  void set_hidden_objects(Span<const int> objects);

  /// Objects drawn and culled by the last draw_scene call (for tests and statistics).
  [[nodiscard]] SceneDrawStats last_draw_stats() const;

  /// The scene as uploaded (objects, cameras, light, anchors).
  [[nodiscard]] const Scene& scene() const;

private:
  struct Impl;
  explicit SceneRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace snell

// Snell: the interface through which effects ask the host to draw its scene (DESIGN: Plugins).
#pragma once

#include <snell/math/plane.hpp>
#include <snell/result.hpp>
#include <snell/scene_types.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <optional>

namespace snell {

/// Everything a SceneSource needs to draw the scene for one view.
struct SceneView {
  glm::mat4 view{1.0f}; ///< World to view (may be mirrored: determinant -1).
  /// View to Vulkan clip space, depth [0,1]: y-flipped for 2D views (see docs/conventions.md),
  /// not flipped for cube faces; may be oblique.
  glm::mat4 proj{1.0f};
  glm::vec3 eye{0.0f};                    ///< World-space eye (mirrored eye for mirrored views).
  std::optional<Plane> clip_plane{};      ///< World plane; only its positive side is drawn.
  std::uint32_t layer_mask = layer::main; ///< Objects drawn: those with (layers & mask) != 0.
  /// Swap the pipeline's front face. True when the view flips winding an odd number of times
  /// (mirrored view XOR unflipped-y projection): use `needs_front_face_flip(view, proj)`.
  bool flip_front_face = false;
  VkExtent2D extent{0, 0};                      ///< Size of the target being rendered.
  VkFormat color_format = VK_FORMAT_UNDEFINED;  ///< Format of the active colour attachment.
  VkFormat depth_format = VK_FORMAT_D32_SFLOAT; ///< Depth attachment format (UNDEFINED: none).
  /// Multiview: 0 for a single view; 0b111111 to draw the six cube faces in one pass, with
  /// `multiview_view_proj[i]` per view (then `view` / `proj` are ignored for positions).
  std::uint32_t view_mask = 0;
  std::array<glm::mat4, 6> multiview_view_proj{}; ///< Per-view matrices when view_mask != 0.
  float time = 0.0f;                              ///< Scene time in seconds (animation).
  /// The pixels of the target the pass keeps (its scissor), for culling: a SceneSource may skip
  /// geometry that projects entirely outside it (Snell's SceneRenderer does). It does not set
  /// the scissor: the caller has (record_scene_pass sets both). Extent 0 x 0: the whole target.
  /// Ignored for multiview. Default {} (whole target).
  VkRect2D scissor{};
};

/// True when drawing with `view` and `proj` flips triangle winding in the framebuffer compared
/// with Snell's main views (a mirrored view, or a projection whose clip y is not flipped).
[[nodiscard]] bool needs_front_face_flip(const glm::mat4& view, const glm::mat4& proj);

/// Implemented by the host (SceneRenderer is Snell's own): draws the scene for a view.
class SceneSource {
public:
  virtual ~SceneSource() = default;
  /// Records draws of the scene for `view` inside an active dynamic rendering whose attachments
  /// match `view.color_format` / `view.depth_format` and `view.view_mask`. Errors (a pipeline
  /// that cannot be created for the view's formats, ...) are returned, never only logged; the
  /// caller then ends its rendering and skips what depended on the draw.
  [[nodiscard]] virtual Result<void> draw_scene(VkCommandBuffer cmd, const SceneView& view) = 0;
};

} // namespace snell

// Snell plugin toolkit: render a view of the host's scene into a target. Mirrored views with
// oblique or clip-distance clipping (planar reflections), refraction views, and cube captures
// (six faces by multiview or one by one), each timed by the GPU timer under a name.
#pragma once

#include <snell/effect.hpp>
#include <snell/images.hpp>
#include <snell/math/plane.hpp>

#include <glm/vec4.hpp>

#include <cstdint>

namespace snell {

/// How a pass keeps one side of a plane.
enum class PlaneClip : std::uint8_t {
  oblique,       ///< Lengyel's oblique near plane (no per-vertex cost). Default.
  clip_distance, ///< gl_ClipDistance against the plane (the seeds' clip plane).
};

/// `main` seen in the mirror `mirror`: reflected view and eye, front face flipped. Extent and
/// formats stay those of `main` until aim_at().
[[nodiscard]] SceneView mirrored_view(const SceneView& main, const Plane& mirror);

/// Keeps only the positive side of `keep` in `view`. With PlaneClip::oblique the projection's
/// near plane becomes `keep` when the eye is strictly on the clipped side (otherwise an
/// oblique near plane cannot exist: a camera on the plane); then and with clip_distance the
/// pass clips with gl_ClipDistance. Returns the method used.
PlaneClip clip_view(SceneView& view, const Plane& keep, PlaneClip mode);

/// Points `view` at `target`: its extent, colour and depth formats, single view; recomputes
/// flip_front_face from the matrices.
void aim_at(SceneView& view, const RenderTarget& target);

/// One scene pass into a 2D target.
struct ScenePass {
  const char* name = "pass"; ///< GPU timer name ("water.reflection"). Default "pass".
  SceneView view{};          ///< What to draw (aim_at the target first).
  /// The render area and scissor in pixels: the only pixels cleared, drawn and stored (the
  /// rest of the target keeps its previous contents), also handed to the scene for culling
  /// (SceneView::scissor). Extent {0, 0} = the whole target. Default whole.
  VkRect2D scissor{{0, 0}, {0, 0}};
  glm::vec4 clear{0.0f, 0.0f, 0.0f, 1.0f}; ///< Linear clear colour. Default opaque black.
};

/// Records `pass` into `target`: begin rendering (clear), scissor, `scene.draw_scene`, end
/// rendering (colour mips generated when the target has them; colour and depth left
/// SHADER_READ_ONLY_OPTIMAL), timed as `pass.name` when `timer` is given. A draw_scene error is
/// returned after the rendering is closed, so the command buffer stays valid.
[[nodiscard]] Result<void> record_scene_pass(VkCommandBuffer cmd, SceneSource& scene,
                                             const RenderTarget& target, const ScenePass& pass,
                                             GpuTimer* timer = nullptr);

/// How a cube capture draws its faces.
enum class CubeCaptureMode : std::uint8_t {
  multiview, ///< One pass, view mask 0b111111 (Vulkan 1.1 multiview). Default.
  six_pass,  ///< Six passes, one per face (seed 002).
};

/// A capture of the scene around a point.
struct CubeCapture {
  const char* name = "cube";                  ///< GPU timer name. Default "cube".
  glm::vec3 center{0.0f};                     ///< World position of the capture. Default origin.
  float z_near = 0.1f;                        ///< Near plane distance, > 0. Default 0.1.
  float z_far = 200.0f;                       ///< Far plane distance, > z_near. Default 200.
  std::uint32_t layer_mask = layer::captured; ///< Objects drawn. Default captured.
  CubeCaptureMode mode = CubeCaptureMode::multiview; ///< Default multiview.
  glm::vec4 clear{0.0f, 0.0f, 0.0f, 1.0f};           ///< Default opaque black.
  float time = 0.0f;                                 ///< Scene time, s. Default 0.
  /// The faces drawn, one bit per face (bit f = CubeFace f). Default 0x3F (all six). Fewer
  /// faces (a capture sliced over frames) are drawn one by one; the other faces keep their
  /// contents and the mips are left alone (build them with the slice that completes the cube).
  std::uint32_t faces = 0x3F;
  /// Rebuild the mip chain after drawing. Default true.
  bool mips = true;
};

/// Records the six faces of `capture` into `cube` (face f written where direction_to_cube puts
/// it), then its mips; leaves the cube SHADER_READ_ONLY_OPTIMAL.
[[nodiscard]] Result<void> record_cube_capture(VkCommandBuffer cmd, SceneSource& scene,
                                               const CubeTarget& cube, const CubeCapture& capture,
                                               GpuTimer* timer = nullptr);

} // namespace snell

// Scene passes: mirrored / clipped views of the host's scene rendered into toolkit targets.
#include <snell/gpu_timer.hpp>
#include <snell/math.hpp>
#include <snell/toolkit/scene_pass.hpp>

namespace snell {

SceneView mirrored_view(const SceneView& main, const Plane& mirror) {
  SceneView v = main;
  v.view = reflect_view(main.view, mirror);
  v.eye = reflect_point(mirror, main.eye);
  v.clip_plane.reset();
  v.view_mask = 0;
  v.flip_front_face = needs_front_face_flip(v.view, v.proj);
  return v;
}

PlaneClip clip_view(SceneView& view, const Plane& keep, PlaneClip mode) {
  view.clip_plane.reset();
  // An oblique near plane needs the eye strictly on the clipped side of the plane.
  const bool eye_clipped = signed_distance(keep, view.eye) < -1e-4f;
  if (mode == PlaneClip::oblique && eye_clipped) {
    const glm::vec4 view_plane = to_vec4(transform_plane(keep, view.view));
    view.proj = oblique_projection(view.proj, view_plane, DepthRange::zero_to_one);
    view.flip_front_face = needs_front_face_flip(view.view, view.proj);
    return PlaneClip::oblique;
  }
  view.clip_plane = keep;
  return PlaneClip::clip_distance;
}

void aim_at(SceneView& view, const RenderTarget& target) {
  view.extent = {target.width(), target.height()};
  view.color_format = target.vk_color_format();
  view.depth_format = target.depth_format();
  view.view_mask = 0;
  view.flip_front_face = needs_front_face_flip(view.view, view.proj);
}

Result<void> record_scene_pass(VkCommandBuffer cmd, SceneSource& scene, const RenderTarget& target,
                               const ScenePass& pass, GpuTimer* timer) {
  if (!target) {
    return fail(ErrorCode::invalid_argument,
                std::string(pass.name != nullptr ? pass.name : "pass") + ": no target");
  }
  GpuTimerScope scope(timer, cmd, pass.name);
  const float clear[4] = {pass.clear.r, pass.clear.g, pass.clear.b, pass.clear.a};
  // The scissor is the render area: nothing outside it is cleared or stored.
  target.begin_rendering(cmd, clear, 1.0f, pass.scissor);
  SceneView view = pass.view;
  view.scissor = pass.scissor; // lets the scene cull what the scissor removes anyway
  Result<void> drawn = scene.draw_scene(cmd, view);
  target.end_rendering(cmd);
  return drawn;
}

Result<void> record_cube_capture(VkCommandBuffer cmd, SceneSource& scene, const CubeTarget& cube,
                                 const CubeCapture& capture, GpuTimer* timer) {
  const std::string name = capture.name != nullptr ? capture.name : "cube";
  if (!cube) {
    return fail(ErrorCode::invalid_argument, name + ": no cube target");
  }
  if (!(capture.z_near > 0.0f && capture.z_far > capture.z_near)) {
    return fail(ErrorCode::invalid_argument, name + ": CubeCapture needs 0 < z_near < z_far (got " +
                                                 std::to_string(capture.z_near) + ", " +
                                                 std::to_string(capture.z_far) + ")");
  }
  GpuTimerScope scope(timer, cmd, capture.name);
  const glm::mat4 proj =
      cube_face_projection(capture.z_near, capture.z_far, DepthRange::zero_to_one);
  SceneView v;
  v.proj = proj;
  v.eye = capture.center;
  v.layer_mask = capture.layer_mask;
  v.extent = {cube.size(), cube.size()};
  v.color_format = to_vk_format(cube.color_format());
  v.depth_format = VK_FORMAT_D32_SFLOAT;
  v.time = capture.time;
  const float clear[4] = {capture.clear.r, capture.clear.g, capture.clear.b, capture.clear.a};
  Result<void> drawn;
  const std::uint32_t faces = capture.faces & 0x3Fu;
  const bool all = faces == 0x3Fu;
  cube.begin_capture(cmd, !all);
  if (capture.mode == CubeCaptureMode::multiview && all) {
    // Every face view has det +1 and an unflipped projection: one front face for all six.
    v.view = cube_face_view(capture.center, CubeFace::pos_x);
    v.flip_front_face = needs_front_face_flip(v.view, proj);
    v.view_mask = 0x3F;
    for (std::size_t f = 0; f < 6; ++f) {
      v.multiview_view_proj[f] = proj * cube_face_view(capture.center, static_cast<CubeFace>(f));
    }
    cube.begin_multiview(cmd, clear);
    drawn = scene.draw_scene(cmd, v);
    cube.end_multiview(cmd);
  } else {
    for (std::uint32_t f = 0; f < 6; ++f) {
      if ((faces & (1u << f)) == 0) {
        continue;
      }
      v.view = cube_face_view(capture.center, static_cast<CubeFace>(f));
      v.flip_front_face = needs_front_face_flip(v.view, proj);
      cube.begin_face(cmd, f, clear);
      auto r = scene.draw_scene(cmd, v);
      cube.end_face(cmd);
      if (!r && drawn) {
        drawn = r;
      }
    }
  }
  cube.end_capture(cmd, capture.mips);
  return drawn;
}

} // namespace snell

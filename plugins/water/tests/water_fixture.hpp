// Helpers for the water tests: a test scene with a floor below the water, markers, and
// rendering frames with or without the water effect.
#pragma once

#include "gpu_fixture.hpp"

#include <snell/frame.hpp>
#include <snell/water.hpp>

namespace snell::test {

/// Everything one water test renders with.
struct WaterRig {
  Scene scene;
  std::optional<SceneRenderer> renderer;
  std::optional<FrameRenderer> frame;
  FrameStats last_stats; ///< Of the last render().
  std::unique_ptr<WaterEffect> water;
  CameraDesc camera;
  std::uint32_t width = 256, height = 192;

  /// Builds the renderer, a frame of width x height and the water effect from the scene.
  void init(Context& ctx);
  /// One frame (with the water when `with_water`), read back as RGBA8.
  Image render(float time, bool with_water = true);
  /// The main view the frame uses.
  [[nodiscard]] SceneView main_view() const;
};

/// A dark scene: water at y = 0 over 20 x 20 m, a grey floor at y = -2, sky black.
Scene water_test_scene();

/// A water effect with default parameters and no scene (for parameter tests).
std::unique_ptr<WaterEffect> bare_water(Context& ctx);

/// The world ray through the centre of pixel (x, y) (rows top first) of a width x height view.
struct PixelRay {
  glm::vec3 origin{0.0f};
  glm::vec3 dir{0.0f}; ///< Unit.
};
PixelRay pixel_ray(const SceneView& view, std::uint32_t x, std::uint32_t y, std::uint32_t width,
                   std::uint32_t height);

} // namespace snell::test

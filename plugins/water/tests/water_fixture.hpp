// Helpers for the water tests: a test scene with a floor below the water, markers, and
// rendering frames with or without the water effect.
#pragma once

#include "frame_rig.hpp"

#include <snell/frame.hpp>
#include <snell/water.hpp>

namespace snell::test {

/// Everything one water test renders with: the frame rig and the water effect.
struct WaterRig : FrameRig {
  std::unique_ptr<WaterEffect> water;

  /// Builds the renderer, the frame and the water effect from the scene.
  void init(Context& ctx);
  /// One frame at `time` (with the water when `with_water`), read back as RGBA8.
  Image render(float time, bool with_water = true);
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

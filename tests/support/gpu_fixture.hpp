// GPU test support: one validated context per test, scene building blocks, pixel probes.
// The snell::test_support library (tests/support/CMakeLists.txt), shared by tests/gpu and the
// plugins' own tests.
#pragma once

#include <snell/context.hpp>
#include <snell/images.hpp>
#include <snell/readback.hpp>
#include <snell/scene.hpp>
#include <snell/scene_renderer.hpp>

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace snell::test {

/// A context with the validation layer (synchronization validation included). On destruction
/// it CHECKs that no validation error was reported and prints every message.
class GpuFixture {
public:
  GpuFixture();
  ~GpuFixture();
  GpuFixture(const GpuFixture&) = delete;
  GpuFixture& operator=(const GpuFixture&) = delete;
  Context& ctx() { return *ctx_; }
  /// For tests that provoke validation errors on purpose: the exact count expected at the end.
  void expect_validation_errors(std::uint32_t count) { expected_errors_ = count; }

private:
  std::optional<Context> ctx_;
  std::uint32_t expected_errors_ = 0;
};

/// An axis-aligned box mesh centred at the origin (CCW outward faces, per-face normals).
Mesh make_box_mesh(glm::vec3 half_extent, int material);
/// A quad in the XZ plane facing +Y, centred at the origin.
Mesh make_quad_mesh(glm::vec2 half_extent, int material);
/// Appends an unlit-looking (emissive, black albedo) material and returns its index.
int add_emissive_material(Scene& scene, glm::vec3 color);
/// Appends an object with its own copy of `mesh` at `position`; returns the object index.
int add_object(Scene& scene, const Mesh& mesh, glm::vec3 position,
               std::uint32_t layers = layer::all);
/// A scene with black sky/ambient so only emissive markers show.
Scene empty_dark_scene();

/// Renders `scene` for `view` into a new WxH rgba8_unorm target and reads it back.
Image render_view(Context& ctx, SceneRenderer& renderer, const SceneView& view, std::uint32_t width,
                  std::uint32_t height);

/// Centroid (x, y in pixels, y = row from the top) of the pixels within `tolerance` (per
/// channel, 0..255) of `rgb`, and their count.
struct Blob {
  glm::vec2 centroid{0.0f};
  int count = 0;
};
Blob find_color(const Image& image, glm::vec3 rgb, int tolerance = 24);

/// Pixel position predicted by the math: Vulkan convention, rows top first.
glm::vec2 predict_pixel(const glm::mat4& view_proj, glm::vec3 world, std::uint32_t width,
                        std::uint32_t height);

/// Writes `image` as `<dir>/<name>.png`, creating `dir`.
void save_png_in(const std::string& dir, const Image& image, const std::string& name);

#ifdef SNELL_TEST_OUTPUT_DIR
/// Writes `image` to the test executable's output folder (for looking at failures). Inline: the
/// folder is the SNELL_TEST_OUTPUT_DIR of the test executable that includes this header, not of
/// the support library, so each suite keeps its own folder.
inline void save_png(const Image& image, const std::string& name) {
  save_png_in(SNELL_TEST_OUTPUT_DIR, image, name);
}
#endif

} // namespace snell::test

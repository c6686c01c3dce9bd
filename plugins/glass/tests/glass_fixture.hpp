// Helpers for the glass tests: small scenes built in code (a backdrop wall facing the camera,
// emissive markers and panels, transmissive quads), a frame renderer with the glass effect,
// sRGB <-> linear conversions, intensity-weighted centroids, and an exact double-precision ray
// tracer through a solid slab (Snell's law at both faces), independent of the shader.
#pragma once

#include "frame_rig.hpp"

#include <snell/frame.hpp>
#include <snell/glass.hpp>
#include <snell/snapshot.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

/// REQUIREs that a Result holds a value, failing with its error message. (REQUIRE_MESSAGE(
/// r.has_value(), r.error().message) would read error() of a value when doctest runs with -s,
/// which stringifies messages of passing assertions too: bad_variant_access.)
#define GLASS_REQUIRE_OK(result)                                                                   \
  do {                                                                                             \
    const auto& glass_require_ok_ = (result);                                                      \
    if (!glass_require_ok_.has_value()) {                                                          \
      FAIL(glass_require_ok_.error().message);                                                     \
    }                                                                                              \
  } while (false)

namespace snell::test {

constexpr std::uint32_t kGlassWidth = 640;
constexpr std::uint32_t kGlassHeight = 360;

/// Everything one glass test renders with: the frame rig (640 x 360, sRGB) and the glass.
struct GlassRig : FrameRig {
  std::unique_ptr<GlassEffect> glass;

  GlassRig() {
    width = kGlassWidth;
    height = kGlassHeight;
    color = ColorFormat::rgba8_srgb;
  }
  /// Builds the scene renderer, the frame and the glass effect (create_glass with this scene).
  /// Call after the scene and camera are set.
  void init(Context& ctx);
  /// One frame with the glass (or, with_glass = false, the opaque scene alone), read back.
  Image render(bool with_glass = true);
  /// Sets the glass parameters (REQUIREs success).
  void set(const GlassParams& p);
  [[nodiscard]] glm::mat4 view_proj() const;
};

/// One frame as a host of its own records it (samples/embed-host): update, the effect's passes,
/// the opaque scene into `target`, a scene snapshot when `snapshot` is given and the effect wants
/// one (of `region`, default the effect's snapshot_region(); {} = everything), the effect's
/// surfaces; read back. Without `snapshot` FrameInfo::snapshot is null: the effect renders its
/// own background.
Image host_render(Context& ctx, SceneRenderer& renderer, const RenderTarget& target, Effect& effect,
                  const CameraDesc& camera, const DirectionalLight& light,
                  std::uint64_t frame_index, SceneSnapshot* snapshot = nullptr,
                  std::optional<VkRect2D> region = std::nullopt);

/// A dark scene (black sky, no light, no ambient) with a backdrop wall: an emissive box whose
/// front face (facing +Z) lies in the plane z = `wall_z`, 40 x 40 m.
Scene glass_test_scene(glm::vec3 wall_color = glm::vec3(0.0f), float wall_z = -2.0f);
/// A flat emissive box of half size `half` (x, y) and 1 cm deep whose front face (facing +Z) is
/// centred at `front_center`. Returns the object index.
int add_marker(Scene& scene, glm::vec3 front_center, glm::vec2 half, glm::vec3 color);
/// A quad of half size `half` (x, y) facing +Z, centred at `center`, with material `material`.
int add_panel(Scene& scene, glm::vec3 center, glm::vec2 half, int material);
/// A transmissive material (transmission 1, thin-walled, roughness 0, no attenuation) of tint
/// `tint`. Returns its index.
int add_transmissive_material(Scene& scene, glm::vec3 tint);

/// Glass parameters that isolate transmission: no Fresnel, no highlight, no normal-map offset,
/// no colour texture blend.
GlassParams transmission_only(GlassParams p = {});
/// transmission_only() for a pane centred at (0, 1.5, 0), 4 x 4 m, facing `normal`, of
/// `thickness` and IOR 1.5.
GlassParams pane_params(glm::vec3 normal, float thickness);
/// The camera most tests use: at (0, 1.5, 3) looking down -Z at (0, 1.5, 0), 50 degrees.
CameraDesc front_camera();
/// The unit normal turned `degrees` about +Y from +Z: a view ray along -Z meets the pane at
/// that angle of incidence.
glm::vec3 turned_normal(float degrees);

/// The first field that differs between `a` and `b` ("" when all are equal).
std::string first_difference(const GlassParams& a, const GlassParams& b);

/// sRGB transfer functions (IEC 61966-2-1).
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);
/// Channel `c` of pixel (x, y), 0..255.
int channel(const Image& image, std::uint32_t x, std::uint32_t y, int c);
/// Channel `c` of pixel (x, y) decoded to linear [0, 1].
double linear_at(const Image& image, std::uint32_t x, std::uint32_t y, int c);

/// A pixel rectangle [x0, x1) x [y0, y1), clamped to the image by the users.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
/// Centroid (pixel centres at i + 0.5, rows top first) of channel `c`'s linear value above
/// `floor` inside `box`, weighted by (value - floor); `weight` receives the total weight.
glm::dvec2 weighted_centroid(const Image& image, int c, double floor, PixelBox box,
                             double* weight = nullptr);
/// A box of half size `half` pixels around `center`.
PixelBox box_around(glm::dvec2 center, int half, const Image& image);

/// A ray in double precision.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 dir{0.0}; ///< Unit.
};
/// The camera ray through the continuous pixel position `pixel` (pixel centres at i + 0.5,
/// rows top first) of `view` (make_main_view), from the eye.
Ray camera_ray(const SceneView& view, glm::dvec2 pixel, std::uint32_t width, std::uint32_t height);
/// Where `world` projects, continuous pixel coordinates (double precision).
glm::dvec2 project_pixel(const SceneView& view, glm::dvec3 world, std::uint32_t width,
                         std::uint32_t height);

/// A solid slab: `thickness` along the unit `normal`, centred on `center`.
struct Slab {
  glm::dvec3 center{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
  double thickness = 0.0;
  double ior = 1.5;
};
/// Traces `ray` through `slab` exactly: intersection with the face toward the ray's origin,
/// Snell's law into the glass, the straight path to the opposite face, Snell's law out. The
/// result starts at the exit point. nullopt if the ray does not meet the entry face ahead.
std::optional<Ray> trace_slab(const Ray& ray, const Slab& slab);
/// The continuous pixel whose camera ray, traced through `slab`, hits `target` (a point of the
/// plane through `target` with normal `plane_normal`): Newton's method on the pixel
/// coordinates with a central-difference Jacobian, from the unrefracted projection. nullopt if
/// it does not converge to 1e-9 m.
std::optional<glm::dvec2> pixel_through_slab(const SceneView& view, std::uint32_t width,
                                             std::uint32_t height, const Slab& slab,
                                             glm::dvec3 target, glm::dvec3 plane_normal);

/// The 10%-90% width (pixels) of the rising transition of channel `c` (linear) along row `y`,
/// between the mean of the first and last `plateau` pixels of [x0, x1), interpolated linearly
/// between pixel centres. Negative if no transition is found.
double edge_width(const Image& image, std::uint32_t y, int x0, int x1, int c, int plateau = 8);

} // namespace snell::test

// The glass effect's optics, measured in rendered pixels against predictions made here,
// independently of the shader: projection through a thin pane, exact ray tracing through thick
// slabs, stacked panes, roughness, dispersion and Beer-Lambert absorption.
#include "glass_fixture.hpp"

#include <cmath>
#include <string>

using namespace snell;
using test::kGlassHeight;
using test::kGlassWidth;

namespace {

constexpr float kWallZ = -2.0f;
/// Markers sit 1 cm in front of the wall.
constexpr float kMarkerZ = kWallZ + 0.01f;

/// A rig with the front camera over `scene`, the glass made from it.
test::GlassRig make_rig(Context& ctx, Scene scene) {
  test::GlassRig rig;
  rig.scene = std::move(scene);
  rig.camera = test::front_camera();
  rig.init(ctx);
  return rig;
}

/// The red-channel centroid of the marker within `half` pixels of `near`.
glm::dvec2 marker_centroid(const Image& image, glm::dvec2 near, int half = 60) {
  double weight = 0.0;
  const glm::dvec2 c =
      test::weighted_centroid(image, 0, 0.02, test::box_around(near, half, image), &weight);
  REQUIRE(weight > 10.0); // the marker is there
  return c;
}

} // namespace

// Fails if a thin-walled pane displaced what is behind it: e.g. the shader refracting the
// thin-walled direction, the background lookup using a wrong view-projection or a flipped v, or
// the pane's tint not applied (the green check). Facing the eye, turned 45 degrees, and as a
// billboard (normal (0, 0, 0)). Verified: predicting with the marker moved 2 cm (about 1.5 px)
// fails.
TEST_CASE("glass: thin pane - a marker behind it appears where the camera projects it") {
  test::GpuFixture gpu;
  const glm::vec3 marker(0.4f, 1.7f, kMarkerZ);
  Scene scene = test::glass_test_scene();
  test::add_marker(scene, marker, {0.1f, 0.1f}, glm::vec3(1.0f));
  test::GlassRig rig = make_rig(gpu.ctx(), std::move(scene));
  for (const float degrees : {0.0f, 45.0f, -1.0f}) {
    CAPTURE(degrees); // -1: the billboard
    const glm::vec3 normal = degrees >= 0.0f ? test::turned_normal(degrees) : glm::vec3(0.0f);
    GlassParams p = test::pane_params(normal, 0.0f);
    p.tint = {1.0f, 0.5f, 1.0f}; // proves the marker is seen through the pane
    rig.set(p);
    const Image image = rig.render();
    test::save_png(image, "thin_pane_" + std::to_string(static_cast<int>(degrees)));
    const glm::dvec2 predicted =
        test::project_pixel(rig.main_view(), glm::dvec3(marker), kGlassWidth, kGlassHeight);
    const glm::dvec2 found = marker_centroid(image, predicted);
    CAPTURE(predicted);
    CAPTURE(found);
    MESSAGE("thin pane at " << degrees << " deg: projected (" << predicted.x << ", " << predicted.y
                            << "), found (" << found.x << ", " << found.y << ")");
    CHECK(glm::length(found - predicted) < 1.0);
    const auto px = static_cast<std::uint32_t>(predicted.x);
    const auto py = static_cast<std::uint32_t>(predicted.y);
    CHECK(test::linear_at(image, px, py, 0) == doctest::Approx(1.0).epsilon(0.02));
    CHECK(test::linear_at(image, px, py, 1) == doctest::Approx(0.5).epsilon(0.03));
  }
}

// Fails if the lateral shift of a solid slab is wrong: a missing shift (thickness ignored), the
// wrong sign, Snell's law with the wrong ratio or the shift measured on the wrong face. Verified:
// tracing here with IOR 1.33 instead of 1.5 fails at 60 degrees (3.1 px); the effect's thickness
// 0 with the tracer's 0.5 fails both (7.9 and 21.7 px); thickness 0 in both fails the
// non-vacuity check (> 5 px from the unrefracted projection). Also seen from the slab's back
// and tilted about X (a vertical shift: a flipped v would fail it).
TEST_CASE("glass: thick slab at 30 and 60 degrees - the marker appears where exact tracing puts "
          "it") {
  test::GpuFixture gpu;
  const glm::vec3 marker(0.0f, 1.5f, kMarkerZ);
  Scene scene = test::glass_test_scene();
  test::add_marker(scene, marker, {0.1f, 0.1f}, glm::vec3(1.0f));
  test::GlassRig rig = make_rig(gpu.ctx(), std::move(scene));
  constexpr float kThickness = 0.5f;
  struct Case {
    const char* name;
    glm::vec3 normal;
  };
  const float tilt = glm::radians(45.0f);
  const Case cases[] = {
      {"30", test::turned_normal(30.0f)},
      {"60", test::turned_normal(60.0f)},
      {"60_back", -test::turned_normal(60.0f)},          // facing away: the drawn face is its back
      {"45_up", {0.0f, std::sin(tilt), std::cos(tilt)}}, // turned about X: a vertical shift
  };
  for (const Case& c : cases) {
    const std::string degrees = c.name;
    CAPTURE(degrees);
    const GlassParams p = test::pane_params(c.normal, kThickness);
    rig.set(p);
    const Image image = rig.render();
    test::save_png(image, "thick_slab_" + degrees);
    const SceneView view = rig.main_view();
    const test::Slab slab{glm::dvec3(p.center), glm::dvec3(p.normal), kThickness, 1.5};
    const auto predicted = test::pixel_through_slab(view, kGlassWidth, kGlassHeight, slab,
                                                    glm::dvec3(marker), {0.0, 0.0, 1.0});
    REQUIRE(predicted.has_value());
    const glm::dvec2 unrefracted =
        test::project_pixel(view, glm::dvec3(marker), kGlassWidth, kGlassHeight);
    const glm::dvec2 found = marker_centroid(image, *predicted);
    CAPTURE(*predicted);
    CAPTURE(unrefracted);
    CAPTURE(found);
    MESSAGE("slab at " << degrees << " deg: unrefracted (" << unrefracted.x << ", " << unrefracted.y
                       << "), traced (" << predicted->x << ", " << predicted->y << "), found ("
                       << found.x << ", " << found.y << ")");
    CHECK(glm::length(*predicted - unrefracted) > 5.0); // the shift matters
    CHECK(glm::length(found - *predicted) < 2.0);
  }
}

// Fails if a pane seen through a pane is lost or applied twice: without the analytic tracing of
// the slabs behind (the snapshot holds neither pane), the overlap would show the front tint
// alone, which is what max_layers = 1 must show. Verified: expecting the overlap with
// max_layers = 1 to match the product of both tints fails.
TEST_CASE("glass: stacked transmissive objects - both tints in the overlap, max_layers 1 loses the "
          "back") {
  test::GpuFixture gpu;
  const glm::vec3 wall(0.8f);
  const glm::vec3 red_tint(1.0f, 0.4f, 0.4f), blue_tint(0.4f, 0.4f, 1.0f);
  Scene scene = test::glass_test_scene(wall);
  // Front (red-ish) at z = 0 over x in [-0.9, 0.3]; back (blue-ish) at z = -1 over [-0.3, 0.9].
  test::add_panel(scene, {-0.3f, 1.5f, 0.0f}, {0.6f, 0.6f},
                  test::add_transmissive_material(scene, red_tint));
  test::add_panel(scene, {0.3f, 1.5f, -1.0f}, {0.6f, 0.6f},
                  test::add_transmissive_material(scene, blue_tint));
  test::GlassRig rig = make_rig(gpu.ctx(), std::move(scene));
  REQUIRE(rig.glass->surface_count() == 2);
  CHECK_FALSE(rig.glass->params().pane); // a scene with glass of its own and no window anchor
  GlassParams p = test::transmission_only(rig.glass->params());
  rig.set(p);
  const SceneView view = rig.main_view();
  auto at = [&](glm::vec3 world) {
    const glm::dvec2 px = test::project_pixel(view, glm::dvec3(world), kGlassWidth, kGlassHeight);
    return glm::uvec2(px);
  };
  const glm::uvec2 both = at({0.0f, 1.5f, 0.0f}), front_only = at({-0.7f, 1.5f, 0.0f}),
                   back_only = at({0.7f, 1.5f, -1.0f}), neither = at({1.5f, 1.5f, kWallZ});
  // Expected 8-bit sRGB value of the wall (linear `wall`) times `f`.
  auto check = [](const Image& image, glm::uvec2 px, glm::vec3 f, const std::string& where) {
    CAPTURE(where);
    CAPTURE(px.x);
    CAPTURE(px.y);
    for (int c = 0; c < 3; ++c) {
      CAPTURE(c);
      const double want = 255.0 * test::linear_to_srgb(0.8 * f[c]);
      const int got = test::channel(image, px.x, px.y, c);
      CAPTURE(got);
      CAPTURE(want);
      CHECK(std::abs(got - want) <= 2.5);
    }
  };
  const Image stacked = rig.render();
  test::save_png(stacked, "stacked_panes");
  check(stacked, neither, glm::vec3(1.0f), "neither");
  check(stacked, front_only, red_tint, "front only");
  check(stacked, back_only, blue_tint, "back only");
  check(stacked, both, red_tint * blue_tint, "both");
  // Both reduced in the overlap: red by the back (blue-ish) pane, blue by the front one.
  CHECK(test::linear_at(stacked, both.x, both.y, 0) <
        0.6 * test::linear_at(stacked, neither.x, neither.y, 0));
  CHECK(test::linear_at(stacked, both.x, both.y, 2) <
        0.6 * test::linear_at(stacked, neither.x, neither.y, 2));

  p.max_layers = 1;
  rig.set(p);
  const Image single = rig.render();
  test::save_png(single, "stacked_panes_one_layer");
  check(single, both, red_tint, "both, one layer"); // the back pane is lost
  check(single, back_only, blue_tint, "back only, one layer");
}

// Fails if roughness did not blur (no mips requested, the LOD ignored or not growing with
// roughness). Verified: widths for roughness 0, 0, 0, 0 fail the strict increase.
TEST_CASE("glass: roughness widens a sharp edge behind the pane monotonically") {
  test::GpuFixture gpu;
  Scene scene = test::glass_test_scene();
  // White from x = 0.05 to the right on the black wall: a vertical edge near the centre column.
  test::add_marker(scene, {5.05f, 1.5f, kMarkerZ}, {5.0f, 5.0f}, glm::vec3(1.0f));
  test::GlassRig rig = make_rig(gpu.ctx(), std::move(scene));
  const std::uint32_t row = kGlassHeight / 2;
  double previous = -1.0;
  std::vector<double> widths;
  for (const float roughness : {0.0f, 0.2f, 0.4f, 0.6f}) {
    CAPTURE(roughness);
    GlassParams p = test::pane_params({0.0f, 0.0f, 1.0f}, 0.0f);
    p.size = {20.0f, 20.0f}; // covers the view: the whole snapshot is sampled
    p.roughness = roughness;
    rig.set(p);
    const Image image = rig.render();
    test::save_png(image, "rough_edge_" + std::to_string(static_cast<int>(roughness * 10)));
    const double width = test::edge_width(image, row, 160, 540, 0, 16);
    MESSAGE("roughness " << roughness << ": 10-90% edge width " << width << " px");
    CHECK(width >= 0.0);
    CHECK(width > previous);
    previous = width;
    widths.push_back(width);
  }
  CHECK(widths.front() < 2.0); // clear glass keeps the edge sharp
  CHECK(widths.back() > 10.0);
}

// Fails if dispersion did not split the channels (one IOR for all), split them the wrong way
// round (red above blue), or split them without dispersion. Verified: the effect's dispersion 0
// for the split frame fails the direction and position checks, and dispersion 5 for the plain
// frame fails the 0.5 px coincidence (3.9 px).
TEST_CASE("glass: dispersion separates red and blue of a white bar in the predicted direction") {
  test::GpuFixture gpu;
  const glm::vec3 bar(0.0f, 1.5f, kMarkerZ);
  Scene scene = test::glass_test_scene();
  test::add_marker(scene, bar, {0.05f, 1.0f}, glm::vec3(1.0f));
  test::GlassRig rig = make_rig(gpu.ctx(), std::move(scene));
  constexpr float kThickness = 1.0f, kDispersion = 5.0f;
  const glm::vec3 normal = test::turned_normal(45.0f);
  const SceneView view = rig.main_view();
  auto predict = [&](double ior) {
    const test::Slab slab{{0.0, 1.5, 0.0}, glm::dvec3(normal), kThickness, ior};
    const auto px = test::pixel_through_slab(view, kGlassWidth, kGlassHeight, slab, glm::dvec3(bar),
                                             {0.0, 0.0, 1.0});
    REQUIRE(px.has_value());
    return *px;
  };
  // KHR_materials_dispersion: half-spread (ior - 1) * 0.025 * dispersion, red below, blue above.
  const double half_spread = (1.5 - 1.0) * 0.025 * kDispersion;
  const glm::dvec2 base = predict(1.5), red = predict(1.5 - half_spread),
                   blue = predict(1.5 + half_spread);
  const glm::dvec2 unrefracted =
      test::project_pixel(view, glm::dvec3(bar), kGlassWidth, kGlassHeight);
  const double shift_dir = base.x - unrefracted.x > 0.0 ? 1.0 : -1.0; // the lateral shift, in x
  CAPTURE(unrefracted);
  CAPTURE(red);
  CAPTURE(blue);
  REQUIRE(std::abs(base.x - unrefracted.x) > 5.0);
  REQUIRE((blue.x - red.x) * shift_dir > 2.0); // higher IOR, larger shift: blue further along
  // The bar's centroid per channel in rows around the centre.
  auto centroid_x = [&](const Image& image, int c) {
    test::PixelBox box = test::box_around(base, 60, image);
    box.y0 = static_cast<int>(base.y) - 20;
    box.y1 = static_cast<int>(base.y) + 21;
    double weight = 0.0;
    const glm::dvec2 at = test::weighted_centroid(image, c, 0.02, box, &weight);
    REQUIRE(weight > 10.0);
    return at.x;
  };
  GlassParams p = test::pane_params(normal, kThickness);
  p.dispersion = kDispersion;
  rig.set(p);
  const Image split = rig.render();
  test::save_png(split, "dispersion");
  const double r = centroid_x(split, 0), b = centroid_x(split, 2);
  CAPTURE(r);
  CAPTURE(b);
  MESSAGE("dispersion: predicted red x " << red.x << ", blue x " << blue.x << " (base " << base.x
                                         << ", unrefracted " << unrefracted.x << "); found red "
                                         << r << ", blue " << b);
  CHECK((b - r) * shift_dir > 1.0); // blue displaced further along the shift than red
  CHECK(std::abs(r - red.x) < 1.0);
  CHECK(std::abs(b - blue.x) < 1.0);

  p.dispersion = 0.0f;
  rig.set(p);
  const Image plain = rig.render();
  test::save_png(plain, "dispersion_none");
  const double r0 = centroid_x(plain, 0), b0 = centroid_x(plain, 2);
  CAPTURE(r0);
  CAPTURE(b0);
  MESSAGE("no dispersion: red x " << r0 << ", blue x " << b0);
  CHECK(std::abs(r0 - b0) < 0.5);
  CHECK(std::abs(r0 - base.x) < 1.0);
}

// Fails if absorption used the wrong path length (thickness alone at oblique incidence, or
// not at all), the wrong exponent (distance / thickness) or applied it in sRGB space. Verified:
// expecting c^(2t/d) fails (up to 60 in 8-bit units), and expecting the path t instead of
// t / cos(theta_t) at 45 degrees fails (up to 10).
TEST_CASE("glass: Beer-Lambert - the background times attenuation_color^(path/distance)") {
  test::GpuFixture gpu;
  const glm::vec3 wall(0.8f, 0.6f, 0.4f);
  test::GlassRig rig = make_rig(gpu.ctx(), test::glass_test_scene(wall));
  const Image background = rig.render(false);
  constexpr double kThickness = 0.5, kDistance = 0.25;
  const glm::dvec3 color(0.5, 0.7, 0.9);
  for (const float degrees : {0.0f, 45.0f}) {
    CAPTURE(degrees);
    GlassParams p = test::pane_params(test::turned_normal(degrees), float(kThickness));
    p.attenuation_color = glm::vec3(color);
    p.attenuation_distance = float(kDistance);
    if (degrees > 0.0f) {
      // Transmission alone (not weighted by 1 - F): the Fresnel term stays exact but unseen.
      p.fresnel = GlassFresnel::exact;
      p.debug_view = GlassDebugView::transmission;
    }
    rig.set(p);
    const Image image = rig.render();
    test::save_png(image, "beer_lambert_" + std::to_string(static_cast<int>(degrees)));
    const SceneView view = rig.main_view();
    for (const std::uint32_t y : {kGlassHeight / 2 - 40, kGlassHeight / 2, kGlassHeight / 2 + 40}) {
      for (const std::uint32_t x : {kGlassWidth / 2 - 60, kGlassWidth / 2, kGlassWidth / 2 + 60}) {
        CAPTURE(x);
        CAPTURE(y);
        // The path inside: thickness / cos(theta_t), theta_t from this pixel's ray.
        const test::Ray ray =
            test::camera_ray(view, glm::dvec2(x + 0.5, y + 0.5), kGlassWidth, kGlassHeight);
        const double cos_i = std::abs(glm::dot(ray.dir, glm::dvec3(p.normal)));
        const double sin_t = std::sqrt(1.0 - cos_i * cos_i) / 1.5;
        const double path = kThickness / std::sqrt(1.0 - sin_t * sin_t);
        for (int c = 0; c < 3; ++c) {
          CAPTURE(c);
          const double bg = test::linear_at(background, x, y, c);
          const double want =
              255.0 * test::linear_to_srgb(bg * std::pow(color[c], path / kDistance));
          CHECK(std::abs(test::channel(image, x, y, c) - want) <= 2.0);
        }
      }
    }
  }
}

// A defect this test found (fixed: the margin is now two texels of level ceil(L)).
// snapshot_region() grew a rough surface's rectangle by 2^(roughness * log2(size)) px, one texel of
// the blurred level, but the trilinear lookup reads texels of the next level up to about 1.5 of its
// texels away, so near the region's edges the blur mixes in snapshot pixels never copied (black).
// Fails if a rough pane over a uniform wall is not uniform through the FrameRenderer; the
// host-rendered control with the whole snapshot copied shows the cause is the region, not the blur
// itself.
TEST_CASE(
    "glass: a rough pane over a uniform wall stays uniform - the snapshot region covers the blur") {
  test::GpuFixture gpu;
  Context& ctx = gpu.ctx();
  Scene scene = test::glass_test_scene(glm::vec3(0.5f));
  GlassParams p = test::pane_params({0.0f, 0.0f, 1.0f}, 0.0f);
  p.size = {2.0f, 2.0f}; // about 260 px square: the region is well inside the frame
  p.roughness = 0.6f;
  auto uniform_range = [](const Image& image) {
    int lo = 255, hi = 0;
    for (std::uint32_t y = 0; y < kGlassHeight; ++y) {
      for (std::uint32_t x = 0; x < kGlassWidth; ++x) {
        lo = std::min(lo, test::channel(image, x, y, 0));
        hi = std::max(hi, test::channel(image, x, y, 0));
      }
    }
    return hi - lo;
  };
  // Control: a host copying the whole snapshot every frame.
  {
    auto renderer = SceneRenderer::create(ctx, scene);
    GLASS_REQUIRE_OK(renderer);
    auto target = RenderTarget::create(ctx, RenderTargetDesc{.width = kGlassWidth,
                                                             .height = kGlassHeight,
                                                             .color = ColorFormat::rgba8_srgb});
    GLASS_REQUIRE_OK(target);
    EffectCreateInfo info;
    info.context = &ctx;
    info.color_format = target->vk_color_format();
    info.scene = &scene;
    auto glass = create_glass(info);
    GLASS_REQUIRE_OK(glass);
    GLASS_REQUIRE_OK((*glass)->set_params(p));
    auto snapshot = SceneSnapshot::create(ctx);
    GLASS_REQUIRE_OK(snapshot);
    const Image whole = test::host_render(ctx, *renderer, *target, **glass, test::front_camera(),
                                          scene.light, 1, &*snapshot, VkRect2D{});
    test::save_png(whole, "rough_uniform_whole_snapshot");
    CHECK(uniform_range(whole) <= 1);
  }
  test::GlassRig rig = make_rig(ctx, scene);
  rig.set(p);
  for (int frame = 0; frame < 2; ++frame) {
    CAPTURE(frame);
    const Image image = rig.render();
    test::save_png(image, "rough_uniform_" + std::to_string(frame));
    CHECK(uniform_range(image) <= 1); // the effect's region: 7 darker at the pane's sides
  }
}

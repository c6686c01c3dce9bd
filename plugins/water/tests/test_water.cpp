// The plugin layer and the water effect.
#include "water_fixture.hpp"

#include <snell/math.hpp>

#include <cmath>
#include <cstring>
#include <limits>

using namespace snell;

namespace {

const glm::vec3 kMarkerAbove(1, 0, 0); // red, above the water
const glm::vec3 kMarkerBelow(0, 0, 1); // blue, below the water

/// The water rig with a red marker above and a blue marker below the water.
test::WaterRig marker_rig(Context& ctx, glm::vec3 above, glm::vec3 below) {
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  test::add_object(
      rig.scene,
      test::make_box_mesh(glm::vec3(0.25f), test::add_emissive_material(rig.scene, kMarkerAbove)),
      above, layer::all & ~layer::refracted);
  test::add_object(
      rig.scene,
      test::make_box_mesh(glm::vec3(0.25f), test::add_emissive_material(rig.scene, kMarkerBelow)),
      below, layer::all & ~layer::reflected);
  rig.camera.eye = {0.0f, 4.0f, 9.0f};
  rig.camera.target = {0.0f, -0.5f, 0.0f};
  rig.camera.yfov = glm::radians(50.0f);
  rig.init(ctx);
  return rig;
}

void require_ok(const Result<void>& r) {
  REQUIRE_MESSAGE(r.has_value(), r.error().message);
}

} // namespace

TEST_CASE("registry: builtin effects, unknown names listed, duplicates refused") {
  test::GpuFixture gpu;
  EffectRegistry registry;
  require_ok(register_builtin_effects(registry));
  const std::vector<std::string> names = registry.names(); // other effects may be registered
  CHECK(std::find(names.begin(), names.end(), "water") != names.end());
  REQUIRE(registry.schema("water") != nullptr);
  CHECK(registry.schema("nope") == nullptr);
  EffectCreateInfo info;
  info.context = &gpu.ctx();
  auto unknown = registry.create("lava", info);
  REQUIRE_FALSE(unknown.has_value());
  CHECK(unknown.error().code == ErrorCode::unknown_name);
  CHECK(unknown.error().message.find("lava") != std::string::npos);
  CHECK(unknown.error().message.find("water") != std::string::npos);
  auto twice = register_water(registry);
  REQUIRE_FALSE(twice.has_value());
  CHECK(twice.error().code == ErrorCode::duplicate_name);
  auto created = registry.create("water", info);
  REQUIRE_MESSAGE(created.has_value(), created.error().message);
  CHECK((*created)->type() == "water");
  auto no_context = registry.create("water", EffectCreateInfo{});
  REQUIRE_FALSE(no_context.has_value());
  CHECK(no_context.error().message.find("context") != std::string::npos);
}

TEST_CASE("water: schema defaults are WaterParams' defaults (pinned)") {
  test::GpuFixture gpu;
  EffectCreateInfo info;
  info.context = &gpu.ctx();
  auto water = create_water(info);
  REQUIRE(water.has_value());
  const ParamSchema& schema = water_schema();
  CHECK(schema.params.size() == 26);
  for (const ParamSpec& spec : schema.params) {
    CAPTURE(spec.name);
    CHECK_FALSE(spec.doc.empty());
    auto value = (*water)->get_param(spec.name);
    REQUIRE(value.has_value());
    CHECK(to_string(*value) == to_string(spec.default_value));
    CHECK(validate_param(schema, spec, spec.default_value).has_value());
  }
  // The typed defaults, spelled out: a change to either side must be made on purpose.
  const WaterParams d;
  CHECK(d.resolution_scale == 0.5f);
  CHECK(d.clip_mode == WaterClipMode::oblique);
  CHECK(d.refraction_source == WaterRefractionSource::snapshot);
  CHECK(water_seed_preset().refraction_source == WaterRefractionSource::pass);
  CHECK(d.fresnel == WaterFresnel::exact);
  CHECK(d.ior == doctest::Approx(1.333f));
  CHECK(d.wave_height == doctest::Approx(0.3f));
  CHECK(d.specular_power == 256.0f);
  CHECK(d.reflection_layers == static_cast<int>(layer::reflected));
  CHECK(d.refraction_layers == static_cast<int>(layer::refracted));
  // The seed preset (seeds 000/001).
  const WaterParams seed = water_seed_preset();
  CHECK(seed.resolution_scale == 1.0f);
  CHECK(seed.fresnel == WaterFresnel::constant);
  CHECK(seed.reflectance == doctest::Approx(0.4f));
  CHECK(seed.color_blend == doctest::Approx(0.2f));
  CHECK(seed.water_color == glm::vec3(0.3f, 0.3f, 0.5f));
}

TEST_CASE("water: set_param errors name the key, value and range, and nothing is clamped") {
  test::GpuFixture gpu;
  const auto water = test::bare_water(gpu.ctx());
  WaterEffect& w = *water;
  auto unknown = w.set_param("wave_hieght", 1.0f);
  REQUIRE_FALSE(unknown.has_value());
  CHECK(unknown.error().message.find("wave_hieght") != std::string::npos);
  CHECK(unknown.error().message.find("wave_height") != std::string::npos); // valid keys listed
  auto nan = w.set_param("ior", std::numeric_limits<float>::quiet_NaN());
  REQUIRE_FALSE(nan.has_value());
  CHECK(nan.error().message.find("water.ior") != std::string::npos);
  CHECK(nan.error().message.find("not finite") != std::string::npos);
  auto range = w.set_param("ior", 7.5f);
  REQUIRE_FALSE(range.has_value());
  CHECK(range.error().message.find("7.5") != std::string::npos);
  CHECK(range.error().message.find("[1, 3]") != std::string::npos);
  CHECK(w.params().ior == doctest::Approx(1.333f)); // unchanged, not clamped
  auto type = w.set_param("ior", std::string("glass"));
  REQUIRE_FALSE(type.has_value());
  CHECK(type.error().message.find("float") != std::string::npos);
  auto choice = w.set_param("clip_mode", std::string("stencil"));
  REQUIRE_FALSE(choice.has_value());
  CHECK(choice.error().message.find("oblique") != std::string::npos);
  auto vec = w.set_param("absorption", glm::vec3(0.1f, -1.0f, 0.0f));
  REQUIRE_FALSE(vec.has_value());
  CHECK(vec.error().message.find("component 1") != std::string::npos);
  require_ok(w.set_param("wave_height", 0.0f));
  CHECK(w.params().wave_height == 0.0f);
  require_ok(w.set_param("preset", std::string("seed")));
  CHECK(w.params().fresnel == WaterFresnel::constant);
  WaterParams bad = w.params();
  bad.size = glm::vec2(0.0f, 1.0f);
  CHECK_FALSE(w.set_params(bad).has_value());
  // Text parsing, as the CLI does it.
  const ParamSchema& schema = water_schema();
  auto parsed = parse_param(schema, *schema.find("center"), "1.5,-2");
  REQUIRE(parsed.has_value());
  CHECK(std::get<glm::vec2>(*parsed) == glm::vec2(1.5f, -2.0f));
  CHECK_FALSE(parse_param(schema, *schema.find("center"), "1.5").has_value());
  CHECK_FALSE(parse_param(schema, *schema.find("wave_height"), "inf").has_value());
}

TEST_CASE("water: normal_map loads a file, and a missing one is an error naming it") {
  test::GpuFixture gpu;
  const auto water = test::bare_water(gpu.ctx());
  WaterEffect& w = *water;
  auto missing = w.set_param("normal_map", std::string("/nonexistent/ripples.png"));
  REQUIRE_FALSE(missing.has_value());
  CHECK(missing.error().message.find("/nonexistent/ripples.png") != std::string::npos);
  CHECK(w.params().normal_map.empty()); // unchanged
  // A flat 4x4 normal map file: accepted, read back, and the built-in one restored with "".
  Image flat;
  flat.name = "flat";
  flat.width = flat.height = 4;
  for (int i = 0; i < 16; ++i) {
    flat.rgba8.insert(flat.rgba8.end(), {128, 128, 255, 255});
  }
  const std::string path = std::string(SNELL_TEST_OUTPUT_DIR) + "/flat_normals.png";
  test::save_png(flat, "flat_normals");
  require_ok(w.set_param("normal_map", path));
  CHECK(std::get<std::string>(*w.get_param("normal_map")) == path);
  require_ok(w.set_param("normal_map", std::string()));
}

TEST_CASE("water: mirror probe - a marker above the water appears where reflection_matrix says") {
  test::GpuFixture gpu;
  const glm::vec3 above(1.5f, 1.0f, -1.0f);
  test::WaterRig rig = marker_rig(gpu.ctx(), above, {-1.5f, -1.0f, 1.0f});
  require_ok(rig.water->set_param("debug_view", std::string("reflection"))); // full reflection
  require_ok(rig.water->set_param("wave_height", 0.0f));                     // no distortion
  for (const float scale : {1.0f, 0.5f}) {
    CAPTURE(scale);
    require_ok(rig.water->set_param("resolution_scale", scale));
    const Image image = rig.render(0.0f);
    test::save_png(image, scale == 1.0f ? "water_mirror_probe" : "water_mirror_probe_half");
    const SceneView v = rig.main_view();
    const Plane water{{0, 1, 0}, 0.0f};
    const glm::vec2 direct = test::predict_pixel(v.proj * v.view, above, rig.width, rig.height);
    const glm::vec2 mirrored = test::predict_pixel(v.proj * v.view * reflection_matrix(water),
                                                   above, rig.width, rig.height);
    // Two red blobs: the marker and its reflection; the one nearer the predicted mirror image
    // is the reflection. Split the image at the midpoint between the two predictions.
    Image lower = image;
    const float split = 0.5f * (direct.y + mirrored.y);
    for (std::uint32_t y = 0; y < image.height; ++y) {
      if (static_cast<float>(y) + 0.5f < split) {
        std::fill_n(&lower.rgba8[std::size_t{y} * image.width * 4], image.width * 4, 0);
      }
    }
    const test::Blob blob = test::find_color(lower, kMarkerAbove, 40);
    CAPTURE(mirrored);
    CAPTURE(blob.centroid);
    REQUIRE(blob.count > 10);
    // One texel of the reflection target is 1/scale output pixels: allow one texel plus the
    // half-pixel of centroid quantisation.
    const float tol = 1.0f / scale + 0.5f;
    CHECK(std::fabs(blob.centroid.x - mirrored.x) <= tol);
    CHECK(std::fabs(blob.centroid.y - mirrored.y) <= tol);
  }
}

TEST_CASE("water: refraction probe - a marker below flat water appears where the camera predicts") {
  test::GpuFixture gpu;
  const glm::vec3 below(-1.0f, -1.0f, 1.0f);
  test::WaterRig rig = marker_rig(gpu.ctx(), {1.5f, 1.0f, -1.0f}, below);
  require_ok(rig.water->set_param("debug_view", std::string("refraction")));
  require_ok(rig.water->set_param("wave_height", 0.0f));
  require_ok(rig.water->set_param("resolution_scale", 1.0f));
  const Image image = rig.render(0.0f);
  test::save_png(image, "water_refraction_probe");
  const SceneView v = rig.main_view();
  const glm::vec2 predicted = test::predict_pixel(v.proj * v.view, below, rig.width, rig.height);
  const test::Blob blob = test::find_color(image, kMarkerBelow, 40);
  CAPTURE(predicted);
  CAPTURE(blob.centroid);
  REQUIRE(blob.count > 10);
  CHECK(std::fabs(blob.centroid.x - predicted.x) <= 1.5f);
  CHECK(std::fabs(blob.centroid.y - predicted.y) <= 1.5f);
}

TEST_CASE("water: no leaks - above-water objects are not refracted, below-water not reflected") {
  test::GpuFixture gpu;
  for (const char* mode : {"oblique", "clip_distance"}) {
    CAPTURE(mode);
    // Both markers on every layer: only the clipping keeps them out of the wrong target.
    test::WaterRig rig;
    rig.scene = test::water_test_scene();
    test::add_object(
        rig.scene,
        test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(rig.scene, kMarkerAbove)),
        {0.8f, 0.6f, 0.0f});
    test::add_object(
        rig.scene,
        test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(rig.scene, kMarkerBelow)),
        {-0.8f, -0.6f, 0.0f});
    for (Object& o : rig.scene.objects) {
      o.layers = layer::all;
    }
    rig.camera.eye = {0.0f, 3.0f, 7.0f};
    rig.camera.target = {0.0f, 0.0f, 0.0f};
    rig.init(gpu.ctx());
    require_ok(rig.water->set_param("clip_mode", std::string(mode)));
    require_ok(rig.water->set_param("refraction_source", std::string("pass")));
    (void)rig.render(0.0f);
    const auto targets = rig.water->debug_targets();
    REQUIRE(targets.size() == 3);
    auto reflection = read_debug_target(gpu.ctx(), targets[0]);
    auto refraction = read_debug_target(gpu.ctx(), targets[1]);
    REQUIRE(reflection.has_value());
    REQUIRE(refraction.has_value());
    auto count = [](const FloatImage& img, glm::vec3 c) {
      int n = 0;
      for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        const glm::vec3 p(img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]);
        n += glm::length(p - c) < 0.2f ? 1 : 0;
      }
      return n;
    };
    CHECK(count(*reflection, kMarkerAbove) > 20);
    CHECK(count(*reflection, kMarkerBelow) == 0);
    CHECK(count(*refraction, kMarkerBelow) > 20);
    CHECK(count(*refraction, kMarkerAbove) == 0);
  }
}

TEST_CASE("water: oblique clipping and clip distance render the same image") {
  test::GpuFixture gpu;
  test::WaterRig rig = marker_rig(gpu.ctx(), {1.0f, 0.8f, 0.0f}, {-1.0f, -0.8f, 0.5f});
  require_ok(rig.water->set_param("clip_mode", std::string("oblique")));
  const Image a = rig.render(0.5f);
  require_ok(rig.water->set_param("clip_mode", std::string("clip_distance")));
  const Image b = rig.render(0.5f);
  // Same geometry and same pixels; only depth precision differs (the oblique projection
  // redistributes depth), which can flip a handful of edge pixels at the clip line.
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.rgba8.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 3; ++c) {
      d = std::max(d, std::abs(int(a.rgba8[i + c]) - int(b.rgba8[i + c])));
    }
    differ += d > 8 ? 1 : 0;
  }
  CAPTURE(differ);
  CHECK(differ <= a.rgba8.size() / 4 / 200); // at most 0.5% of the pixels
}

TEST_CASE("water: no wind means a still surface, and wind changes only the water") {
  test::GpuFixture gpu;
  test::WaterRig rig = marker_rig(gpu.ctx(), {1.0f, 0.8f, 0.0f}, {-1.0f, -0.8f, 0.5f});
  const Image plain = rig.render(0.0f, false);
  require_ok(rig.water->set_param("wind_force", 0.0f));
  const Image still_a = rig.render(0.0f);
  const Image still_b = rig.render(3.0f);
  CHECK(still_a.rgba8 == still_b.rgba8);
  require_ok(rig.water->set_param("wind_force", 1.0f));
  const Image wind_a = rig.render(0.0f);
  const Image wind_b = rig.render(3.0f);
  std::size_t changed = 0, outside = 0;
  for (std::size_t i = 0; i < wind_a.rgba8.size(); i += 4) {
    const bool differs = std::memcmp(&wind_a.rgba8[i], &wind_b.rgba8[i], 3) != 0;
    // Water pixels: where the frame with water differs from the plain frame.
    const bool water = std::memcmp(&wind_a.rgba8[i], &plain.rgba8[i], 3) != 0 ||
                       std::memcmp(&wind_b.rgba8[i], &plain.rgba8[i], 3) != 0;
    changed += differs ? 1 : 0;
    outside += differs && !water ? 1 : 0;
  }
  CHECK(changed > 1000);
  CHECK(outside == 0);
}

TEST_CASE("water: a camera on the plane or below it renders without errors (clip fallback)") {
  test::GpuFixture gpu;
  test::WaterRig rig = marker_rig(gpu.ctx(), {1.0f, 0.8f, 0.0f}, {-1.0f, -0.8f, 0.5f});
  for (const float eye_y : {0.0f, 1e-6f, -1.0f}) {
    CAPTURE(eye_y);
    rig.camera.eye = {0.0f, eye_y, 8.0f};
    rig.camera.target = {0.0f, eye_y, 0.0f};
    for (const char* mode : {"oblique", "clip_distance"}) {
      require_ok(rig.water->set_param("clip_mode", std::string(mode)));
      const Image image = rig.render(0.0f); // fails on any effect error
      CHECK(image.width == rig.width);
    }
  }
}

namespace {

/// The integer shift (dx, dy) in pixels that best maps `a` onto `b` (b(x, y) ~ a(x - dx,
/// y - dy)) over the central window, by least squares over a +-range search.
glm::ivec2 best_shift(const Image& a, const Image& b, int range) {
  double best = 1e300;
  glm::ivec2 arg(0);
  const int w = static_cast<int>(a.width), h = static_cast<int>(a.height);
  for (int dy = -range; dy <= range; ++dy) {
    for (int dx = -range; dx <= range; ++dx) {
      double sum = 0.0;
      for (int y = h / 4; y < 3 * h / 4; ++y) {
        for (int x = w / 4; x < 3 * w / 4; ++x) {
          const std::uint8_t* pa = &a.rgba8[(std::size_t(y - dy) * a.width + (x - dx)) * 4];
          const std::uint8_t* pb = &b.rgba8[(std::size_t(y) * b.width + x) * 4];
          for (int c = 0; c < 3; ++c) {
            const double d = double(pa[c]) - double(pb[c]);
            sum += d * d;
          }
        }
      }
      if (sum < best) {
        best = sum;
        arg = {dx, dy};
      }
    }
  }
  return arg;
}

} // namespace

TEST_CASE("water: ripples move downwind") {
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  // Straight down from 10 m: image up is world +z, image right is world -x.
  rig.camera.eye = {0.0f, 10.0f, 0.0f};
  rig.camera.target = {0.0f, 0.0f, 0.0f};
  rig.camera.up = {0.0f, 0.0f, 1.0f};
  rig.camera.yfov = glm::radians(50.0f);
  rig.init(gpu.ctx());
  require_ok(rig.water->set_param("debug_view", std::string("normals")));
  require_ok(rig.water->set_param("wave_height", 1.0f));
  require_ok(rig.water->set_param("wind_force", 1.0f));
  // 0.4 s at 1 m/s: 0.4 m, about 8 pixels at 20.6 px/m (192 px over 2 * 10 * tan 25 = 9.3 m).
  struct Case {
    glm::vec2 wind;
    glm::ivec2 sign; // expected direction on screen
  };
  for (const Case c : {Case{{0, 1}, {0, -1}}, Case{{0, -1}, {0, 1}}, Case{{1, 0}, {-1, 0}}}) {
    CAPTURE(c.wind);
    require_ok(rig.water->set_param("wind_direction", c.wind));
    const Image a = rig.render(0.0f);
    const Image b = rig.render(0.4f);
    const glm::ivec2 s = best_shift(a, b, 14);
    CAPTURE(s);
    // Downwind, at between the second layer's (0.7) and the first layer's (1.0) speed.
    const int along = c.sign.x * s.x + c.sign.y * s.y;
    CHECK(along >= 4);
    CHECK(along <= 10);
  }
}

TEST_CASE("water: from below, Snell's window - total internal reflection past the critical angle") {
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  rig.camera.eye = {0.0f, -1.0f, 3.0f};
  rig.camera.target = {0.0f, 0.2f, 0.0f};
  rig.camera.yfov = glm::radians(80.0f);
  rig.init(gpu.ctx());
  require_ok(rig.water->set_param("debug_view", std::string("fresnel")));
  require_ok(rig.water->set_param("wave_height", 0.0f));
  const Image image = rig.render(0.0f);
  test::save_png(image, "water_snells_window");
  // Every pixel whose ray meets the water: the rendered Fresnel term (linear target) against
  // fresnel_dielectric for a ray leaving water (eta = 1.333) at the ray's angle to the vertical.
  const SceneView v = rig.main_view();
  const float critical = critical_angle(ior::water, 1.0f);
  int inside = 0, outside = 0, wrong = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const auto [origin, dir] = test::pixel_ray(v, x, y, image.width, image.height);
      if (dir.y <= 1e-3f) {
        continue; // looking down or level: no water surface
      }
      const glm::vec3 p = origin + dir * (-origin.y / dir.y);
      if (std::fabs(p.x) > 9.5f || std::fabs(p.z) > 9.5f) {
        continue; // off the water rectangle
      }
      const float theta = std::acos(glm::clamp(dir.y, -1.0f, 1.0f));
      if (std::fabs(theta - critical) < glm::radians(0.75f)) {
        continue; // the curve is too steep at the critical angle to compare per pixel
      }
      const float expected = fresnel_dielectric(dir.y, ior::water);
      const float got = image.rgba8[(std::size_t{y} * image.width + x) * 4] / 255.0f;
      (theta < critical ? inside : outside) += 1;
      wrong += std::fabs(got - expected) > 0.03f ? 1 : 0;
    }
  }
  CAPTURE(inside);
  CAPTURE(outside);
  CHECK(inside > 500);  // Snell's window: the sky side, mostly transmitted
  CHECK(outside > 500); // beyond 48.6 degrees: total internal reflection, F = 1
  CHECK(wrong == 0);
}

TEST_CASE("water: distorted refraction never shows what is in front of the surface point") {
  // A red box just under the surface near a low camera, and strong ripples. A far surface
  // point whose distorted sample lands on the (nearer) box must fall back to its undistorted
  // sample, so red may only appear where the surface point is not farther than the box.
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  const glm::vec3 box_center(0.0f, -0.35f, 2.0f);
  const glm::vec3 half(0.6f, 0.3f, 0.6f);
  test::add_object(rig.scene,
                   test::make_box_mesh(half, test::add_emissive_material(rig.scene, kMarkerAbove)),
                   box_center, layer::all & ~layer::reflected);
  rig.camera.eye = {0.0f, 1.2f, 5.0f};
  rig.camera.target = {0.0f, -0.3f, -2.0f};
  rig.init(gpu.ctx());
  require_ok(rig.water->set_param("debug_view", std::string("refraction")));
  require_ok(rig.water->set_param("wave_height", 2.0f));
  require_ok(rig.water->set_param("distortion", 0.3f));
  require_ok(rig.water->set_param("resolution_scale", 1.0f));
  const Image image = rig.render(0.0f);
  test::save_png(image, "water_no_leak_in_front");
  float box_far = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner =
        box_center + half * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    box_far = std::max(box_far, glm::distance(rig.camera.eye, corner));
  }
  const SceneView v = rig.main_view();
  int red = 0, leaked = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* px = &image.rgba8[(std::size_t{y} * image.width + x) * 4];
      if (!(px[0] > 150 && px[1] < 60 && px[2] < 60)) {
        continue;
      }
      ++red;
      const auto [origin, dir] = test::pixel_ray(v, x, y, image.width, image.height);
      if (dir.y >= 0.0f) {
        continue;
      }
      const glm::vec3 p = origin + dir * (-origin.y / dir.y);
      leaked += glm::distance(rig.camera.eye, p) > box_far + 0.05f ? 1 : 0;
    }
  }
  CAPTURE(red);
  CAPTURE(leaked);
  CHECK(red > 500);
  CHECK(leaked == 0);
}

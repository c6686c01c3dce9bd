// Golden images of the built-in scenes, plus independent pixel probes that do not depend on the
// references: where the math says an object projects, the image shows that object's colour.
#include <snell/builtin_scenes.hpp>
#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/math.hpp>
#include <snell/probe_directory.hpp>
#include <snell/readback.hpp>
#include <snell/scene_renderer.hpp>

#include "pixel_rays.hpp"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace snell;

namespace {

constexpr std::uint32_t kW = 320;
constexpr std::uint32_t kH = 180;

/// Why the golden tests cannot run here, or nullptr when they can. The references are
/// bit-stable only on Mesa lavapipe (llvmpipe): a GPU rasterises, filters and rounds
/// differently, so without lavapipe there is nothing to compare with. The pixel-probe tests
/// (label gpu: tests/gpu/test_render_probes.cpp and the plugins' probes) are the check on every
/// other device.
const std::string* lavapipe_missing() {
  static const std::optional<std::string> reason = []() -> std::optional<std::string> {
    auto devices = Context::enumerate_devices();
    if (!devices) {
      return "cannot list the Vulkan devices (" + devices.error().message + ")";
    }
    std::string seen;
    for (const DeviceInfo& d : *devices) {
      std::string lower = d.name;
      std::transform(lower.begin(), lower.end(), lower.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (d.type == VK_PHYSICAL_DEVICE_TYPE_CPU && d.suitable &&
          lower.find("llvmpipe") != std::string::npos) {
        return std::nullopt;
      }
      seen += (seen.empty() ? "" : ", ") + d.name;
    }
    return "no Mesa lavapipe (llvmpipe) Vulkan device among: " + (seen.empty() ? "none" : seen);
  }();
  return reason ? &*reason : nullptr;
}

} // namespace

/// First statement of every golden test: without lavapipe the test is skipped with the reason.
/// The message starts with "SNELL_SKIP:", which CTest's SKIP_REGULAR_EXPRESSION (CMakeLists.txt)
/// turns into a skipped test (doctest has no run-time skip).
#define SNELL_GOLDEN_NEEDS_LAVAPIPE()                                                              \
  if (const std::string* why = lavapipe_missing()) {                                               \
    MESSAGE("SNELL_SKIP: golden images need Mesa lavapipe for bit-stable pixels; "                 \
            << *why << ". The pixel-probe tests (label gpu) are the cross-device check.");         \
    return;                                                                                        \
  }

namespace {

struct Rendered {
  Image image;
  SceneView view;
  Scene scene;
};

/// One effect of a golden frame: its registered name and the parameters set on it.
struct EffectSetup {
  std::string effect;
  std::vector<std::pair<std::string, ParamValue>> params{};
};

/// Renders a built-in scene (or a glTF file when `name` ends in .gltf) with `effects`
/// (registry-created in order, sharing a ProbeDirectory, each with its parameters set).
Rendered render_builtin(const std::string& name, const std::vector<EffectSetup>& effects) {
  auto ctx = Context::create(
      ContextDesc{.validation = true, .device = "lavapipe", .app_name = "snell-golden"});
  REQUIRE_MESSAGE(ctx.has_value(), ctx.error().message);
  auto scene = name.size() > 5 && name.substr(name.size() - 5) == ".gltf"
                   ? load_gltf(std::filesystem::path(SNELL_ASSETS_DIR) / name)
                   : make_builtin_scene(name);
  REQUIRE_MESSAGE(scene.has_value(), scene.error().message);
  Rendered out;
  {
    auto renderer = SceneRenderer::create(*ctx, *scene);
    REQUIRE(renderer.has_value());
    auto frame = FrameRenderer::create(
        *ctx, FrameDesc{.width = kW, .height = kH, .color = ColorFormat::rgba8_srgb});
    REQUIRE(frame.has_value());
    REQUIRE_FALSE(scene->cameras.empty());
    ProbeDirectory probes;
    std::vector<std::unique_ptr<Effect>> owned;
    std::vector<Effect*> list;
    EffectRegistry registry;
    REQUIRE(register_builtin_effects(registry));
    for (const EffectSetup& setup : effects) {
      EffectCreateInfo info;
      info.context = &*ctx;
      info.color_format = frame->target().vk_color_format();
      info.scene = &*scene;
      info.probes = &probes;
      auto created = registry.create(setup.effect, info);
      REQUIRE_MESSAGE(created.has_value(), created.error().message);
      for (const auto& [key, value] : setup.params) {
        auto set = (*created)->set_param(key, value);
        REQUIRE_MESSAGE(set.has_value(), set.error().message);
      }
      list.push_back(created->get());
      owned.push_back(std::move(*created));
    }
    auto stats = list.empty()
                     ? frame->render(*renderer, scene->cameras.front(), 0.0f)
                     : frame->render(*renderer, scene->cameras.front(), 0.0f, list, scene->light);
    REQUIRE_MESSAGE(stats.has_value(), stats.error().message);
    REQUIRE(stats->effect_errors.empty());
    auto image = frame->read_color();
    REQUIRE(image.has_value());
    out.image = std::move(*image);
    out.view = make_main_view(scene->cameras.front(), kW, kH);
  }
  for (const std::string& m : ctx->validation_messages()) {
    MESSAGE(m);
  }
  CHECK(ctx->validation_error_count() == 0);
  out.scene = std::move(*scene);
  return out;
}

/// A built-in scene (or glTF file) with `effect` (none when empty), `preset` applied unless
/// empty.
Rendered render_builtin(const std::string& name, const std::string& effect = "",
                        const std::string& preset = "") {
  if (effect.empty()) {
    return render_builtin(name, std::vector<EffectSetup>{});
  }
  EffectSetup setup{effect};
  if (!preset.empty()) {
    setup.params.push_back({"preset", preset});
  }
  return render_builtin(name, std::vector<EffectSetup>{setup});
}

glm::vec3 pixel(const Image& image, glm::vec2 p) {
  const auto x = static_cast<std::uint32_t>(std::clamp(p.x, 0.0f, float(image.width - 1)));
  const auto y = static_cast<std::uint32_t>(std::clamp(p.y, 0.0f, float(image.height - 1)));
  const std::uint8_t* c = &image.rgba8[(std::size_t{y} * image.width + x) * 4];
  return glm::vec3(c[0], c[1], c[2]) / 255.0f;
}

/// The pixel where the centre of object `name` projects.
glm::vec2 object_pixel(const Rendered& r, const std::string& name) {
  for (const Object& o : r.scene.objects) {
    if (o.name == name) {
      const glm::vec4 clip = r.view.proj * r.view.view * o.world_at(0.0f)[3];
      return project_to_uv(clip, ClipConvention::vulkan) * glm::vec2(kW, kH);
    }
  }
  FAIL("no object named " << name);
  return {};
}

/// Compares with the committed reference. Tolerance: lavapipe is deterministic for one Mesa
/// build, but llvmpipe's rasteriser and texture filtering may round differently with another
/// SIMD width or LLVM version; a change of a few 8-bit steps along edges and in filtered
/// textures is expected, a shading or geometry change moves many pixels by much more. So: at
/// most 0.5% of pixels may differ by more than 16 steps in any channel, and the mean absolute
/// difference must stay under 1 step. On failure the actual and difference images are written.
void compare_with_golden(const Image& actual, const std::string& name) {
  const std::filesystem::path ref_path = std::filesystem::path(SNELL_GOLDEN_DIR) / (name + ".png");
  std::filesystem::create_directories(SNELL_GOLDEN_OUTPUT_DIR);
  const std::filesystem::path out_dir(SNELL_GOLDEN_OUTPUT_DIR);
  if (const char* update = std::getenv("SNELL_UPDATE_GOLDEN");
      update && std::string(update) == "1") {
    REQUIRE(write_png(ref_path, actual));
    MESSAGE("updated " << ref_path.string() << ": look at it before committing");
    return;
  }
  int w = 0, h = 0, comp = 0;
  unsigned char* ref = stbi_load(ref_path.string().c_str(), &w, &h, &comp, 4);
  REQUIRE_MESSAGE(ref != nullptr, "missing reference " << ref_path.string());
  REQUIRE(static_cast<std::uint32_t>(w) == actual.width);
  REQUIRE(static_cast<std::uint32_t>(h) == actual.height);
  Image diff = actual;
  std::size_t big = 0;
  double sum = 0.0;
  const std::size_t pixels = std::size_t{actual.width} * actual.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(actual.rgba8[i * 4 + c]) - int(ref[i * 4 + c]));
      worst = std::max(worst, d);
      sum += d;
      diff.rgba8[i * 4 + c] = static_cast<std::uint8_t>(std::min(255, d * 8));
    }
    diff.rgba8[i * 4 + 3] = 255;
    big += worst > 16 ? 1 : 0;
  }
  stbi_image_free(ref);
  const double mean = sum / double(pixels * 3);
  const double big_fraction = double(big) / double(pixels);
  CAPTURE(mean);
  CAPTURE(big_fraction);
  const bool ok = big_fraction <= 0.005 && mean < 1.0;
  if (!ok) {
    (void)write_png(out_dir / (name + ".actual.png"), actual);
    (void)write_png(out_dir / (name + ".diff.png"), diff);
    MESSAGE("wrote " << (out_dir / (name + ".actual.png")).string() << " and the difference");
  }
  CHECK(ok);
}

bool is_sky_like(glm::vec3 c) {
  return c.b > c.r && c.b > 0.5f;
}

} // namespace

TEST_CASE("golden: pool") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered r = render_builtin("pool");
  compare_with_golden(r.image, "pool");
  // Independent probes: the top-left corner is sky, the brick wall is red-dominant, the
  // orange ball is orange where it projects.
  CHECK(is_sky_like(pixel(r.image, {2, 2})));
  const Anchor* water = r.scene.find_anchor("water");
  REQUIRE(water != nullptr);
  const glm::vec3 ball = pixel(r.image, object_pixel(r, "ball_orange"));
  CAPTURE(ball);
  CHECK(ball.r > 0.6f);
  CHECK(ball.g > 0.2f);
  CHECK(ball.b < 0.3f);
}

TEST_CASE("golden: window") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered r = render_builtin("window");
  compare_with_golden(r.image, "window");
  CHECK(is_sky_like(pixel(r.image, {2, 2})));
  const glm::vec3 ball = pixel(r.image, object_pixel(r, "ball_blue"));
  CAPTURE(ball);
  CHECK(ball.b > ball.r + 0.2f);
}

TEST_CASE("golden: spheres") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered r = render_builtin("spheres");
  compare_with_golden(r.image, "spheres");
  const glm::vec3 probe = pixel(r.image, object_pixel(r, "probe_sphere"));
  CAPTURE(probe);
  CHECK(probe.r > 0.5f); // silver: bright and grey
  CHECK(std::fabs(probe.r - probe.b) < 0.15f);
}

TEST_CASE("golden: pool with water (default and seed preset)") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered plain = render_builtin("pool");
  for (const std::string preset : {"default", "seed"}) {
    CAPTURE(preset);
    const Rendered r = render_builtin("pool", "water", preset);
    compare_with_golden(r.image, "pool_water_" + preset);
    // Independent probes: the centre of the water rectangle, where the math projects it, now
    // shows the water surface (it differs from the plain frame); the sky corner does not change.
    const Anchor* water = r.scene.find_anchor("water");
    REQUIRE(water != nullptr);
    const glm::vec4 clip = r.view.proj * r.view.view * glm::vec4(water->position, 1.0f);
    const glm::vec2 px = project_to_uv(clip, ClipConvention::vulkan) * glm::vec2(kW, kH);
    CHECK(glm::length(pixel(r.image, px) - pixel(plain.image, px)) > 0.02f);
    CHECK(glm::length(pixel(r.image, {2, 2}) - pixel(plain.image, {2, 2})) < 1e-6f);
  }
}

/// The pixel where world point `p` projects.
glm::vec2 project_pixel(const Rendered& r, glm::vec3 p) {
  const glm::vec4 clip = r.view.proj * r.view.view * glm::vec4(p, 1.0f);
  return project_to_uv(clip, ClipConvention::vulkan) * glm::vec2(kW, kH);
}

TEST_CASE("golden: window with glass (default and seed preset) and ice") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered plain = render_builtin("window");
  const Anchor* window = plain.scene.find_anchor("window");
  REQUIRE(window != nullptr);
  // Independent probes: a point of the pane just inside its lower-left corner, over the floor
  // behind it, and one left of the frame, outside the pane.
  const glm::vec2 inside =
      project_pixel(plain, window->position + glm::vec3(-0.4f, -0.45f, 0.0f) * window->size);
  const glm::vec2 outside = project_pixel(plain, window->position + glm::vec3(-2.2f, 0.0f, 0.0f));
  struct Case {
    const char* effect;
    const char* preset;
    const char* golden;
  };
  for (const Case c :
       {Case{"glass", "default", "window_glass_default"},
        Case{"glass", "seed", "window_glass_seed"}, Case{"ice", "default", "window_ice"}}) {
    CAPTURE(c.golden);
    const Rendered r = render_builtin("window", c.effect, c.preset);
    compare_with_golden(r.image, c.golden);
    // Outside the pane nothing changes; inside, clear glass barely changes what is behind
    // (4 % reflection of a sky that is brighter than the floor), the seed's colour texture and
    // the frosted ice change it clearly.
    CHECK(glm::length(pixel(r.image, outside) - pixel(plain.image, outside)) < 1e-6f);
    const float change = glm::length(pixel(r.image, inside) - pixel(plain.image, inside));
    if (std::string(c.golden) == "window_glass_default") {
      CHECK(change < 0.15f);
    } else {
      CHECK(change > 0.05f);
    }
  }
}

TEST_CASE("golden: glTF glass grid (IOR, thickness, roughness, dispersion)") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered plain = render_builtin("glass_grid.gltf");
  const Rendered r = render_builtin("glass_grid.gltf", "glass");
  compare_with_golden(r.image, "glass_grid");
  // Probe: the top-left corner (backdrop, no glass) is unchanged; the centre of every glass
  // object, where the math projects it, differs from the opaque white object drawn without the
  // effect (the effect replaces it with what is behind it).
  CHECK(glm::length(pixel(r.image, {2, 2}) - pixel(plain.image, {2, 2})) < 1e-6f);
  int checked = 0;
  for (const Object& o : r.scene.objects) {
    const Mesh& mesh = r.scene.meshes[static_cast<std::size_t>(o.mesh)];
    if (mesh.material < 0 ||
        r.scene.materials[static_cast<std::size_t>(mesh.material)].transmission <= 0.0f) {
      continue;
    }
    CAPTURE(o.name);
    const glm::vec2 px = object_pixel(r, o.name);
    // (0.01: the 0.3-rough slab blurs light stripes into a grey close to the lit white slab.)
    CHECK(glm::length(pixel(r.image, px) - pixel(plain.image, px)) > 0.01f);
    ++checked;
  }
  CHECK(checked == 8);
}

namespace {

/// True when the eye ray through pixel `px` passes within `scale` x `radius` of `c` (scale > 1:
/// the sphere's outline grown, < 1: shrunk; edge pixels blend with what is behind).
bool in_disc(const Rendered& r, glm::vec3 c, float radius, glm::vec2 px, float scale) {
  const test::Ray ray = test::pixel_ray(r.view, kW, kH, px);
  const glm::vec3 oc = c - ray.origin;
  return glm::length(oc - glm::dot(oc, ray.dir) * ray.dir) <= scale * radius;
}

/// Fails unless `a` and `b` are equal outside the discs of `spheres` ({centre, radius}) and
/// differ inside each of them.
void check_only_spheres_change(const Rendered& a, const Rendered& b,
                               const std::vector<std::pair<glm::vec3, float>>& spheres) {
  std::size_t outside_diff = 0;
  std::vector<std::size_t> inside_diff(spheres.size(), 0);
  for (std::uint32_t y = 0; y < kH; ++y) {
    for (std::uint32_t x = 0; x < kW; ++x) {
      const glm::vec2 px(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const std::size_t i = (std::size_t{y} * kW + x) * 4;
      const bool differs = a.image.rgba8[i] != b.image.rgba8[i] ||
                           a.image.rgba8[i + 1] != b.image.rgba8[i + 1] ||
                           a.image.rgba8[i + 2] != b.image.rgba8[i + 2];
      bool near_any = false;
      for (std::size_t k = 0; k < spheres.size(); ++k) {
        if (in_disc(a, spheres[k].first, spheres[k].second, px, 1.05f)) {
          near_any = true;
          inside_diff[k] += differs && in_disc(a, spheres[k].first, spheres[k].second, px, 0.95f);
        }
      }
      outside_diff += differs && !near_any;
    }
  }
  CHECK(outside_diff == 0);
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    CAPTURE(k);
    CHECK(inside_diff[k] > 50);
  }
}

} // namespace

// Looked at: the spheres scene's mirror ball (the probe anchor's object) shows the coloured
// objects around it and the sky; a glass ball (IOR 1.51, its own sphere) at the front right
// shows the scene behind it upside down (a ball lens). Independent check: the effects change
// only the pixels of the two balls' discs, each of them clearly.
TEST_CASE("golden: spheres with a reflecting and a glass ball (dynamic_cubemap)") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const glm::vec3 glass_centre(2.6f, 0.8f, 1.2f);
  const Rendered plain = render_builtin("spheres");
  const Rendered r =
      render_builtin("spheres", std::vector<EffectSetup>{{"dynamic_cubemap"},
                                                         {"dynamic_cubemap",
                                                          {{"node", std::string()},
                                                           {"center", glass_centre},
                                                           {"radius", 0.8f},
                                                           {"surface", std::string("glass")}}}});
  compare_with_golden(r.image, "spheres_cubemap");
  const Anchor* probe = r.scene.find_anchor("probe");
  REQUIRE(probe != nullptr);
  // The glass ball is new (plain has none); the mirror ball replaces the silver one.
  check_only_spheres_change(plain, r,
                            {{probe->position, 0.5f * probe->size.x}, {glass_centre, 0.8f}});
}

// Looked at: in the room, the mirror ball near the right wall shows that wall and its two
// paintings large and near with box projection, smaller and farther without (as if the walls
// were at infinity). Independent check: the two frames differ only inside the ball's disc.
TEST_CASE("golden: room with box projection on and off (dynamic_cubemap)") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered off = render_builtin("room", std::vector<EffectSetup>{{"dynamic_cubemap"}});
  const Rendered on = render_builtin(
      "room", std::vector<EffectSetup>{{"dynamic_cubemap", {{"box_projection", true}}}});
  compare_with_golden(off.image, "room_cubemap");
  compare_with_golden(on.image, "room_cubemap_box");
  const Anchor* probe = on.scene.find_anchor("probe");
  REQUIRE(probe != nullptr);
  check_only_spheres_change(off, on, {{probe->position, 0.5f * probe->size.x}});
}

namespace {

/// True when the eye ray through pixel `px` meets the mirror scene's mirror (the quad y = 0.01,
/// x and z in [-3, 3]) in front of the eye.
bool on_mirror(const Rendered& r, glm::vec2 px, float margin) {
  const test::Ray ray = test::pixel_ray(r.view, kW, kH, px);
  if (ray.dir.y >= 0.0f) {
    return false;
  }
  const glm::vec3 hit = ray.origin + ray.dir * ((0.01f - ray.origin.y) / ray.dir.y);
  return std::abs(hit.x) <= 3.0f + margin && std::abs(hit.z) <= 3.0f + margin;
}

} // namespace

// Looked at: the mirror scene with the mirror effect shows the wall, the sky, the pedestal, the
// torus and the balls reflected in the floor mirror; rough (0.5), what touches the mirror (the
// pedestal's and the red box's feet) stays sharp while the torus and the floating orange ball
// blur. Independent check: the effect changes only pixels whose eye ray meets the mirror's
// rectangle (traced here), and many of those.
TEST_CASE("golden: mirror scene, default and rough (mirror)") {
  SNELL_GOLDEN_NEEDS_LAVAPIPE();
  const Rendered plain = render_builtin("mirror");
  const Rendered sharp = render_builtin("mirror", std::vector<EffectSetup>{{"mirror"}});
  const Rendered rough =
      render_builtin("mirror", std::vector<EffectSetup>{{"mirror", {{"roughness", 0.5f}}}});
  compare_with_golden(sharp.image, "mirror_default");
  compare_with_golden(rough.image, "mirror_rough");
  for (const Rendered* r : {&sharp, &rough}) {
    std::size_t outside = 0, inside = 0, mirror_pixels = 0;
    for (std::uint32_t y = 0; y < kH; ++y) {
      for (std::uint32_t x = 0; x < kW; ++x) {
        const glm::vec2 px(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        const std::size_t i = (std::size_t{y} * kW + x) * 4;
        const bool differs = r->image.rgba8[i] != plain.image.rgba8[i] ||
                             r->image.rgba8[i + 1] != plain.image.rgba8[i + 1] ||
                             r->image.rgba8[i + 2] != plain.image.rgba8[i + 2];
        if (!on_mirror(plain, px, 0.05f)) {
          outside += differs ? 1 : 0;
        } else if (on_mirror(plain, px, -0.05f)) {
          ++mirror_pixels;
          inside += differs ? 1 : 0;
        }
      }
    }
    CAPTURE(mirror_pixels);
    CHECK(outside == 0);
    CHECK(inside > mirror_pixels / 2);
  }
}

// What the dynamic_cubemap captures and shows, through the plugin (lavapipe, validation on):
// six markers on the faces direction_to_cube names, the owner never in its own capture, and
// refraction through the ball where a ray traced here through the sphere predicts.
#include "cube_markers.hpp"
#include "cubemap_test_support.hpp"
#include "frame_rig.hpp"

#include <snell/dynamic_cubemap.hpp>
#include <snell/math.hpp>
#include <snell/readback.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <string>

using namespace snell;

namespace {

/// A frame rig with one probe created for its scene (REQUIREs success).
std::unique_ptr<DynamicCubemapEffect> make_probe(Context& ctx, test::FrameRig& rig,
                                                 const DynamicCubemapParams& p) {
  auto created = create_dynamic_cubemap(rig.effect_info(ctx));
  REQUIRE_MESSAGE(created.has_value(), (created ? std::string() : created.error().message));
  auto r = (*created)->set_params(p);
  REQUIRE_MESSAGE(r.has_value(), (r ? std::string() : r.error().message));
  return std::move(*created);
}

/// Face `face` of the probe's published capture (its debug target) as RGBA8: linear values
/// clamped to [0, 1] times 255 (no tone curve, so the emissive markers' 1.0 stays 255).
Image probe_face(Context& ctx, const Effect& probe, std::uint32_t face) {
  static const char* const names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  const std::string name = std::string("dynamic_cubemap.face") + names[face];
  for (const DebugTarget& t : probe.debug_targets()) {
    if (t.name == name) {
      auto pixels = read_debug_target(ctx, t);
      REQUIRE_MESSAGE(pixels.has_value(), (pixels ? std::string() : pixels.error().message));
      Image out;
      out.width = pixels->width;
      out.height = pixels->height;
      for (const float v : pixels->rgba) {
        out.rgba8.push_back(static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f));
      }
      return out;
    }
  }
  FAIL("no debug target " << name);
  return {};
}

} // namespace

// Fails if the plugin captures from the wrong point, writes a face to the wrong layer, mirrors
// or rotates a face, or mixes up the capture modes: each marker must land on the face and texel
// that direction_to_cube names, with both capture modes.
TEST_CASE("dynamic_cubemap: six markers land on the faces direction_to_cube names") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  const glm::vec3 center(0.5f, 1.0f, -0.25f);
  std::array<glm::vec3, 6> offsets;
  rig.scene = test::six_marker_scene(center, offsets);
  rig.camera.eye = {0.0f, 1.0f, 8.0f};
  rig.camera.target = center;
  rig.width = 64;
  rig.height = 48;
  rig.init_frame(gpu.ctx());
  for (const char* mode : {"multiview", "six_pass"}) {
    CAPTURE(mode);
    DynamicCubemapParams p;
    p.center = center;
    p.radius = 0.1f;
    p.face_size = 64;
    p.capture = std::string(mode) == "multiview" ? CubemapCaptureMode::multiview
                                                 : CubemapCaptureMode::six_pass;
    auto probe = make_probe(gpu.ctx(), rig, p);
    Effect* effects[] = {probe.get()};
    (void)rig.render_effects(effects);
    test::check_marker_faces(
        [&](std::uint32_t f) {
          Image face = probe_face(gpu.ctx(), *probe, f);
          test::save_png(face, std::string("six_markers_") + mode + "_face" + std::to_string(f));
          return face;
        },
        64.0f, offsets);
  }
}

// Fails if the probe's owner is drawn into its own capture. The owner is one object of two
// green boxes either side of the capture point (on the +x and -x axes), with the `captured`
// layer bit: only the effect's exclusion of the object it draws keeps it out. The same boxes
// show on +x and -x when the probe stands there without owning them (the check can fail).
TEST_CASE("dynamic_cubemap: the owner never appears in its own capture") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  rig.scene = test::empty_dark_scene();
  const int green = test::add_emissive_material(rig.scene, {0.0f, 1.0f, 0.0f});
  Mesh pair = test::make_box_mesh(glm::vec3(0.3f), green);
  const Mesh right = pair;
  for (Vertex& v : pair.vertices) {
    v.position.x -= 1.5f;
  }
  const auto base = static_cast<std::uint32_t>(pair.vertices.size());
  for (Vertex v : right.vertices) {
    v.position.x += 1.5f;
    pair.vertices.push_back(v);
  }
  for (const std::uint32_t i : right.indices) {
    pair.indices.push_back(base + i);
  }
  const glm::vec3 center(0.0f, 1.0f, 0.0f);
  const int owner = test::add_object(rig.scene, pair, center);
  rig.scene.objects[static_cast<std::size_t>(owner)].name = "twin_boxes";
  REQUIRE((rig.scene.objects[static_cast<std::size_t>(owner)].layers & layer::captured) != 0);
  rig.camera.eye = {0.0f, 1.5f, 6.0f};
  rig.camera.target = center;
  rig.width = 64;
  rig.height = 48;
  rig.init_frame(gpu.ctx());
  const auto greens = [&](const Effect& probe) {
    int count = 0;
    for (std::uint32_t f = 0; f < 6; ++f) {
      count += test::find_color(probe_face(gpu.ctx(), probe, f), {0.0f, 1.0f, 0.0f}).count;
    }
    return count;
  };
  DynamicCubemapParams p;
  p.center = center;
  p.radius = 0.05f;
  p.face_size = 32;
  {
    auto bystander = make_probe(gpu.ctx(), rig, p);
    Effect* effects[] = {bystander.get()};
    (void)rig.render_effects(effects);
    CHECK(greens(*bystander) > 100);
  }
  p.node = "twin_boxes";
  auto probe = make_probe(gpu.ctx(), rig, p);
  Effect* effects[] = {probe.get()};
  (void)rig.render_effects(effects);
  REQUIRE(probe->drawn_objects().size() == 1);
  CHECK(probe->drawn_objects()[0] == owner);
  CHECK(greens(*probe) == 0);
}

// Fails if refraction bends the wrong way, ignores the far side of the sphere, or samples from
// the eye rather than along the leaving ray. A red marker hides behind a glass ball (IOR 1.5);
// for every ball pixel the test traces the eye ray into the sphere (Snell's law), across it to
// the far side and out again (glm::refract, a ray-sphere intersection: none of the shader's
// shortcuts), and predicts red where the leaving ray, cast from the centre, meets the marker.
TEST_CASE("dynamic_cubemap: refraction through the ball puts a hidden marker where tracing does") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  rig.scene = test::empty_dark_scene();
  const int red = test::add_emissive_material(rig.scene, {1.0f, 0.0f, 0.0f});
  const glm::vec3 marker(0.5f, 0.3f, -8.0f), half(0.6f, 0.6f, 0.05f);
  test::add_object(rig.scene, test::make_box_mesh(half, red), marker);
  rig.camera.eye = {0.0f, 0.0f, 6.0f};
  rig.camera.target = {0.0f, 0.0f, 0.0f};
  rig.camera.yfov = glm::radians(30.0f);
  rig.width = 240;
  rig.height = 180;
  rig.init_frame(gpu.ctx());
  constexpr float radius = 1.0f, ior = 1.5f;
  DynamicCubemapParams p;
  p.center = glm::vec3(0.0f);
  p.radius = radius;
  p.surface = CubemapSurface::refract;
  p.ior = ior;
  auto probe = make_probe(gpu.ctx(), rig, p);
  Effect* effects[] = {probe.get()};
  const Image image = rig.render_effects(effects);
  glm::vec2 predicted(0.0f), observed(0.0f);
  int predicted_count = 0, observed_count = 0;
  test::for_each_sphere_pixel(
      rig.main_view(), rig.width, rig.height, glm::vec3(0.0f), radius,
      [&](std::uint32_t x, std::uint32_t y, glm::vec3 hit, glm::vec3 d) {
        const glm::vec3 n = glm::normalize(hit);
        const glm::vec3 inside = glm::refract(d, n, 1.0f / ior);
        // The far side: hit + s inside with |.| = radius, s > 0.
        const float s = -2.0f * glm::dot(hit, inside);
        const glm::vec3 exit_normal = glm::normalize(hit + s * inside);
        glm::vec3 out = glm::refract(inside, -exit_normal, ior);
        if (glm::length(out) < 0.5f) {
          out = inside; // cannot happen in a sphere; kept as the shader's fallback
        }
        if (test::hits_box(glm::vec3(0.0f), glm::normalize(out), marker - half, marker + half)) {
          predicted += glm::vec2(x, y);
          ++predicted_count;
        }
        if (test::is_red(image, (std::size_t{y} * rig.width + x) * 4, 100)) {
          observed += glm::vec2(x, y);
          ++observed_count;
        }
      });
  REQUIRE(predicted_count > 4);
  REQUIRE(observed_count > 4);
  predicted /= static_cast<float>(predicted_count);
  observed /= static_cast<float>(observed_count);
  INFO("predicted ", predicted.x, ", ", predicted.y, " (", predicted_count, " px); observed ",
       observed.x, ", ", observed.y, " (", observed_count, " px)");
  CHECK(glm::distance(predicted, observed) < 1.5f);
  CHECK(std::abs(observed_count - predicted_count) < predicted_count / 4 + 4);
  // A ball lens turns the image over: the marker sits up and right of the axis behind the ball,
  // so it shows down and left of the ball's centre on screen (x left, y down in pixels).
  const glm::vec2 centre_px = test::predict_pixel(rig.main_view().proj * rig.main_view().view,
                                                  glm::vec3(0.0f), rig.width, rig.height);
  CHECK(observed.x < centre_px.x);
  CHECK(observed.y > centre_px.y);
}

// Fails if a probe's surface writes no depth: a far probe drawn after a near one (in the same
// line of sight) would cover it. The near ball is tinted red, the far one green; both reflect a
// white wall behind the camera, so the centre pixel is red, never green.
TEST_CASE("dynamic_cubemap: a probe's ball hides the probes behind it") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  rig.scene = test::empty_dark_scene();
  test::add_object(rig.scene,
                   test::make_box_mesh({8.0f, 8.0f, 0.1f},
                                       test::add_emissive_material(rig.scene, glm::vec3(1.0f))),
                   {0.0f, 0.0f, 12.0f});
  rig.camera.eye = {0.0f, 0.0f, 5.0f};
  rig.camera.target = {0.0f, 0.0f, 0.0f};
  rig.width = 64;
  rig.height = 48;
  rig.init_frame(gpu.ctx());
  DynamicCubemapParams p;
  p.face_size = 32;
  p.center = {0.0f, 0.0f, 0.0f};
  p.radius = 0.5f;
  p.tint = {1.0f, 0.0f, 0.0f};
  auto near = make_probe(gpu.ctx(), rig, p);
  p.center = {0.0f, 0.0f, -4.0f};
  p.radius = 1.5f;
  p.tint = {0.0f, 1.0f, 0.0f};
  auto far = make_probe(gpu.ctx(), rig, p);
  Effect* effects[] = {near.get(), far.get()}; // the far one is drawn last
  const Image image = rig.render_effects(effects);
  const std::size_t i = (std::size_t{rig.height / 2} * rig.width + rig.width / 2) * 4;
  CAPTURE(int(image.rgba8[i]));
  CAPTURE(int(image.rgba8[i + 1]));
  CHECK(image.rgba8[i] > 100);
  CHECK(image.rgba8[i + 1] < 30);
}

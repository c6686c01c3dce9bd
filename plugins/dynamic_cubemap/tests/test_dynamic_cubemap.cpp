// The dynamic cube map's own tests (lavapipe, validation on): a mirror ball shows a marker where
// reflect(view, normal) points at it from the ball's centre (predicted here by tracing every
// pixel, independently of the shaders), and multiview and six-pass captures give the same image.
#include "cubemap_test_support.hpp"
#include "frame_rig.hpp"

#include <snell/builtin_scenes.hpp>
#include <snell/dynamic_cubemap.hpp>
#include <snell/math.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <optional>

using namespace snell;
using test::for_each_sphere_pixel;
using test::hits_box;
using test::is_red;

namespace {

constexpr glm::vec3 kMarker(2.5f, 1.0f, 4.0f); // beside the camera, outside its view
constexpr glm::vec3 kMarkerHalf(0.3f);
constexpr float kRadius = 1.0f;

struct ProbeRig : test::FrameRig {
  std::unique_ptr<DynamicCubemapEffect> probe;

  void init(Context& ctx) {
    scene = test::empty_dark_scene();
    const int red = test::add_emissive_material(scene, {1.0f, 0.0f, 0.0f});
    test::add_object(scene, test::make_box_mesh(kMarkerHalf, red), kMarker);
    camera.eye = {0.0f, 0.0f, 6.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.yfov = glm::radians(45.0f);
    width = 320;
    height = 240;
    init_frame(ctx);
    auto created = create_dynamic_cubemap(effect_info(ctx));
    REQUIRE_MESSAGE(created.has_value(), (created ? std::string() : created.error().message));
    probe = std::move(*created);
    DynamicCubemapParams p;
    p.center = glm::vec3(0.0f);
    p.radius = kRadius;
    REQUIRE(probe->set_params(p).has_value());
  }
  Image render() {
    Effect* effects[] = {probe.get()};
    return render_effects(effects);
  }
};

} // namespace

// Fails if the surface looked up the wrong direction (no reflection, a flipped cube face, a
// lookup from the eye instead of the centre) or the capture missed the marker. Prediction: for
// every pixel, the eye ray meets the sphere at p with normal n; the cube (captured at the
// centre) shows the marker there when reflect(view, n), cast from the centre, hits the marker's
// box. The centroid of those pixels must match the centroid of the red pixels on the ball.
TEST_CASE("dynamic_cubemap: a mirror ball shows a marker where reflect(view, normal) points") {
  test::GpuFixture gpu;
  ProbeRig rig;
  rig.init(gpu.ctx());
  const Image image = rig.render();
  const SceneView view = rig.main_view();
  glm::vec2 predicted(0.0f), observed(0.0f);
  int predicted_count = 0, observed_count = 0;
  for_each_sphere_pixel(
      view, rig.width, rig.height, glm::vec3(0.0f), kRadius,
      [&](std::uint32_t x, std::uint32_t y, glm::vec3 p, glm::vec3 d) {
        const glm::vec3 r = glm::reflect(d, glm::normalize(p));
        if (is_red(image, (std::size_t{y} * rig.width + x) * 4, 128)) {
          observed += glm::vec2(x, y);
          ++observed_count;
        }
        if (hits_box(glm::vec3(0.0f), r, kMarker - kMarkerHalf, kMarker + kMarkerHalf)) {
          predicted += glm::vec2(x, y);
          ++predicted_count;
        }
      });
  REQUIRE(predicted_count > 4);
  REQUIRE(observed_count > 4);
  predicted /= static_cast<float>(predicted_count);
  observed /= static_cast<float>(observed_count);
  INFO("predicted ", predicted.x, ", ", predicted.y, " (", predicted_count, " px); observed ",
       observed.x, ", ", observed.y, " (", observed_count, " px)");
  CHECK(glm::distance(predicted, observed) < 1.5f);
  // The marker itself is outside the camera's view: every red pixel is the reflection.
  CHECK(observed_count < predicted_count * 2);
}

// Fails if the two capture paths put a face in a different place or orientation. (On lavapipe
// both are six passes, see CubemapCaptureMode::multiview; on a GPU this compares the paths.)
TEST_CASE("dynamic_cubemap: multiview and six-pass captures give the same image") {
  test::GpuFixture gpu;
  ProbeRig rig;
  rig.init(gpu.ctx());
  const Image multiview = rig.render();
  REQUIRE(rig.probe->set_param("capture", std::string("six_pass")).has_value());
  const Image six = rig.render();
  int worst = 0;
  for (std::size_t i = 0; i < six.rgba8.size(); ++i) {
    worst = std::max(worst, std::abs(int(six.rgba8[i]) - int(multiview.rgba8[i])));
  }
  CHECK(worst <= 2);
  // The owner is the effect's own sphere here: nothing of the scene is hidden.
  CHECK(rig.probe->drawn_objects().empty());
}

// Fails if `node` is ignored (the green sphere keeps its own shading), if the owner is not left
// out of the scene renderer, or if an unknown name is accepted or changes anything.
TEST_CASE("dynamic_cubemap: node attaches the probe to a scene object, unknown names refused") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  test::init_spheres_rig(gpu.ctx(), rig, 320, 180);
  auto created = create_dynamic_cubemap(rig.effect_info(gpu.ctx()));
  REQUIRE_MESSAGE(created.has_value(), (created ? std::string() : created.error().message));
  std::unique_ptr<DynamicCubemapEffect> probe = std::move(*created);
  int green = -1;
  for (std::size_t i = 0; i < rig.scene.objects.size(); ++i) {
    if (rig.scene.objects[i].name == "sphere_green") {
      green = static_cast<int>(i);
    }
  }
  REQUIRE(green >= 0);
  const glm::vec3 centre(rig.scene.objects[static_cast<std::size_t>(green)].world_at(0.0f)[3]);
  const SceneView view = rig.main_view();
  const glm::vec2 px = test::predict_pixel(view.proj * view.view, centre, rig.width, rig.height);
  const auto at = [&](const Image& image) {
    const std::size_t i =
        (static_cast<std::size_t>(px.y) * image.width + static_cast<std::size_t>(px.x)) * 4;
    return glm::ivec3(image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2]);
  };
  Effect* effects[] = {probe.get()};
  const glm::ivec3 before = at(rig.render_effects(effects)); // the anchor's probe ball
  CHECK(before.g > before.r + 40);                           // the green sphere, lit

  auto bad = probe->set_param("node", std::string("no_such_object"));
  REQUIRE_FALSE(bad.has_value());
  CHECK(bad.error().message.find("dynamic_cubemap.node") != std::string::npos);
  CHECK(bad.error().message.find("no_such_object") != std::string::npos);
  // The anchor's object is the default owner, by name; the refused value changed nothing.
  CHECK(std::get<std::string>(*probe->get_param("node")) == "probe_sphere");

  REQUIRE(probe->set_param("node", std::string("sphere_green")).has_value());
  const glm::vec3 after = at(rig.render_effects(effects));
  const Span<const int> drawn = probe->drawn_objects();
  REQUIRE(drawn.size() == 1);
  CHECK(drawn[0] == green);
  // A mirror now: at its centre it reflects what is behind the camera, not green paint.
  CHECK_FALSE(after.g > after.r + 40);
}

namespace {

/// The pixels of `image` whose eye ray meets the sphere (centre `c`, radius `r`) of `view`.
std::vector<std::uint8_t> disc_pixels(const Image& image, const SceneView& view, glm::vec3 c,
                                      float r) {
  std::vector<std::uint8_t> out;
  // 0.9 r: away from the silhouette, whose edge pixels blend with the background.
  for_each_sphere_pixel(
      view, image.width, image.height, c, 0.9f * r,
      [&](std::uint32_t x, std::uint32_t y, glm::vec3, glm::vec3) {
        const auto i = static_cast<std::ptrdiff_t>((std::size_t{y} * image.width + x) * 4);
        out.insert(out.end(), image.rgba8.begin() + i, image.rgba8.begin() + i + 3);
      });
  return out;
}

} // namespace

// Fails if a slice shows before its cube is complete (the ball would change on a frame that
// publishes nothing), if a publication is missed, or if every_n / on_demand refresh at other
// frames. The spheres scene's boxes and torus spin, so every capture (0.5 s apart) differs.
TEST_CASE("dynamic_cubemap: refresh policies - slices are published whole, every_n, on_demand") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  test::init_spheres_rig(gpu.ctx(), rig, 256, 144);
  const Anchor* anchor = rig.scene.find_anchor("probe");
  REQUIRE(anchor != nullptr);
  const SceneView view = rig.main_view();
  auto created = create_dynamic_cubemap(rig.effect_info(gpu.ctx()));
  REQUIRE_MESSAGE(created.has_value(), (created ? std::string() : created.error().message));
  std::unique_ptr<DynamicCubemapEffect> probe = std::move(*created);
  Effect* effects[] = {probe.get()};
  float time = 0.0f;
  const auto frame = [&] {
    time += 0.5f;
    return disc_pixels(rig.render_effects(effects, time), view, anchor->position,
                       0.5f * anchor->size.x);
  };

  SUBCASE("faces_per_frame = 2: a new cube every third frame, never a partial one") {
    REQUIRE(probe->set_param("refresh", std::string("faces_per_frame")).has_value());
    REQUIRE(probe->set_param("faces_per_frame", 2).has_value());
    const std::vector<std::uint64_t> expected = {1, 1, 1, 2, 2, 2, 3};
    std::vector<std::uint8_t> previous;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      CAPTURE(k);
      const std::vector<std::uint8_t> ball = frame();
      REQUIRE_FALSE(ball.empty());
      CHECK(probe->publications() == expected[k]);
      if (k > 0) {
        const bool published = expected[k] != expected[k - 1];
        CHECK((ball != previous) == published);
      }
      previous = ball;
    }
  }
  SUBCASE("every_n = 3 and on_demand") {
    REQUIRE(probe->set_param("refresh", std::string("every_n")).has_value());
    REQUIRE(probe->set_param("refresh_n", 3).has_value());
    std::vector<std::uint64_t> seen;
    for (int k = 0; k < 6; ++k) {
      (void)frame();
      seen.push_back(probe->publications());
    }
    // Frame 1 captures, then every third frame after the last publication: 4, 7, ...
    CHECK(seen == std::vector<std::uint64_t>{1, 1, 1, 2, 2, 2});
    REQUIRE(probe->set_param("refresh", std::string("on_demand")).has_value());
    const std::vector<std::uint8_t> a = frame();
    const std::vector<std::uint8_t> b = frame();
    CHECK(probe->publications() == 2);
    CHECK(a == b);
    probe->request_update();
    const std::vector<std::uint8_t> c = frame();
    CHECK(probe->publications() == 3);
    CHECK(c != b);
  }
}

namespace {

/// Centroid of the pixels of a mirror ball (centre `c`, radius `r`) in `view` whose reflected
/// ray from the surface point hits the box `lo..hi` (the exact mirror image), and of the red
/// pixels `image` shows on the ball.
struct BallCentroids {
  glm::vec2 predicted{0.0f}, observed{0.0f};
  int predicted_count = 0, observed_count = 0;
};

BallCentroids ball_centroids(const Image& image, const SceneView& view, glm::vec3 c, float r,
                             glm::vec3 lo, glm::vec3 hi) {
  BallCentroids out;
  for_each_sphere_pixel(view, image.width, image.height, c, r,
                        [&](std::uint32_t x, std::uint32_t y, glm::vec3 p, glm::vec3 d) {
                          const glm::vec3 refl = glm::reflect(d, glm::normalize(p - c));
                          if (hits_box(p, refl, lo, hi)) {
                            out.predicted += glm::vec2(x, y);
                            ++out.predicted_count;
                          }
                          if (is_red(image, (std::size_t{y} * image.width + x) * 4, 100)) {
                            out.observed += glm::vec2(x, y);
                            ++out.observed_count;
                          }
                        });
  out.predicted /= static_cast<float>(std::max(out.predicted_count, 1));
  out.observed /= static_cast<float>(std::max(out.observed_count, 1));
  return out;
}

} // namespace

// Fails if box projection is not applied or aims from the wrong point. A marker on a room's
// side wall, a mirror ball 1.5 m from it: with box projection the ball shows the
// marker where an exact mirror reflection (traced here from the surface point) puts it; without
// it the cube is treated as infinitely far and the marker shows measurably elsewhere.
TEST_CASE("dynamic_cubemap: box projection puts a wall marker where the exact mirror does") {
  test::GpuFixture gpu;
  ProbeRig rig;
  rig.scene = test::empty_dark_scene();
  const int red = test::add_emissive_material(rig.scene, {1.0f, 0.0f, 0.0f});
  const glm::vec3 marker(2.98f, 1.0f, -1.2f), half(0.02f, 0.3f, 0.3f);
  test::add_object(rig.scene, test::make_box_mesh(half, red), marker);
  rig.camera.eye = {0.0f, 1.2f, 2.5f};
  rig.camera.target = {1.5f, 1.0f, -2.0f};
  rig.camera.yfov = glm::radians(30.0f);
  rig.width = 320;
  rig.height = 240;
  rig.init_frame(gpu.ctx());
  auto created = create_dynamic_cubemap(rig.effect_info(gpu.ctx()));
  REQUIRE(created.has_value());
  rig.probe = std::move(*created);
  const glm::vec3 centre(1.5f, 1.0f, -2.0f); // 1.5 m from the marker's wall
  constexpr float radius = 0.5f;
  DynamicCubemapParams p;
  p.center = centre;
  p.radius = radius;
  p.box_projection = true;
  p.box_min = {-3.0f, 0.0f, -3.0f};
  p.box_max = {3.0f, 3.0f, 3.0f};
  REQUIRE(rig.probe->set_params(p).has_value());
  const SceneView view = rig.main_view();
  const BallCentroids boxed =
      ball_centroids(rig.render(), view, centre, radius, marker - half, marker + half);
  INFO("boxed: predicted ", boxed.predicted.x, ", ", boxed.predicted.y, " (", boxed.predicted_count,
       "), observed ", boxed.observed.x, ", ", boxed.observed.y, " (", boxed.observed_count, ")");
  REQUIRE(boxed.predicted_count > 4);
  REQUIRE(boxed.observed_count > 4);
  CHECK(glm::distance(boxed.predicted, boxed.observed) < 1.5f);

  REQUIRE(rig.probe->set_param("box_projection", false).has_value());
  const BallCentroids far =
      ball_centroids(rig.render(), view, centre, radius, marker - half, marker + half);
  INFO("at infinity: observed ", far.observed.x, ", ", far.observed.y, " (", far.observed_count,
       ")");
  CHECK(glm::distance(far.predicted, far.observed) > 3.0f);

  // A box that is not a box is refused and changes nothing.
  p.box_max = {-4.0f, 3.0f, 3.0f};
  auto bad = rig.probe->set_params(p);
  REQUIRE_FALSE(bad.has_value());
  CHECK(bad.error().message.find("dynamic_cubemap.box_max") != std::string::npos);
  CHECK_FALSE(rig.probe->params().box_projection);
}

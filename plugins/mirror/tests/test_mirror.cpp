// The mirror effect's own tests (lavapipe, validation on). Predictions come from CPU ray tracing
// against the mirror's plane (mirror_rig.hpp), never from the shaders.
#include "mirror_rig.hpp"

#include <snell/math.hpp>

#include <glm/trigonometric.hpp>

#include <cmath>
#include <tuple>

using namespace snell;
using test::MirrorRig;
using test::Rect;

namespace {

bool is_red(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  return r > 100 && g < 60 && b < 60;
}

constexpr glm::vec3 kHalf(0.3f); // marker half size

/// The linear RGB (0..1) of pixel `px` of an RGBA8 linear image.
glm::vec3 at(const Image& image, glm::vec2 px) {
  const std::size_t i =
      (static_cast<std::size_t>(px.y) * image.width + static_cast<std::size_t>(px.x)) * 4;
  return glm::vec3(image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2]) / 255.0f;
}

/// Checks that the red marker `marker` shows in mirror `r` where the traced reflection puts it.
void check_marker(const Image& image, const SceneView& view, const Rect& r, glm::vec3 marker,
                  float tolerance_px = 1.5f) {
  const test::Centroids c =
      test::mirror_centroids(image, view, r, marker - kHalf, marker + kHalf, is_red);
  INFO("predicted ", c.predicted.x, ", ", c.predicted.y, " (", c.predicted_count, " px); observed ",
       c.observed.x, ", ", c.observed.y, " (", c.observed_count, " px)");
  REQUIRE(c.predicted_count > 10);
  REQUIRE(c.observed_count > 10);
  CHECK(glm::distance(c.predicted, c.observed) < tolerance_px);
  CHECK(std::abs(c.observed_count - c.predicted_count) < c.predicted_count / 4 + 8);
}

} // namespace

// Fails if the mirrored view is wrong (a flipped or unmirrored image, a reflection about the
// wrong plane, a misregistered lookup). A wall mirror facing +Z with the marker behind the
// camera (only the mirror can show it), and a floor mirror given as a scene node ("Mirror", a
// quad) with the marker above it: the red pixels' centroid is where the traced reflection puts it.
TEST_CASE("mirror: a marker shows where its mirror image projects (wall, and floor node)") {
  test::GpuFixture gpu;
  SUBCASE("wall mirror, marker behind the camera") {
    MirrorRig rig;
    const glm::vec3 marker(-0.6f, 1.4f, 7.5f);
    test::add_object(rig.scene,
                     test::make_box_mesh(kHalf, test::add_emissive_material(rig.scene, {1, 0, 0})),
                     marker);
    rig.camera.eye = {1.0f, 1.2f, 5.0f};
    rig.camera.target = {0.0f, 1.0f, 0.0f};
    rig.init_frame(gpu.ctx());
    const Rect wall{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {4.0f, 3.0f}};
    MirrorParams p = test::rect_params(wall);
    p.tint = glm::vec3(1.0f);
    rig.add(gpu.ctx(), p);
    const Image image = rig.render_mirrors();
    check_marker(image, rig.main_view(), wall, marker);
  }
  SUBCASE("floor mirror from a node") {
    MirrorRig rig;
    const glm::vec3 marker(0.5f, 0.6f, -1.5f);
    test::add_object(rig.scene,
                     test::make_box_mesh(kHalf, test::add_emissive_material(rig.scene, {1, 0, 0})),
                     marker);
    const int grey = test::add_emissive_material(rig.scene, {0.05f, 0.05f, 0.05f});
    const int quad = test::add_object(rig.scene, test::make_quad_mesh({3.0f, 3.0f}, grey), {});
    rig.scene.objects[static_cast<std::size_t>(quad)].name = "Mirror";
    rig.camera.eye = {0.0f, 2.0f, 5.0f};
    rig.camera.target = {0.0f, 0.0f, 0.0f};
    rig.init_frame(gpu.ctx());
    MirrorParams p;
    p.node = "Mirror";
    p.tint = glm::vec3(1.0f);
    MirrorEffect& mirror = rig.add(gpu.ctx(), p);
    const Image image = rig.render_mirrors();
    CHECK(glm::length(glm::vec3(mirror.plane()) - glm::vec3(0.0f, 1.0f, 0.0f)) < 1e-5f);
    CHECK(std::abs(mirror.plane().w) < 1e-5f);
    const Rect floor{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, {6.0f, 6.0f}};
    check_marker(image, rig.main_view(), floor, marker);
  }
}

// Fails if anything behind the plane reaches the reflection: a green box behind a wall mirror
// stands between the mirrored camera and the marker's image, so without clipping it would hide
// the marker. Both clip modes must drop it, and give the same image (within 2 steps on 99.5 % of
// the pixels: their rasterisation of the clipped edge may differ by a pixel).
TEST_CASE("mirror: nothing behind the plane shows, oblique and clip-distance agree") {
  test::GpuFixture gpu;
  MirrorRig rig;
  const glm::vec3 marker(0.0f, 1.0f, 8.0f);
  test::add_object(rig.scene,
                   test::make_box_mesh(kHalf, test::add_emissive_material(rig.scene, {1, 0, 0})),
                   marker);
  // Behind the mirror (z < 0), smaller than it: the mirror hides it from the camera too.
  test::add_object(
      rig.scene,
      test::make_box_mesh({0.8f, 0.8f, 0.3f}, test::add_emissive_material(rig.scene, {0, 1, 0})),
      {0.0f, 1.0f, -1.0f});
  rig.camera.eye = {0.3f, 1.1f, 5.0f};
  rig.camera.target = {0.0f, 1.0f, 0.0f};
  rig.init_frame(gpu.ctx());
  const Rect wall{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {3.0f, 3.0f}};
  MirrorParams p = test::rect_params(wall);
  p.tint = glm::vec3(1.0f);
  MirrorEffect& mirror = rig.add(gpu.ctx(), p);
  const Image oblique = rig.render_mirrors();
  const auto greens = [](const Image& image) {
    int n = 0;
    for (std::size_t i = 0; i < image.rgba8.size(); i += 4) {
      n += image.rgba8[i + 1] > 60 && image.rgba8[i] < 60 ? 1 : 0;
    }
    return n;
  };
  CHECK(greens(oblique) == 0);
  check_marker(oblique, rig.main_view(), wall, marker);
  REQUIRE(mirror.set_param("clip", std::string("clip_distance")).has_value());
  const Image clipped = rig.render_mirrors();
  CHECK(greens(clipped) == 0);
  int off = 0;
  for (std::size_t i = 0; i < oblique.rgba8.size(); ++i) {
    off += std::abs(int(oblique.rgba8[i]) - int(clipped.rgba8[i])) > 2 ? 1 : 0;
  }
  CHECK(off <= static_cast<int>(oblique.rgba8.size() / 4 / 200));
}

namespace {

/// Width in pixels of the edge of a bright reflection on a dark ground, along row `y` from
/// column `inside` (in the reflection's plateau) to `outside` (on the ground): the pixels whose
/// red lies between 10 % and 90 % of the way from the ground's value to the plateau's.
int edge_width(const Image& image, int inside, int outside, int y) {
  const auto red = [&](int x) {
    return static_cast<float>(image.rgba8[(std::size_t(y) * image.width + std::size_t(x)) * 4]);
  };
  const float top = red(inside), ground = red(outside);
  const int step = outside < inside ? -1 : 1;
  int width = 0;
  for (int x = inside; x != outside; x += step) {
    const float t = (red(x) - ground) / std::max(top - ground, 1.0f);
    width += t > 0.1f && t < 0.9f ? 1 : 0;
  }
  return width;
}

} // namespace

// Fails if roughness does not blur, blurs without contact hardening, or blurs less as it grows.
// Two wide white panels above a floor mirror: A stands on it, B floats 1 m higher. Their
// reflections' outer edges are measured along a row through each (the 10 %..90 % transition
// between the panel's plateau and the dark ground): B's edge widens with every roughness step
// and clearly from 0 to 0.45, and at 0.45 it is wider than A's (A's edge is near the mirror).
// The panels are wide so that the blur (a few dozen pixels) never reaches their middles.
TEST_CASE("mirror: roughness widens a reflected edge monotonically, contact hardening") {
  test::GpuFixture gpu;
  MirrorRig rig;
  const int white = test::add_emissive_material(rig.scene, {1, 1, 1});
  const glm::vec3 half(1.0f, 0.3f, 0.1f);
  const glm::vec3 a(-1.4f, 0.3f, -1.5f), b(1.4f, 1.3f, -1.5f); // A touches the mirror
  test::add_object(rig.scene, test::make_box_mesh(half, white), a);
  test::add_object(rig.scene, test::make_box_mesh(half, white), b);
  rig.camera.eye = {0.0f, 1.0f, 6.0f};
  rig.camera.target = {0.0f, -0.5f, 0.0f};
  rig.camera.yfov = glm::radians(50.0f);
  rig.init_frame(gpu.ctx());
  const Rect floor{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, {10.0f, 10.0f}};
  MirrorParams p = test::rect_params(floor);
  p.tint = glm::vec3(1.0f);
  p.resolution_scale = 1.0f;
  MirrorEffect& mirror = rig.add(gpu.ctx(), p);
  const glm::mat4 vp = rig.main_view().proj * rig.main_view().view;
  const auto px = [&](glm::vec3 w) { return test::predict_pixel(vp, w, rig.width, rig.height); };
  // The reflections (the panels mirrored in y = 0): centre and outer edge of each, on screen.
  const glm::vec2 a_mid = px({a.x, -a.y, a.z + half.z});
  const glm::vec2 a_edge = px({a.x - half.x, -a.y, a.z + half.z});
  const glm::vec2 b_mid = px({b.x, -b.y, b.z + half.z});
  const glm::vec2 b_edge = px({b.x + half.x, -b.y, b.z + half.z});
  const int reach = 40; // pixels past the edge: beyond the widest blur measured
  std::vector<int> widths;
  int a_width = 0;
  for (const float roughness : {0.0f, 0.15f, 0.3f, 0.45f}) {
    CAPTURE(roughness);
    REQUIRE(mirror.set_param("roughness", roughness).has_value());
    const Image image = rig.render_mirrors();
    test::save_png(image, "roughness_" + std::to_string(static_cast<int>(roughness * 100.0f)));
    widths.push_back(
        edge_width(image, int(0.5f * (b_mid.x + b_edge.x)), int(b_edge.x) + reach, int(b_mid.y)));
    a_width =
        edge_width(image, int(0.5f * (a_mid.x + a_edge.x)), int(a_edge.x) - reach, int(a_mid.y));
  }
  INFO("B's edge widths: ", widths[0], " ", widths[1], " ", widths[2], " ", widths[3],
       "; A's at 0.45: ", a_width);
  for (std::size_t i = 1; i < widths.size(); ++i) {
    CHECK(widths[i] >= widths[i - 1]);
  }
  CHECK(widths.front() <= 2);
  CHECK(widths.back() >= widths.front() + 6);
  CHECK(widths.back() > a_width + 3);
}

// Fails if tint or Fresnel deviate from their formulas. A grey (0.8) marker seen in a wall
// mirror at full resolution, at the centre of its predicted reflection: metal = tint x 0.8 per
// channel; dielectric = base x (1 - F) + F x 0.8 with F the exact dielectric reflectance
// (snell::fresnel_dielectric, unit-tested against the literature) at that pixel's incidence.
TEST_CASE("mirror: tint and dielectric Fresnel match their formulas at a probe pixel") {
  test::GpuFixture gpu;
  MirrorRig rig;
  const glm::vec3 marker(-1.2f, 1.0f, 7.0f);
  test::add_object(
      rig.scene,
      test::make_box_mesh(glm::vec3(0.6f), test::add_emissive_material(rig.scene, glm::vec3(0.8f))),
      marker);
  rig.camera.eye = {2.0f, 1.0f, 4.0f};
  rig.camera.target = {0.0f, 1.0f, 0.0f};
  rig.init_frame(gpu.ctx());
  const Rect wall{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {5.0f, 3.0f}};
  MirrorParams p = test::rect_params(wall);
  p.resolution_scale = 1.0f;
  p.tint = {0.5f, 0.25f, 1.0f};
  MirrorEffect& mirror = rig.add(gpu.ctx(), p);
  const Image metal = rig.render_mirrors();
  const test::Centroids c = test::mirror_centroids(
      metal, rig.main_view(), wall, marker - glm::vec3(0.6f), marker + glm::vec3(0.6f),
      [](std::uint8_t r, std::uint8_t, std::uint8_t) { return r > 20; });
  REQUIRE(c.predicted_count > 50);
  const glm::vec2 probe = glm::floor(c.predicted);
  const glm::vec3 got = at(metal, probe);
  CAPTURE(got);
  CHECK(glm::length(got - p.tint * 0.8f) < 3.0f / 255.0f);

  p.tint = glm::vec3(1.0f);
  p.fresnel = MirrorFresnel::dielectric;
  p.ior = 1.5f;
  p.base_color = {0.1f, 0.2f, 0.3f};
  REQUIRE(mirror.set_params(p).has_value());
  const Image dielectric = rig.render_mirrors();
  glm::vec3 o, d;
  test::pixel_ray(rig.main_view(), rig.width, rig.height, static_cast<std::uint32_t>(probe.x),
                  static_cast<std::uint32_t>(probe.y), o, d);
  const float f = fresnel_dielectric(std::abs(glm::dot(d, wall.normal)), 1.0f / 1.5f);
  const glm::vec3 expected = p.base_color * (1.0f - f) + f * 0.8f;
  const glm::vec3 got_d = at(dielectric, probe);
  CAPTURE(f);
  CAPTURE(got_d);
  CAPTURE(expected);
  CHECK(f > 0.04f); // oblique enough to matter
  CHECK(glm::length(got_d - expected) < 3.0f / 255.0f);
}

// Fails if a bad node is accepted or changes anything, or a camera behind the mirror breaks the
// frame: a roof-shaped mesh is refused with how far it is off its plane, an unknown name is
// refused, and from behind the mirror shows back_color with no pass drawn (and no validation
// message: the fixture fails on any).
TEST_CASE("mirror: non-planar and unknown nodes refused, a camera behind renders cleanly") {
  test::GpuFixture gpu;
  MirrorRig rig;
  const int grey = test::add_emissive_material(rig.scene, {0.1f, 0.1f, 0.1f});
  Mesh roof = test::make_quad_mesh({1.0f, 1.0f}, grey);
  const std::size_t n = roof.vertices.size();
  for (std::size_t i = 0; i < n; ++i) { // a second quad, tilted up along x: a bent sheet
    Vertex v = roof.vertices[i];
    v.position.x += 2.0f;
    v.position.y = 0.4f * (v.position.x - 1.0f);
    roof.vertices.push_back(v);
  }
  const std::size_t indices = roof.indices.size();
  for (std::size_t i = 0; i < indices; ++i) {
    roof.indices.push_back(static_cast<std::uint32_t>(roof.indices[i] + n));
  }
  const int bent = test::add_object(rig.scene, roof, {0.0f, 0.0f, -3.0f});
  rig.scene.objects[static_cast<std::size_t>(bent)].name = "bent_sheet";
  rig.camera.eye = {0.0f, 1.0f, -4.0f}; // behind the wall mirror below, looking at its back
  rig.camera.target = {0.0f, 1.0f, 0.0f};
  rig.init_frame(gpu.ctx());
  const Rect wall{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {2.0f, 2.0f}};
  MirrorParams p = test::rect_params(wall);
  MirrorEffect& mirror = rig.add(gpu.ctx(), p);

  auto bad = mirror.set_param("node", std::string("bent_sheet"));
  REQUIRE_FALSE(bad.has_value());
  CAPTURE(bad.error().message);
  CHECK(bad.error().message.find("mirror.node") != std::string::npos);
  CHECK(bad.error().message.find("'bent_sheet'") != std::string::npos);
  CHECK(bad.error().message.find("not planar") != std::string::npos);
  auto unknown = mirror.set_param("node", std::string("no_such_mirror"));
  REQUIRE_FALSE(unknown.has_value());
  CHECK(unknown.error().message.find("no_such_mirror") != std::string::npos);
  CHECK(std::get<std::string>(*mirror.get_param("node")).empty());

  const Image back = rig.render_mirrors();
  const glm::vec2 centre = test::predict_pixel(rig.main_view().proj * rig.main_view().view,
                                               wall.center, rig.width, rig.height);
  CHECK(glm::length(at(back, centre) - p.back_color) < 2.0f / 255.0f);
  CHECK_FALSE(mirror.host_view().drawn);
  for (const PassTime& pass : rig.last_stats.passes) {
    CHECK(pass.name != "mirror.reflection");
  }
}

// Fails if two mirrors share or overwrite each other's pass or target: two wall mirrors turned
// toward each other's side, each with its own pass this frame, each showing the marker where
// its own traced reflection puts it.
TEST_CASE("mirror: two mirrors in one frame") {
  test::GpuFixture gpu;
  MirrorRig rig;
  const glm::vec3 marker(0.0f, 1.2f, 8.0f);
  test::add_object(rig.scene,
                   test::make_box_mesh(kHalf, test::add_emissive_material(rig.scene, {1, 0, 0})),
                   marker);
  rig.camera.eye = {0.0f, 1.1f, 5.0f};
  rig.camera.target = {0.0f, 1.0f, 0.0f};
  rig.init_frame(gpu.ctx());
  const glm::vec3 nl = glm::normalize(glm::vec3(0.15f, 0.0f, 1.0f));
  const glm::vec3 nr = glm::normalize(glm::vec3(-0.15f, 0.0f, 1.0f));
  const Rect left{{-1.3f, 1.0f, 0.0f}, nl, {0.0f, 1.0f, 0.0f}, {2.0f, 2.0f}};
  const Rect right{{1.3f, 1.0f, 0.0f}, nr, {0.0f, 1.0f, 0.0f}, {2.0f, 2.0f}};
  for (const Rect& r : {left, right}) {
    MirrorParams p = test::rect_params(r);
    p.tint = glm::vec3(1.0f);
    rig.add(gpu.ctx(), p);
  }
  const Image image = rig.render_mirrors();
  int passes = 0;
  for (const PassTime& pass : rig.last_stats.passes) {
    passes += pass.name == "mirror.reflection" ? 1 : 0;
  }
  CHECK(passes == 2);
  check_marker(image, rig.main_view(), left, marker);
  check_marker(image, rig.main_view(), right, marker);
}

// Fails if the host's projective lookup (MirrorHostView::texture_matrix, as mirror_uv in
// shaders/snell/mirror.glsl applies it) does not land where the main view sees a point of the
// mirror: on the plane, the reflection's uv is the point's screen uv.
TEST_CASE("mirror: the host view's texture matrix maps the mirror to its screen position") {
  test::GpuFixture gpu;
  MirrorRig rig;
  rig.camera.eye = {1.5f, 1.6f, 4.0f};
  rig.camera.target = {0.0f, 1.0f, 0.0f};
  rig.init_frame(gpu.ctx());
  const Rect wall{{0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {3.0f, 2.0f}};
  MirrorEffect& mirror = rig.add(gpu.ctx(), test::rect_params(wall));
  (void)rig.render_mirrors();
  const MirrorHostView host = mirror.host_view();
  CHECK(host.drawn);
  CHECK(host.color != VK_NULL_HANDLE);
  CHECK(host.sampler != VK_NULL_HANDLE);
  CHECK(host.mip_levels == 1); // a sharp mirror builds no mip chain
  CHECK(glm::length(glm::vec3(host.plane) - wall.normal) < 1e-6f);
  const glm::mat4 vp = rig.main_view().proj * rig.main_view().view;
  for (const glm::vec2 local : {glm::vec2(0.0f), glm::vec2(-1.2f, 0.7f), glm::vec2(1.4f, -0.9f)}) {
    const glm::vec3 p = wall.center + glm::vec3(local, 0.0f);
    const glm::vec4 t = host.texture_matrix * glm::vec4(p, 1.0f);
    const glm::vec2 uv = glm::vec2(t) / t.w;
    const glm::vec2 screen = project_to_uv(vp * glm::vec4(p, 1.0f), ClipConvention::vulkan);
    CAPTURE(local);
    CHECK(glm::distance(uv, screen) < 1e-4f);
  }
}

// Fails if a rough mirror's blur reads parts of the reflection target its pass did not draw
// (they hold an old clear, black): a small mirror facing up reflects only the sky, so at any
// roughness its centre keeps the sky's colour. And if a mirror writes no depth: a far mirror
// drawn after a near one that hides it must not show through.
TEST_CASE("mirror: a rough mirror keeps the sky's colour, a near mirror hides a far one") {
  test::GpuFixture gpu;
  MirrorRig rig;
  rig.scene.sky.zenith = {0.2f, 0.4f, 0.8f};
  rig.scene.sky.horizon = {0.2f, 0.4f, 0.8f};
  rig.scene.sky.ground = {0.2f, 0.4f, 0.8f};
  rig.camera.eye = {0.0f, 4.0f, 2.0f};
  rig.camera.target = {0.0f, 0.0f, 0.0f};
  rig.init_frame(gpu.ctx());
  const Rect pad{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, {0.6f, 0.6f}};
  MirrorParams p = test::rect_params(pad);
  p.tint = glm::vec3(1.0f);
  MirrorEffect& mirror = rig.add(gpu.ctx(), p);
  const glm::vec2 centre = test::predict_pixel(rig.main_view().proj * rig.main_view().view,
                                               pad.center, rig.width, rig.height);
  for (const float roughness : {0.0f, 0.4f, 0.8f}) {
    CAPTURE(roughness);
    REQUIRE(mirror.set_param("roughness", roughness).has_value());
    const glm::vec3 got = at(rig.render_mirrors(), centre);
    CAPTURE(got);
    CHECK(glm::length(got - rig.scene.sky.zenith) < 8.0f / 255.0f);
  }

  // A near mirror tinted red in front of a far one tinted green, the near one drawn first.
  MirrorRig pair;
  pair.scene.sky = rig.scene.sky;
  pair.camera.eye = {0.0f, 1.0f, 5.0f};
  pair.camera.target = {0.0f, 1.0f, 0.0f};
  pair.init_frame(gpu.ctx());
  for (const auto& [z, size, tint] :
       {std::tuple{1.0f, 1.0f, glm::vec3(1, 0, 0)}, std::tuple{-2.0f, 4.0f, glm::vec3(0, 1, 0)}}) {
    MirrorParams m = test::rect_params(
        Rect{{0.0f, 1.0f, z}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {size, size}});
    m.tint = tint;
    pair.add(gpu.ctx(), m);
  }
  const glm::vec2 middle = test::predict_pixel(pair.main_view().proj * pair.main_view().view,
                                               {0.0f, 1.0f, 1.0f}, pair.width, pair.height);
  const glm::vec3 seen = at(pair.render_mirrors(), middle);
  CAPTURE(seen);
  CHECK(seen.g < 0.05f);
}

// Fails if a mirror node vanishes from the other mirrors' passes, or if the host shades it under
// the mirror: a floor mirror given as a node with a green (emissive) material, seen in a wall
// mirror: the wall mirror shows the floor's material (no recursion) where the traced reflection
// meets the floor quad. The node is named in replaced_objects() (left out of the opaque pass
// only), never in drawn_objects() (which would hide it from every pass).
TEST_CASE("mirror: a node mirror seen in another mirror shows its surface, without recursion") {
  test::GpuFixture gpu;
  MirrorRig rig;
  const int green = test::add_emissive_material(rig.scene, {0.0f, 1.0f, 0.0f});
  const int quad = test::add_object(rig.scene, test::make_quad_mesh({1.5f, 1.5f}, green), {});
  rig.scene.objects[static_cast<std::size_t>(quad)].name = "Mirror";
  rig.camera.eye = {0.0f, 2.5f, 5.0f};
  rig.camera.target = {0.0f, 1.0f, -1.0f};
  rig.init_frame(gpu.ctx());
  MirrorParams floor_p;
  floor_p.node = "Mirror";
  MirrorEffect& floor = rig.add(gpu.ctx(), floor_p);
  const Rect wall{{0.0f, 1.5f, -2.5f}, {0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f}, {5.0f, 3.0f}};
  MirrorParams wall_p = test::rect_params(wall);
  wall_p.tint = glm::vec3(1.0f);
  rig.add(gpu.ctx(), wall_p);
  const Image image = rig.render_mirrors();
  REQUIRE(floor.replaced_objects().size() == 1);
  CHECK(floor.replaced_objects()[0] == quad);
  CHECK(floor.drawn_objects().empty());
  const test::Centroids c = test::mirror_centroids(
      image, rig.main_view(), wall, {-1.5f, -0.01f, -1.5f}, {1.5f, 0.01f, 1.5f},
      [](std::uint8_t r, std::uint8_t g, std::uint8_t b) { return g > 150 && r < 60 && b < 60; });
  INFO("predicted ", c.predicted.x, ", ", c.predicted.y, " (", c.predicted_count, " px); observed ",
       c.observed.x, ", ", c.observed.y, " (", c.observed_count, " px)");
  REQUIRE(c.predicted_count > 50);
  CHECK(glm::distance(c.predicted, c.observed) < 2.0f);
  CHECK(std::abs(c.observed_count - c.predicted_count) < c.predicted_count / 5 + 8);
}

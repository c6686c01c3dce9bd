// Pixel probes: where the math says a marker lands is where the renderer draws it.
#include "gpu_fixture.hpp"

#include <snell/math.hpp>
#include <snell/toolkit/scene_pass.hpp>

using namespace snell;

namespace {

constexpr std::uint32_t kW = 256;
constexpr std::uint32_t kH = 192;

SceneView main_view(glm::vec3 eye, glm::vec3 target) {
  SceneView v;
  v.view = look_at(eye, target, {0, 1, 0});
  v.proj = flip_clip_y(perspective(glm::radians(60.0f), float(kW) / float(kH), 0.1f, 100.0f,
                                   DepthRange::zero_to_one));
  v.eye = eye;
  v.layer_mask = layer::all;
  v.flip_front_face = needs_front_face_flip(v.view, v.proj);
  return v;
}

} // namespace

TEST_CASE("probe: a marker lands at the pixel the view-projection predicts (+-1 px)") {
  test::GpuFixture gpu;
  Scene scene = test::empty_dark_scene();
  const glm::vec3 red(1, 0, 0), green(0, 1, 0);
  const glm::vec3 p_red(1.5f, 2.0f, -1.0f);    // up and right of the target
  const glm::vec3 p_green(-2.0f, -1.0f, 0.5f); // down and left
  test::add_object(
      scene, test::make_box_mesh(glm::vec3(0.15f), test::add_emissive_material(scene, red)), p_red);
  test::add_object(scene,
                   test::make_box_mesh(glm::vec3(0.15f), test::add_emissive_material(scene, green)),
                   p_green);
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE_MESSAGE(renderer.has_value(), renderer.error().message);
  const SceneView view = main_view({0.5f, 1.0f, 8.0f}, {0, 0, 0});
  CHECK_FALSE(view.flip_front_face);
  const Image image = test::render_view(gpu.ctx(), *renderer, view, kW, kH);
  test::save_png(image, "probe_markers");
  for (const auto& [color, pos] : {std::pair{red, p_red}, std::pair{green, p_green}}) {
    const test::Blob blob = test::find_color(image, color);
    const glm::vec2 predicted = test::predict_pixel(view.proj * view.view, pos, kW, kH);
    CAPTURE(predicted);
    CAPTURE(blob.centroid);
    REQUIRE(blob.count > 16);
    CHECK(std::fabs(blob.centroid.x - predicted.x) <= 1.0f);
    CHECK(std::fabs(blob.centroid.y - predicted.y) <= 1.0f);
  }
  // World up is image up: the higher marker is nearer the top row, the right one to the right.
  CHECK(test::find_color(image, red).centroid.y < test::find_color(image, green).centroid.y);
  CHECK(test::find_color(image, red).centroid.x > test::find_color(image, green).centroid.x);
}

TEST_CASE("probe: the clip plane removes the clipped side and keeps the other") {
  test::GpuFixture gpu;
  Scene scene = test::empty_dark_scene();
  const glm::vec3 above(0, 0, 1), below(1, 1, 0);
  test::add_object(scene,
                   test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(scene, above)),
                   {-1.0f, 0.5f, 0});
  test::add_object(scene,
                   test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(scene, below)),
                   {1.0f, -0.5f, 0});
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());
  SceneView view = main_view({0, 0.5f, 6.0f}, {0, 0, 0});
  const Image both = test::render_view(gpu.ctx(), *renderer, view, kW, kH);
  CHECK(test::find_color(both, above).count > 50);
  CHECK(test::find_color(both, below).count > 50);
  view.clip_plane = Plane{{0, 1, 0}, 0.0f}; // keep y >= 0
  const Image clipped = test::render_view(gpu.ctx(), *renderer, view, kW, kH);
  test::save_png(clipped, "probe_clip_plane");
  CHECK(test::find_color(clipped, above).count == test::find_color(both, above).count);
  CHECK(test::find_color(clipped, below).count == 0);
  view.clip_plane = Plane{{0, -1, 0}, 0.0f}; // keep y <= 0
  const Image flipped = test::render_view(gpu.ctx(), *renderer, view, kW, kH);
  CHECK(test::find_color(flipped, above).count == 0);
  CHECK(test::find_color(flipped, below).count > 50);
}

TEST_CASE("probe: a mirrored view shows the mirror image with correct winding") {
  test::GpuFixture gpu;
  Scene scene = test::empty_dark_scene();
  // A box whose bottom face is red and top face is green (two single-sided quads).
  const glm::vec3 green(0, 1, 0), red(1, 0, 0), marker(0, 0, 1);
  const int top = test::add_object(
      scene, test::make_quad_mesh({0.5f, 0.5f}, test::add_emissive_material(scene, green)),
      {0, 1.5f, 0});
  Mesh bottom = test::make_quad_mesh({0.5f, 0.5f}, test::add_emissive_material(scene, red));
  for (Vertex& v : bottom.vertices) { // face down: mirror the quad through y (CCW kept)
    v.position.z = -v.position.z;
    v.normal = -v.normal;
  }
  test::add_object(scene, bottom, {0, 1.0f, 0});
  const glm::vec3 p_marker(1.2f, 2.0f, 0.3f);
  test::add_object(
      scene, test::make_box_mesh(glm::vec3(0.05f), test::add_emissive_material(scene, marker)),
      p_marker);
  (void)top;
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());

  // The camera above looks down at the quads: it sees the green top face only.
  SceneView view = main_view({0.0f, 5.0f, 4.0f}, {0, 1, 0});
  const Image direct = test::render_view(gpu.ctx(), *renderer, view, kW, kH);
  CHECK(test::find_color(direct, green).count > 100);
  CHECK(test::find_color(direct, red).count == 0);

  // Mirrored across the plane y = 0: the mirrored camera is below, looking up at the bottom.
  const Plane mirror{{0, 1, 0}, 0.0f};
  SceneView mirrored = view;
  mirrored.view = reflect_view(view.view, mirror);
  mirrored.eye = reflect_point(mirror, view.eye);
  mirrored.flip_front_face = needs_front_face_flip(mirrored.view, mirrored.proj);
  CHECK(mirrored.flip_front_face);
  const Image image = test::render_view(gpu.ctx(), *renderer, mirrored, kW, kH);
  test::save_png(image, "probe_mirrored");
  // Correct winding: the red bottom face is seen, the green top is culled (no back faces).
  CHECK(test::find_color(image, red).count > 100);
  CHECK(test::find_color(image, green).count == 0);
  // The marker appears where reflection_matrix predicts.
  const glm::vec3 mirrored_marker = reflect_point(mirror, p_marker);
  const glm::vec2 predicted = test::predict_pixel(view.proj * view.view, mirrored_marker, kW, kH);
  const glm::vec2 predicted_r =
      test::predict_pixel(view.proj * view.view * reflection_matrix(mirror), p_marker, kW, kH);
  CHECK(glm::length(predicted - predicted_r) < 1e-3f);
  const test::Blob blob = test::find_color(image, marker);
  REQUIRE(blob.count > 4);
  CAPTURE(predicted);
  CAPTURE(blob.centroid);
  CHECK(std::fabs(blob.centroid.x - predicted.x) <= 1.0f);
  CHECK(std::fabs(blob.centroid.y - predicted.y) <= 1.0f);
  // Without the front-face flip the winding is wrong: the faces swap (a test that can fail).
  mirrored.flip_front_face = false;
  const Image wrong = test::render_view(gpu.ctx(), *renderer, mirrored, kW, kH);
  CHECK(test::find_color(wrong, red).count == 0);
  CHECK(test::find_color(wrong, green).count > 100);
}

TEST_CASE("probe: culling skips what cannot show and keeps every visible pixel") {
  // Three markers: one in view, one behind the camera, one beside the view. A scissored pass
  // over the left half keeps the left marker and culls the right one; an oblique near plane
  // (a mirror's clipping) culls the marker under the plane. The image is the same as one drawn
  // with nothing to cull, and the marker that straddles the frame edge is still drawn.
  test::GpuFixture gpu;
  Scene scene = test::empty_dark_scene();
  const glm::vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
  const SceneView view = main_view({0.0f, 1.0f, 8.0f}, {0, 1, 0});
  const glm::vec3 p_left(-1.5f, 1.0f, 0.0f);   // in view, left half
  const glm::vec3 p_right(2.0f, 1.0f, 0.0f);   // in view, right half
  const glm::vec3 p_behind(0.0f, 1.0f, 12.0f); // behind the camera
  const glm::vec3 p_edge(0.0f, 5.65f, 0.0f);   // straddles the top edge (+-0.3)
  const glm::vec3 p_under(0.0f, -0.8f, 2.0f);  // below y = -0.5
  test::add_object(
      scene, test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(scene, red)), p_left);
  test::add_object(scene,
                   test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(scene, green)),
                   p_right);
  test::add_object(scene,
                   test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(scene, blue)),
                   p_behind);
  test::add_object(scene,
                   test::make_box_mesh(glm::vec3(0.3f), test::add_emissive_material(scene, blue)),
                   p_edge);
  test::add_object(
      scene, test::make_box_mesh(glm::vec3(0.2f), test::add_emissive_material(scene, {1, 1, 0})),
      p_under);
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());

  const Image full = test::render_view(gpu.ctx(), *renderer, view, kW, kH);
  CHECK(renderer->last_draw_stats().drawn == 4);
  CHECK(renderer->last_draw_stats().culled == 1); // the one behind the camera
  const test::Blob edge = test::find_color(full, blue);
  CHECK(edge.count > 8);         // the straddling marker (the only blue one in view)
  CHECK(edge.centroid.y < 8.0f); // at the top row

  SceneView left = view;
  left.scissor = {{0, 0}, {kW / 2, kH}};
  (void)test::render_view(gpu.ctx(), *renderer, left, kW, kH);
  CHECK(renderer->last_draw_stats().culled == 2); // behind, and the right one
  const glm::vec2 px = test::predict_pixel(view.proj * view.view, p_right, kW, kH);
  CHECK(px.x > kW / 2 + 10); // the right marker really projects outside the scissor

  // The mirror y = -0.5 seen from the mirrored camera, clipped by an oblique near plane (the
  // toolkit's reflection path): the marker under the mirror is culled, the others still show.
  const Plane floor{{0, 1, 0}, 0.5f};
  SceneView mirrored = mirrored_view(view, floor);
  REQUIRE(clip_view(mirrored, floor, PlaneClip::oblique) == PlaneClip::oblique);
  const Image reflected = test::render_view(gpu.ctx(), *renderer, mirrored, kW, kH);
  // Culled: behind the camera, under the mirror, and the top-edge marker, which the mirrored
  // camera (at y = -2) sees 7.35 m up at 8 m, above its 4.6 m half-height: out of view.
  CHECK(renderer->last_draw_stats().culled == 3);
  CHECK(test::find_color(reflected, red).count > 16);
  CHECK(test::find_color(reflected, green).count > 16);
  CHECK(test::find_color(reflected, {1, 1, 0}).count == 0);
  CHECK(test::find_color(reflected, blue).count == 0);
  // The same view as a clip-distance plane culls it too.
  SceneView plane_clip = view;
  plane_clip.clip_plane = floor;
  (void)test::render_view(gpu.ctx(), *renderer, plane_clip, kW, kH);
  CHECK(renderer->last_draw_stats().culled == 2);
}

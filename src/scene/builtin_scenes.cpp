// The built-in procedural scenes (layouts documented in include/snell/builtin_scenes.hpp).
// Positions are chosen so that each effect has something to show: objects under, across and
// above the water; a spinning crate wholly behind the window; colour all around the probe.
#include <snell/builtin_scenes.hpp>

#include "procedural_meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>
#include <utility>

namespace snell {
namespace {

constexpr float degrees = 3.14159265358979f / 180.0f;

// Layer rules (see the header): a planar reflection only shows what is above the water, a
// refraction only what is below it, so objects wholly on one side skip the other pass.
constexpr std::uint32_t under_water = layer::all & ~layer::reflected;
constexpr std::uint32_t above_water = layer::all & ~layer::refracted;

Material plain(std::string name, glm::vec3 colour, float roughness = 0.5f, float specular = 0.5f) {
  Material m;
  m.name = std::move(name);
  m.base_color = glm::vec4(colour, 1.0f);
  m.roughness = roughness;
  m.specular = specular;
  return m;
}

Material textured(std::string name, int image, glm::vec2 uv_scale, float roughness = 0.8f,
                  float specular = 0.2f) {
  Material m = plain(std::move(name), glm::vec3(1.0f), roughness, specular);
  m.base_color_texture = image;
  m.uv_scale = uv_scale;
  return m;
}

// The generators only fail on bad arguments; the scenes pass constants inside the ranges.
int add_image(Scene& scene, Result<Image> image, std::string name) {
  scene.images.push_back(std::move(image).value());
  scene.images.back().name = std::move(name);
  return static_cast<int>(scene.images.size()) - 1;
}

int add_material(Scene& scene, Material material) {
  scene.materials.push_back(std::move(material));
  return static_cast<int>(scene.materials.size()) - 1;
}

// Adds `mesh` drawn with material `material` and one object instancing it; returns the object.
int add_object(Scene& scene, std::string name, Mesh mesh, int material, const glm::mat4& transform,
               std::uint32_t layers = layer::all) {
  mesh.name = name;
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
  Object object;
  object.name = std::move(name);
  object.mesh = static_cast<int>(scene.meshes.size()) - 1;
  object.transform = transform;
  object.layers = layers;
  scene.objects.push_back(std::move(object));
  return static_cast<int>(scene.objects.size()) - 1;
}

glm::mat4 at(glm::vec3 position) {
  return glm::translate(glm::mat4(1.0f), position);
}

glm::mat4 at(glm::vec3 position, float angle, glm::vec3 axis) {
  return glm::rotate(at(position), angle, glm::normalize(axis));
}

// Azimuth 0 is +Z, growing toward +X (as the sphere's u).
glm::vec3 around(float azimuth_deg, float radius, float y) {
  return {radius * std::sin(azimuth_deg * degrees), y, radius * std::cos(azimuth_deg * degrees)};
}

CameraDesc camera(glm::vec3 eye, glm::vec3 target, float yfov_deg) {
  CameraDesc c;
  c.name = "default";
  c.eye = eye;
  c.target = target;
  c.yfov = yfov_deg * degrees;
  c.z_near = 0.1f;
  c.z_far = 200.0f;
  return c;
}

} // namespace

std::vector<std::string_view> builtin_scene_names() {
  return {"pool", "window", "spheres", "room", "mirror"};
}

Result<Scene> make_builtin_scene(std::string_view name) {
  if (name == "pool") {
    return make_pool_scene();
  }
  if (name == "window") {
    return make_window_scene();
  }
  if (name == "spheres") {
    return make_spheres_scene();
  }
  if (name == "room") {
    return make_room_scene();
  }
  if (name == "mirror") {
    return make_mirror_scene();
  }
  std::string known;
  for (std::string_view n : builtin_scene_names()) {
    known += (known.empty() ? "" : ", ") + std::string(n);
  }
  return fail(ErrorCode::unknown_name,
              "unknown scene '" + std::string(name) + "'; built-in scenes: " + known);
}

Scene make_pool_scene() {
  using detail::BasinPart;
  Scene s;
  s.name = "pool";
  constexpr float ground_y = 1.0f; // seed 000: ground at y = 1
  constexpr float water_y = 2.75f; // seed 000: water height
  constexpr float basin_h = 2.0f;  // rim at y = 3, just above the water
  constexpr float basin_floor = 0.25f;
  constexpr float inner = 8.0f; // water area 8 x 8
  constexpr float wall = 0.6f;
  constexpr float floor_y = ground_y + basin_floor;
  constexpr float rim_y = ground_y + basin_h;

  BrickPattern flags;
  flags.columns = 4;
  flags.rows = 4;
  flags.mortar = 0.05f;
  flags.brick = {0.66f, 0.63f, 0.57f};
  flags.joint = {0.36f, 0.34f, 0.31f};
  flags.seed = 11;
  BrickPattern tiles;
  tiles.columns = 8;
  tiles.rows = 8;
  tiles.row_offset = 0.0f;
  tiles.mortar = 0.10f;
  tiles.brick = {0.45f, 0.78f, 0.84f};
  tiles.joint = {0.93f, 0.95f, 0.96f};
  tiles.variation = 0.06f;
  tiles.seed = 12;
  const int flag_img = add_image(s, make_brick_image(512, flags), "flagstones");
  const int brick_img = add_image(s, make_brick_image(512, BrickPattern{}), "bricks");
  const int tile_img = add_image(s, make_brick_image(512, tiles), "pool_tiles");

  // Mesh uvs are in metres; uv_scale = 1 / (metres one image covers).
  const int ground_m = add_material(s, textured("flagstones", flag_img, glm::vec2(0.25f)));
  const int wall_m = add_material(s, textured("bricks", brick_img, glm::vec2(0.5f)));
  const int tile_m = add_material(s, textured("pool_tiles", tile_img, glm::vec2(0.5f), 0.4f, 0.4f));
  const int stone_m = add_material(s, textured("coping", flag_img, glm::vec2(0.5f)));

  // The ground lies below the water everywhere, so it never shows in the reflection.
  add_object(s, "ground", detail::make_plane({40.0f, 40.0f}, 8, 1.0f), ground_m,
             at({0.0f, ground_y, 0.0f}), under_water);
  add_object(s, "wall", detail::make_box({24.0f, 10.0f, 0.6f}, 1.0f), wall_m,
             at({0.0f, 6.0f, 8.0f}));
  add_object(s, "basin_inside",
             detail::make_basin({inner, inner}, basin_h, wall, basin_floor, BasinPart::inside),
             tile_m, at({0.0f, ground_y, 0.0f}));
  add_object(s, "basin_outside",
             detail::make_basin({inner, inner}, basin_h, wall, basin_floor, BasinPart::outside),
             stone_m, at({0.0f, ground_y, 0.0f}));

  // Under the water, resting on the pool floor.
  add_object(s, "stone_red", detail::make_box({0.9f, 0.6f, 0.7f}),
             add_material(s, plain("red", {0.75f, 0.12f, 0.10f}, 0.4f)),
             at({-1.8f, floor_y + 0.3f, -0.8f}, 25.0f * degrees, {0, 1, 0}), under_water);
  add_object(s, "stone_yellow", detail::make_sphere(0.45f),
             add_material(s, plain("yellow", {0.90f, 0.72f, 0.10f}, 0.3f)),
             at({1.6f, floor_y + 0.45f, 1.2f}), under_water);
  add_object(s, "ring_blue", detail::make_torus(0.55f, 0.15f),
             add_material(s, plain("blue", {0.10f, 0.25f, 0.80f}, 0.3f)),
             at({0.6f, floor_y + 0.15f, -2.2f}), under_water);
  // Across the surface: half in, half out.
  add_object(s, "ball_orange", detail::make_sphere(0.8f),
             add_material(s, plain("orange", {0.95f, 0.40f, 0.05f}, 0.25f, 0.7f)),
             at({-1.0f, 2.6f, 2.0f}));
  // Above the water: columns on the back rim corners, a sphere on a pedestal behind the pool.
  const int marble = add_material(s, plain("marble", {0.85f, 0.83f, 0.80f}, 0.3f, 0.6f));
  const float corner = 0.5f * inner + 0.5f * wall;
  for (float side : {-1.0f, 1.0f}) {
    add_object(s, side < 0.0f ? "column_left" : "column_right", detail::make_cylinder(0.25f, 2.5f),
               marble, at({side * corner, rim_y + 1.25f, corner}), above_water);
  }
  add_object(s, "pedestal", detail::make_box({0.8f, 2.4f, 0.8f}, 1.0f), stone_m,
             at({2.0f, ground_y + 1.2f, 6.2f}));
  add_object(s, "statue_sphere", detail::make_sphere(0.7f),
             add_material(s, plain("white", {0.92f, 0.92f, 0.95f}, 0.2f, 0.8f)),
             at({2.0f, ground_y + 2.4f + 0.7f, 6.2f}), above_water);

  s.anchors.push_back(Anchor{"water", {0.0f, water_y, 0.0f}, {inner, 0.0f, inner}, -1});
  s.cameras.push_back(camera({-6.0f, 8.0f, -12.0f}, {0.0f, 4.5f, 1.0f}, 50.0f));
  s.light.direction = glm::normalize(glm::vec3(0.45f, -0.7f, 0.55f));
  s.light.color = {1.0f, 0.96f, 0.88f};
  s.light.intensity = 1.0f;
  s.light.ambient = {0.22f, 0.25f, 0.30f};
  s.sky.zenith = {0.16f, 0.36f, 0.74f};
  s.sky.horizon = {0.70f, 0.80f, 0.92f};
  s.sky.ground = {0.28f, 0.26f, 0.22f};
  return s;
}

Scene make_window_scene() {
  Scene s;
  s.name = "window";
  const int checker_img = add_image(
      s, make_checker_image(256, 8, {0.85f, 0.85f, 0.82f}, {0.22f, 0.24f, 0.28f}), "floor_checker");
  const int brick_img = add_image(s, make_brick_image(512, BrickPattern{}), "bricks");
  const int crate_img = add_image(
      s, make_checker_image(256, 4, {0.90f, 0.50f, 0.15f}, {0.96f, 0.90f, 0.72f}), "crate");

  add_object(s, "floor", detail::make_plane({20.0f, 20.0f}, 4, 1.0f),
             add_material(s, textured("floor", checker_img, glm::vec2(0.25f), 0.6f, 0.3f)),
             at({0.0f, 0.0f, 0.0f}));
  add_object(s, "backdrop", detail::make_box({12.0f, 6.0f, 0.3f}, 1.0f),
             add_material(s, textured("bricks", brick_img, glm::vec2(0.5f))),
             at({0.0f, 3.0f, -5.0f}));
  add_object(s, "pedestal", detail::make_cylinder(0.6f, 0.6f),
             add_material(s, plain("stone", {0.55f, 0.55f, 0.58f}, 0.7f, 0.2f)),
             at({0.0f, 0.3f, -1.2f}));
  // Seed 003 spins its cube about Y; 0.5 rad/s is a calm turn (one revolution in ~12.6 s).
  // Turned 30 degrees at time 0 so that a still frame shows two faces.
  const int crate =
      add_object(s, "crate", detail::make_box(glm::vec3(1.4f)),
                 add_material(s, textured("crate", crate_img, glm::vec2(1.0f), 0.6f, 0.3f)),
                 at({0.0f, 1.5f, -1.2f}, 30.0f * degrees, {0, 1, 0}));
  s.objects[static_cast<std::size_t>(crate)].spin_axis = {0.0f, 1.0f, 0.0f};
  s.objects[static_cast<std::size_t>(crate)].spin_rate = 0.5f;
  add_object(s, "ball_blue", detail::make_sphere(0.4f),
             add_material(s, plain("blue", {0.10f, 0.30f, 0.85f}, 0.25f, 0.7f)),
             at({1.8f, 0.4f, -2.4f}));

  // A free-standing wooden frame around the window quad (x in [-1.4, 1.4], y in [0.5, 2.5]).
  constexpr float wz = 1.5f, half_w = 1.4f, bottom = 0.5f, top = 2.5f, bar = 0.12f;
  const int wood = add_material(s, plain("wood", {0.36f, 0.21f, 0.10f}, 0.6f, 0.3f));
  const float post_h = top + bar;
  for (float side : {-1.0f, 1.0f}) {
    add_object(s, side < 0.0f ? "frame_left" : "frame_right", detail::make_box({bar, post_h, bar}),
               wood, at({side * (half_w + 0.5f * bar), 0.5f * post_h, wz}));
  }
  add_object(s, "frame_top", detail::make_box({2.0f * half_w, bar, bar}), wood,
             at({0.0f, top + 0.5f * bar, wz}));
  add_object(s, "frame_bottom", detail::make_box({2.0f * half_w, bar, bar}), wood,
             at({0.0f, bottom - 0.5f * bar, wz}));

  s.anchors.push_back(
      Anchor{"window", {0.0f, 0.5f * (bottom + top), wz}, {2.0f * half_w, top - bottom, 0.0f}, -1});
  s.cameras.push_back(camera({0.0f, 2.1f, 6.0f}, {0.0f, 1.4f, -1.2f}, 45.0f));
  s.light.direction = glm::normalize(glm::vec3(-0.4f, -0.8f, -0.45f));
  s.light.color = {1.0f, 0.97f, 0.92f};
  s.light.ambient = {0.25f, 0.26f, 0.30f};
  s.sky.zenith = {0.25f, 0.45f, 0.80f};
  s.sky.horizon = {0.80f, 0.86f, 0.92f};
  s.sky.ground = {0.30f, 0.28f, 0.25f};
  return s;
}

Scene make_spheres_scene() {
  Scene s;
  s.name = "spheres";
  const int checker_img =
      add_image(s, make_checker_image(256, 8, {0.88f, 0.88f, 0.86f}, {0.25f, 0.27f, 0.30f}),
                "ground_checker");
  add_object(s, "ground", detail::make_plane({30.0f, 30.0f}, 6, 1.0f),
             add_material(s, textured("ground", checker_img, glm::vec2(0.25f), 0.7f, 0.2f)),
             at({0.0f, 0.0f, 0.0f}));
  add_object(s, "pedestal", detail::make_cylinder(0.45f, 0.5f),
             add_material(s, plain("stone", {0.50f, 0.50f, 0.52f}, 0.7f, 0.2f)),
             at({0.0f, 0.25f, 0.0f}));

  // The probe owner: no `captured` bit, so its own capture leaves it out (see the header).
  const glm::vec3 centre(0.0f, 1.5f, 0.0f);
  constexpr float radius = 1.0f;
  const int probe = add_object(s, "probe_sphere", detail::make_sphere(radius, 64, 32),
                               add_material(s, plain("silver", {0.90f, 0.91f, 0.93f}, 0.05f, 1.0f)),
                               at(centre), layer::all & ~layer::captured);

  // Six objects at 60 degree steps; camera 0 sits at azimuth ~34 degrees, between two of them.
  const int red_box = add_object(s, "box_red", detail::make_box(glm::vec3(1.0f)),
                                 add_material(s, plain("red", {0.85f, 0.10f, 0.08f}, 0.4f)),
                                 at(around(0.0f, 4.0f, 0.5f), 20.0f * degrees, {0, 1, 0}));
  s.objects[static_cast<std::size_t>(red_box)].spin_rate = 0.4f;
  add_object(s, "sphere_green", detail::make_sphere(0.6f),
             add_material(s, plain("green", {0.15f, 0.70f, 0.20f}, 0.3f, 0.6f)),
             at(around(60.0f, 3.5f, 2.2f)));
  // Stood on edge (its axis along world Z), tumbling about its object X axis.
  const int torus = add_object(s, "torus_blue", detail::make_torus(0.7f, 0.2f),
                               add_material(s, plain("blue", {0.12f, 0.25f, 0.85f}, 0.3f, 0.6f)),
                               at(around(120.0f, 4.0f, 1.8f), 90.0f * degrees, {1, 0, 0}));
  s.objects[static_cast<std::size_t>(torus)].spin_axis = {1.0f, 0.0f, 0.0f};
  s.objects[static_cast<std::size_t>(torus)].spin_rate = 0.8f;
  add_object(s, "column_yellow", detail::make_cylinder(0.4f, 2.2f),
             add_material(s, plain("yellow", {0.92f, 0.78f, 0.12f}, 0.4f)),
             at(around(180.0f, 4.0f, 1.1f)));
  const int purple = add_object(s, "box_purple", detail::make_box(glm::vec3(0.8f)),
                                add_material(s, plain("purple", {0.55f, 0.15f, 0.75f}, 0.3f)),
                                at(around(240.0f, 3.5f, 2.8f), 45.0f * degrees, {1, 0, 1}));
  s.objects[static_cast<std::size_t>(purple)].spin_rate = 0.6f;
  add_object(s, "sphere_cyan", detail::make_sphere(0.5f),
             add_material(s, plain("cyan", {0.10f, 0.75f, 0.80f}, 0.3f, 0.6f)),
             at(around(300.0f, 4.5f, 0.5f)));
  add_object(s, "sphere_orange", detail::make_sphere(0.35f),
             add_material(s, plain("orange", {0.95f, 0.45f, 0.08f}, 0.3f, 0.6f)),
             at({0.6f, 3.7f, -0.4f}));

  s.anchors.push_back(Anchor{"probe", centre, glm::vec3(2.0f * radius), probe});
  s.cameras.push_back(camera({5.0f, 3.4f, 7.5f}, {0.0f, 1.4f, 0.0f}, 45.0f));
  s.light.direction = glm::normalize(glm::vec3(-0.5f, -0.9f, -0.35f));
  s.light.color = {1.0f, 0.93f, 0.82f};
  s.light.ambient = {0.24f, 0.24f, 0.30f};
  s.sky.zenith = {0.12f, 0.28f, 0.70f};
  s.sky.horizon = {0.92f, 0.72f, 0.52f};
  s.sky.ground = {0.26f, 0.23f, 0.20f};
  return s;
}

Scene make_room_scene() {
  Scene s;
  s.name = "room";
  const int checker_img = add_image(
      s, make_checker_image(256, 8, {0.86f, 0.84f, 0.80f}, {0.20f, 0.22f, 0.26f}), "floor_checker");
  const int brick_img = add_image(s, make_brick_image(512, BrickPattern{}), "bricks");
  add_object(s, "floor", detail::make_plane({10.0f, 10.0f}, 4, 1.0f),
             add_material(s, textured("floor", checker_img, glm::vec2(0.5f), 0.6f, 0.3f)),
             at({0.0f, 0.0f, 0.0f}));
  // Walls and ceiling: 0.2 m boxes whose inner faces are the room's box (-5, 0, -5)..(5, 5, 5).
  constexpr float half = 5.0f, height = 5.0f, t = 0.2f;
  add_object(s, "wall_back", detail::make_box({2.0f * half, height, t}, 1.0f),
             add_material(s, textured("bricks", brick_img, glm::vec2(0.5f))),
             at({0.0f, 0.5f * height, -half - 0.5f * t}));
  add_object(s, "wall_front", detail::make_box({2.0f * half, height, t}, 1.0f),
             add_material(s, plain("plaster", {0.80f, 0.78f, 0.74f}, 0.8f, 0.1f)),
             at({0.0f, 0.5f * height, half + 0.5f * t}));
  add_object(s, "wall_right", detail::make_box({t, height, 2.0f * half}, 1.0f),
             add_material(s, plain("blue_paint", {0.18f, 0.32f, 0.70f}, 0.7f, 0.2f)),
             at({half + 0.5f * t, 0.5f * height, 0.0f}));
  add_object(s, "wall_left", detail::make_box({t, height, 2.0f * half}, 1.0f),
             add_material(s, plain("green_paint", {0.22f, 0.55f, 0.25f}, 0.7f, 0.2f)),
             at({-half - 0.5f * t, 0.5f * height, 0.0f}));
  add_object(s, "ceiling", detail::make_box({2.0f * half, t, 2.0f * half}, 1.0f),
             add_material(s, plain("ceiling", {0.90f, 0.90f, 0.88f}, 0.9f, 0.0f)),
             at({0.0f, height + 0.5f * t, 0.0f}));
  // Two paintings on the right wall, 2 cm proud of it: bright markers for box projection.
  add_object(s, "painting_yellow", detail::make_box({0.04f, 1.0f, 1.4f}, 1.0f),
             add_material(s, plain("yellow", {0.95f, 0.80f, 0.10f}, 0.5f, 0.2f)),
             at({half - 0.02f, 1.8f, -2.0f}));
  add_object(s, "painting_red", detail::make_box({0.04f, 1.2f, 0.8f}, 1.0f),
             add_material(s, plain("red", {0.85f, 0.12f, 0.08f}, 0.5f, 0.2f)),
             at({half - 0.02f, 2.0f, 1.2f}));
  add_object(s, "pedestal", detail::make_cylinder(0.35f, 0.4f),
             add_material(s, plain("stone", {0.50f, 0.50f, 0.52f}, 0.7f, 0.2f)),
             at({2.8f, 0.2f, -0.4f}));
  // The probe owner, 2.2 m from the right wall: no `captured` bit (see the header).
  const glm::vec3 centre(2.8f, 1.1f, -0.4f);
  constexpr float radius = 0.7f;
  const int probe = add_object(s, "probe_sphere", detail::make_sphere(radius, 64, 32),
                               add_material(s, plain("silver", {0.90f, 0.91f, 0.93f}, 0.05f, 1.0f)),
                               at(centre), layer::all & ~layer::captured);
  add_object(s, "box_orange", detail::make_box(glm::vec3(0.8f)),
             add_material(s, plain("orange", {0.95f, 0.45f, 0.08f}, 0.4f)),
             at({-2.5f, 0.4f, -2.5f}, 25.0f * degrees, {0, 1, 0}));
  s.anchors.push_back(Anchor{"probe", centre, glm::vec3(2.0f * radius), probe});
  s.cameras.push_back(camera({4.7f, 1.6f, 0.9f}, {2.8f, 1.0f, -0.4f}, 50.0f));
  s.light.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
  s.light.color = {1.0f, 0.96f, 0.90f};
  s.light.ambient = {0.30f, 0.30f, 0.32f};
  s.sky.zenith = {0.12f, 0.28f, 0.70f};
  s.sky.horizon = {0.80f, 0.82f, 0.86f};
  s.sky.ground = {0.26f, 0.23f, 0.20f};
  return s;
}

Scene make_mirror_scene() {
  Scene s;
  s.name = "mirror";
  const int checker_img = add_image(
      s, make_checker_image(256, 8, {0.85f, 0.85f, 0.82f}, {0.22f, 0.24f, 0.28f}), "floor_checker");
  const int brick_img = add_image(s, make_brick_image(512, BrickPattern{}), "bricks");
  add_object(s, "floor", detail::make_plane({20.0f, 20.0f}, 4, 1.0f),
             add_material(s, textured("floor", checker_img, glm::vec2(0.25f), 0.6f, 0.3f)),
             at({0.0f, 0.0f, 0.0f}));
  // The mirror: a 6 x 6 m quad 1 cm above the floor (what the scene renderer draws when no
  // effect replaces it: dark polished stone).
  constexpr float mirror_y = 0.01f;
  const int mirror = add_object(s, "mirror_floor", detail::make_plane({6.0f, 6.0f}, 1, 1.0f),
                                add_material(s, plain("dark_stone", {0.05f, 0.05f, 0.06f}, 0.2f)),
                                at({0.0f, mirror_y, 0.0f}));
  add_object(s, "wall", detail::make_box({12.0f, 5.0f, 0.3f}, 1.0f),
             add_material(s, textured("bricks", brick_img, glm::vec2(0.5f))),
             at({0.0f, 2.5f, -4.0f}));
  add_object(s, "pedestal", detail::make_cylinder(0.5f, 0.8f),
             add_material(s, plain("stone", {0.55f, 0.55f, 0.58f}, 0.7f, 0.2f)),
             at({0.0f, mirror_y + 0.4f, 0.0f}));
  const int torus = add_object(s, "torus_blue", detail::make_torus(0.55f, 0.18f),
                               add_material(s, plain("blue", {0.12f, 0.25f, 0.85f}, 0.3f, 0.6f)),
                               at({0.0f, 1.55f, 0.0f}, 90.0f * degrees, {1, 0, 0}));
  s.objects[static_cast<std::size_t>(torus)].spin_axis = {1.0f, 0.0f, 0.0f};
  s.objects[static_cast<std::size_t>(torus)].spin_rate = 0.6f;
  // Touching the mirror (sharp in a rough mirror) and floating 1 m above it (blurred).
  add_object(s, "box_red", detail::make_box(glm::vec3(0.7f)),
             add_material(s, plain("red", {0.85f, 0.10f, 0.08f}, 0.4f)),
             at({1.8f, mirror_y + 0.35f, 1.0f}, 30.0f * degrees, {0, 1, 0}));
  add_object(s, "ball_orange", detail::make_sphere(0.35f),
             add_material(s, plain("orange", {0.95f, 0.45f, 0.08f}, 0.3f, 0.6f)),
             at({-1.8f, mirror_y + 1.35f, 1.0f}));
  add_object(s, "ball_green", detail::make_sphere(0.35f),
             add_material(s, plain("green", {0.15f, 0.70f, 0.20f}, 0.3f, 0.6f)),
             at({-1.8f, mirror_y + 0.35f, -1.2f}));
  s.anchors.push_back(Anchor{"mirror", {0.0f, mirror_y, 0.0f}, {6.0f, 0.0f, 6.0f}, mirror});
  s.cameras.push_back(camera({0.0f, 2.6f, 7.0f}, {0.0f, 0.7f, 0.0f}, 45.0f));
  s.light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.5f));
  s.light.color = {1.0f, 0.96f, 0.90f};
  s.light.ambient = {0.28f, 0.28f, 0.32f};
  s.sky.zenith = {0.20f, 0.40f, 0.80f};
  s.sky.horizon = {0.80f, 0.85f, 0.92f};
  s.sky.ground = {0.30f, 0.28f, 0.25f};
  return s;
}

} // namespace snell

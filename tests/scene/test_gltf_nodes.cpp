// glTF loading: node hierarchy (TRS, matrices, composition, negative scale), scene selection,
// cameras and the directional light.
#include "gltf_builder.hpp"

#include <snell/scene.hpp>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <limits>

using namespace gltf_test;

namespace {

snell::Scene load_ok(const std::filesystem::path& path) {
  snell::Result<snell::Scene> scene = snell::load_gltf(path);
  if (!scene) {
    FAIL_CHECK(scene.error().message);
    return {};
  }
  return std::move(scene).value();
}

bool near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  return glm::length(a - b) <= eps;
}

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}

const float s45 = std::sqrt(0.5f); // sin(45 degrees): quaternions of 90 degree turns.

} // namespace

TEST_CASE("gltf: TRS node transform (translation * rotation * scale)") {
  Builder b = quad_model();
  // 90 degrees about +Y (x -> -z), uniform scale 2, then translate by (1, 2, 3).
  b.doc["nodes"][0]["translation"] = {1, 2, 3};
  b.doc["nodes"][0]["rotation"] = {0, s45, 0, s45};
  b.doc["nodes"][0]["scale"] = {2, 2, 2};
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "trs", Container::glb));
  REQUIRE(scene.objects.size() == 1);
  CHECK(near(apply(scene.objects[0].transform, {1, 0, 0}), {1, 2, 1}));
  CHECK(near(apply(scene.objects[0].transform, {0, 1, 0}), {1, 4, 3}));
}

TEST_CASE("gltf: matrix node transform (column-major)") {
  Builder b = quad_model();
  // Scale x by 3, then translate by (5, 6, 7).
  b.doc["nodes"][0]["matrix"] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "matrix", Container::glb));
  REQUIRE(scene.objects.size() == 1);
  CHECK(near(apply(scene.objects[0].transform, {1, 1, 0}), {8, 7, 7}));
}

TEST_CASE("gltf: hierarchy composes parent * child") {
  Builder b = quad_model();
  // Node 0 (the mesh) becomes the child of a new root that scales by 2 and moves by +10 x.
  b.doc["nodes"][0]["translation"] = {1, 0, 0};
  const int root =
      b.add_node({{"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}, {"children", {0}}});
  const int grand =
      b.add_node({{"rotation", {0, 0, s45, s45}}, {"children", {root}}}); // 90 about z
  b.set_scene({grand});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "tree", Container::glb));
  REQUIRE(scene.objects.size() == 1);
  // Child: (1,0,0) + (1,0,0) = (2,0,0); root: *2 + (10,0,0) = (14,0,0); grand: rotate -> (0,14,0).
  CHECK(near(apply(scene.objects[0].transform, {1, 0, 0}), {0, 14, 0}));
}

TEST_CASE("gltf: negative scale is kept (determinant < 0)") {
  Builder b = quad_model();
  b.doc["nodes"][0]["scale"] = {-1, 1, 1};
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "mirror", Container::glb));
  REQUIRE(scene.objects.size() == 1);
  CHECK(glm::determinant(scene.objects[0].transform) == doctest::Approx(-1.0));
  CHECK(near(apply(scene.objects[0].transform, {1, 0, 0}), {-1, 0, 0}));
}

TEST_CASE("gltf: the default scene is used, without one, scene 0, without scenes, all roots") {
  Builder b = quad_model();
  b.doc["nodes"].push_back({{"mesh", 0}, {"translation", {0, 5, 0}}});
  b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}, {"name", "second"}}});
  TempDir dir;
  SUBCASE("scene: 1") {
    b.doc["scene"] = 1;
    const snell::Scene scene = load_ok(b.write(dir, "s1", Container::glb));
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].transform[3] == glm::vec4(0, 5, 0, 1));
    CHECK(scene.name == "second");
  }
  SUBCASE("no scene property") {
    b.doc.erase("scene");
    const snell::Scene scene = load_ok(b.write(dir, "s0", Container::glb));
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].transform[3] == glm::vec4(0, 0, 0, 1));
    CHECK(scene.name == "s0.glb");
  }
  SUBCASE("no scenes at all") {
    b.doc.erase("scene");
    b.doc.erase("scenes");
    const snell::Scene scene = load_ok(b.write(dir, "none", Container::glb));
    CHECK(scene.objects.size() == 2);
  }
}

TEST_CASE("gltf: perspective camera from its node (looking down -Z), infinite far plane") {
  Builder b = quad_model();
  b.add("cameras", {{"type", "perspective"},
                    {"name", "main"},
                    {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 2.0}}}});
  b.add("cameras", {{"type", "perspective"},
                    {"perspective", {{"yfov", 0.9}, {"znear", 0.5}, {"zfar", 50.0}}}});
  const int c0 = b.add_node({{"camera", 0}, {"translation", {0, 1, 5}}});
  // Turned 90 degrees about +Y: -Z becomes -X.
  const int c1 =
      b.add_node({{"camera", 1}, {"translation", {3, 0, 0}}, {"rotation", {0, s45, 0, s45}}});
  b.set_scene({0, c0, c1});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "cams", Container::glb));
  REQUIRE(scene.cameras.size() == 2);
  const snell::CameraDesc& a = scene.cameras[0];
  CHECK(a.name == "main");
  CHECK(near(a.eye, {0, 1, 5}));
  CHECK(near(a.target, {0, 1, 4}));
  CHECK(near(a.up, {0, 1, 0}));
  CHECK(a.yfov == doctest::Approx(0.5));
  CHECK(a.z_near == doctest::Approx(0.1));
  CHECK(a.z_far == std::numeric_limits<float>::infinity());
  const snell::CameraDesc& c = scene.cameras[1];
  CHECK(near(c.eye, {3, 0, 0}));
  CHECK(near(c.target, {2, 0, 0}));
  CHECK(c.z_far == doctest::Approx(50.0));
}

TEST_CASE("gltf: KHR_lights_punctual directional light sets Scene::light") {
  Builder b = quad_model();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"color", {1, 0, 0}}},
      {{"type", "directional"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 3.0}}};
  // A point light (ignored), then the directional one pointing straight down: -Z turned by -90
  // degrees about X.
  const int point = b.add_node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  const int sun = b.add_node(
      {{"rotation", {-s45, 0, 0, s45}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  b.set_scene({0, point, sun});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "light", Container::glb));
  CHECK(near(scene.light.direction, {0, -1, 0}));
  CHECK(near(scene.light.color, {1.0f, 0.5f, 0.25f}));
  CHECK(scene.light.intensity == doctest::Approx(3.0));
}

TEST_CASE("gltf: without a light the default Scene::light stays") {
  TempDir dir;
  const snell::Scene scene = load_ok(quad_model().write(dir, "nolight", Container::glb));
  const snell::DirectionalLight defaults;
  CHECK(scene.light.direction == defaults.direction);
  CHECK(scene.light.color == defaults.color);
}

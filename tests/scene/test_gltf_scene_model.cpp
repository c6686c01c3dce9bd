// The scene model's methods (Object::world_at, Scene::bounds, Scene::find_anchor) and the
// internal mesh utilities the glTF loader uses (normal and tangent generation, validation).
#include "../../src/scene/mesh_utils.hpp"

#include <snell/scene.hpp>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace {

bool near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  return glm::length(a - b) <= eps;
}

snell::Vertex vertex(glm::vec3 p, glm::vec2 uv = glm::vec2(0.0f)) {
  snell::Vertex v;
  v.position = p;
  v.uv = uv;
  return v;
}

} // namespace

TEST_CASE("Object::world_at spins about the object-space axis after the transform") {
  snell::Object o;
  o.transform = glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0));
  CHECK(o.world_at(3.0f) == o.transform); // spin_rate 0: static
  o.spin_rate = 0.5f;                     // radians per second about +Y
  const float pi = 3.14159265f;
  const glm::mat4 w = o.world_at(pi); // half a turn after pi seconds... of 0.5 rad/s: 90 degrees
  CHECK(near(glm::vec3(w * glm::vec4(1, 0, 0, 1)), {5, 0, -1}));
  o.spin_axis = glm::vec3(0.0f); // An axis that cannot be normalised: no spin, no NaN.
  CHECK(o.world_at(1.0f) == o.transform);
}

TEST_CASE("Scene::bounds covers every transformed vertex, empty scene gives a zero box") {
  snell::Scene scene;
  CHECK(scene.bounds() == std::pair<glm::vec3, glm::vec3>(glm::vec3(0.0f), glm::vec3(0.0f)));
  snell::Mesh mesh;
  mesh.vertices = {vertex({-1, -1, 0}), vertex({1, 1, 0}), vertex({0, 0, 2})};
  scene.meshes.push_back(mesh);
  snell::Object a;
  a.mesh = 0;
  a.transform = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0));
  snell::Object b;
  b.mesh = 0;
  b.transform = glm::rotate(glm::mat4(1.0f), 3.14159265f / 4.0f, glm::vec3(0, 0, 1));
  snell::Object invalid; // mesh -1: not drawn, not bounded
  invalid.transform = glm::translate(glm::mat4(1.0f), glm::vec3(100, 100, 100));
  scene.objects = {a, b, invalid};
  const auto [lo, hi] = scene.bounds();
  const float r = std::sqrt(2.0f); // The rotated square's corners reach +-sqrt(2) on y exactly.
  CHECK(std::abs(lo.x) < 1e-5f);   // b's corner (-1,-1) turns to (0, -sqrt 2); a starts at x = 9.
  CHECK(lo.y == doctest::Approx(-r));
  CHECK(lo.z == doctest::Approx(0.0f));
  CHECK(hi.x == doctest::Approx(11.0f));
  CHECK(hi.y == doctest::Approx(r));
  CHECK(hi.z == doctest::Approx(2.0f));
}

TEST_CASE("Scene::find_anchor") {
  snell::Scene scene;
  CHECK(scene.find_anchor("water") == nullptr);
  scene.anchors.push_back({"water", {0, 1, 0}, {4, 0, 4}, -1});
  scene.anchors.push_back({"probe", {0, 2, 0}, {1, 1, 1}, 0});
  REQUIRE(scene.find_anchor("probe") != nullptr);
  CHECK(scene.find_anchor("probe")->object == 0);
  CHECK(scene.find_anchor("water")->position == glm::vec3(0, 1, 0));
  CHECK(scene.find_anchor("Water") == nullptr);
}

TEST_CASE("mesh_utils: smooth normals are area-weighted, flat normals unweld the vertices") {
  using snell::detail::NormalMode;
  // Two triangles sharing the edge (0,1): a big one facing +Z and a small one facing +X.
  std::vector<snell::Vertex> v = {vertex({0, 0, 0}), vertex({0, 1, 0}), vertex({-10, 0, 0}),
                                  vertex({0, 0, 0.1f})};
  std::vector<std::uint32_t> idx = {0, 1, 2, 0, 1, 3};
  std::vector<snell::Vertex> smooth = v;
  std::vector<std::uint32_t> smooth_idx = idx;
  snell::detail::generate_flat_or_smooth_normals(smooth, smooth_idx, NormalMode::smooth);
  CHECK(smooth_idx == idx);
  // Shared vertex 0: area 5 facing +Z, area 0.05 facing +X -> (0.05, 0, 5) normalised.
  CHECK(near(smooth[0].normal, glm::normalize(glm::vec3(0.05f, 0, 5))));
  CHECK(near(smooth[2].normal, {0, 0, 1}));
  CHECK(near(smooth[3].normal, {1, 0, 0}));
  snell::detail::generate_flat_or_smooth_normals(v, idx, NormalMode::flat);
  REQUIRE(v.size() == 6);
  CHECK(idx == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5});
  CHECK(near(v[0].normal, {0, 0, 1}));
  CHECK(near(v[3].normal, {1, 0, 0}));
  CHECK(v[4].position == glm::vec3(0, 1, 0));
}

TEST_CASE("mesh_utils: degenerate triangles and out-of-range indices are harmless") {
  using snell::detail::NormalMode;
  std::vector<snell::Vertex> v = {vertex({0, 0, 0}), vertex({1, 0, 0}), vertex({2, 0, 0})};
  std::vector<std::uint32_t> idx = {0, 1, 2, 0, 1, 99, 0}; // collinear, out of range, partial
  snell::detail::generate_flat_or_smooth_normals(v, idx, NormalMode::smooth);
  for (const snell::Vertex& x : v) {
    CHECK(x.normal == glm::vec3(0, 1, 0)); // No contribution: +Y.
  }
  snell::detail::generate_tangents(v, idx);
  for (const snell::Vertex& x : v) {
    CHECK(std::abs(glm::dot(glm::vec3(x.tangent), x.normal)) < 1e-6f);
    CHECK(glm::length(glm::vec3(x.tangent)) == doctest::Approx(1.0f));
    CHECK(x.tangent.w == 1.0f);
  }
  snell::detail::generate_flat_or_smooth_normals(v, idx, NormalMode::flat);
  CHECK(v.size() == 3); // Only the in-range triangle survives.
}

TEST_CASE("mesh_utils: huge but finite positions still give unit normals and tangents") {
  // Found by the fuzzer: in float, the cross product of such edges overflows to inf - inf = NaN.
  using snell::detail::NormalMode;
  for (const NormalMode mode : {NormalMode::flat, NormalMode::smooth}) {
    std::vector<snell::Vertex> v = {vertex({1.3e31f, 0, 5e19f}, {0, 0}), vertex({1, 0, 0}, {1, 0}),
                                    vertex({0, 1, 0}, {0, 1}), vertex({3e38f, -3e38f, 3e38f})};
    std::vector<std::uint32_t> idx = {0, 1, 2, 1, 2, 3};
    snell::detail::generate_flat_or_smooth_normals(v, idx, mode);
    snell::detail::generate_tangents(v, idx);
    CHECK_FALSE(snell::detail::first_non_finite_vertex(v).has_value());
    for (const snell::Vertex& x : v) {
      CHECK(glm::length(x.normal) == doctest::Approx(1.0f));
      CHECK(glm::length(glm::vec3(x.tangent)) == doctest::Approx(1.0f));
    }
  }
  CHECK(snell::detail::safe_normalize({3e38f, 3e38f, 0}).has_value());
  CHECK_FALSE(snell::detail::safe_normalize({1, 0, std::numeric_limits<float>::quiet_NaN()}));
  CHECK_FALSE(snell::detail::safe_normalize({0, 0, 0}));
}

TEST_CASE("mesh_utils: tangents follow +u, Gram-Schmidt against a tilted normal") {
  // A quad in XY with u along +X and v = 0 at the top, but normals tilted towards +X.
  std::vector<snell::Vertex> v = {vertex({-1, -1, 0}, {0, 1}), vertex({1, -1, 0}, {1, 1}),
                                  vertex({1, 1, 0}, {1, 0}), vertex({-1, 1, 0}, {0, 0})};
  const glm::vec3 n = glm::normalize(glm::vec3(1, 0, 1));
  for (snell::Vertex& x : v) {
    x.normal = n;
  }
  snell::detail::generate_tangents(v, {0, 1, 2, 0, 2, 3});
  for (const snell::Vertex& x : v) {
    CHECK(std::abs(glm::dot(glm::vec3(x.tangent), n)) < 1e-6f);
    CHECK(near(glm::vec3(x.tangent), glm::normalize(glm::vec3(1, 0, -1))));
    CHECK(x.tangent.w == 1.0f);
  }
  // Degenerate UVs (all equal): a fallback perpendicular to the normal.
  for (snell::Vertex& x : v) {
    x.uv = glm::vec2(0.5f);
  }
  snell::detail::generate_tangents(v, {0, 1, 2, 0, 2, 3});
  for (const snell::Vertex& x : v) {
    CHECK(std::abs(glm::dot(glm::vec3(x.tangent), n)) < 1e-6f);
    CHECK(glm::length(glm::vec3(x.tangent)) == doctest::Approx(1.0f));
  }
}

TEST_CASE("mesh_utils: any_perpendicular is unit and perpendicular for every axis") {
  for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1),
                            glm::vec3(0, 0, -1), glm::normalize(glm::vec3(1, 1, 1))}) {
    const glm::vec3 t = snell::detail::any_perpendicular(n);
    CHECK(glm::length(t) == doctest::Approx(1.0f));
    CHECK(std::abs(glm::dot(t, n)) < 1e-6f);
  }
}

TEST_CASE("mesh_utils: validation helpers") {
  std::vector<snell::Vertex> v = {vertex({0, 0, 0}), vertex({1, 0, 0})};
  CHECK_FALSE(snell::detail::first_non_finite_position(v).has_value());
  CHECK_FALSE(snell::detail::first_non_finite_vertex(v).has_value());
  v[1].uv.x = std::numeric_limits<float>::infinity();
  CHECK_FALSE(snell::detail::first_non_finite_position(v).has_value());
  CHECK(snell::detail::first_non_finite_vertex(v) == std::optional<std::size_t>(1));
  v[0].position.z = std::numeric_limits<float>::quiet_NaN();
  CHECK(snell::detail::first_non_finite_position(v) == std::optional<std::size_t>(0));
  CHECK_FALSE(snell::detail::first_index_out_of_range({0, 1, 1}, 2).has_value());
  CHECK(snell::detail::first_index_out_of_range({0, 2, 1, 5}, 2) == std::optional<std::size_t>(1));
}

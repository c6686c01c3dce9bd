// Procedural meshes (internal, src/scene/procedural_meshes.hpp) and textures
// (include/snell/builtin_scenes.hpp): geometry, tangent frames, winding, tiling, validation.
#include <snell/builtin_scenes.hpp>

// The mesh generators are internal to snell_scene (no public header); the test links the same
// static library, so it reaches them through the source tree.
#include "../../src/scene/procedural_meshes.hpp"

#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <tuple>

using namespace snell;

namespace snell_test {

// Shared with test_builtin_scenes.cpp: every structural invariant a renderer relies on.
// Failures are counted per kind so that a broken mesh reports one line per kind, not thousands.
void check_mesh_valid(const Mesh& mesh) {
  INFO("mesh '" << mesh.name << "'");
  REQUIRE(!mesh.vertices.empty());
  REQUIRE(!mesh.indices.empty());
  REQUIRE(mesh.indices.size() % 3 == 0);
  int bad_attr = 0, bad_normal = 0, bad_tangent = 0;
  for (const Vertex& v : mesh.vertices) {
    bad_attr += !(std::isfinite(v.position.x) && std::isfinite(v.position.y) &&
                  std::isfinite(v.position.z) && std::isfinite(v.uv.x) && std::isfinite(v.uv.y));
    bad_normal += !(std::abs(glm::length(v.normal) - 1.0f) < 1e-4f);
    const glm::vec3 t(v.tangent);
    bad_tangent += !(std::abs(glm::length(t) - 1.0f) < 1e-4f &&
                     std::abs(glm::dot(t, v.normal)) < 1e-4f && std::abs(v.tangent.w) == 1.0f);
  }
  CHECK(bad_attr == 0);
  CHECK(bad_normal == 0);
  CHECK(bad_tangent == 0);

  int out_of_range = 0, degenerate = 0, inside_out = 0, bad_u = 0, bad_handedness = 0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t id[3] = {mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]};
    if (id[0] >= mesh.vertices.size() || id[1] >= mesh.vertices.size() ||
        id[2] >= mesh.vertices.size()) {
      ++out_of_range;
      continue;
    }
    const Vertex& a = mesh.vertices[id[0]];
    const Vertex& b = mesh.vertices[id[1]];
    const Vertex& c = mesh.vertices[id[2]];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec3 face = glm::cross(e1, e2);
    if (glm::length(face) < 1e-9f) {
      ++degenerate;
      continue;
    }
    // Counter-clockwise front faces: the geometric normal agrees with the vertex normals.
    inside_out += glm::dot(face, a.normal + b.normal + c.normal) <= 0.0f;
    // The tangent frame agrees with the uvs: tangent along +u, bitangent toward -v (glTF).
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d1.y * d2.x;
    if (std::abs(det) < 1e-12f) {
      continue;
    }
    const glm::vec3 dp_du = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dp_dv = (e2 * d1.x - e1 * d2.x) / det;
    for (const Vertex* v : {&a, &b, &c}) {
      const glm::vec3 t(v->tangent);
      bad_u += glm::dot(t, dp_du) <= 0.0f;
      bad_handedness += glm::dot(glm::cross(v->normal, t) * v->tangent.w, -dp_dv) <= 0.0f;
    }
  }
  CHECK(out_of_range == 0);
  CHECK(degenerate == 0);
  CHECK(inside_out == 0);
  CHECK(bad_u == 0);
  CHECK(bad_handedness == 0);
}

} // namespace snell_test

namespace {

using snell_test::check_mesh_valid;

std::pair<glm::vec3, glm::vec3> local_bounds(const Mesh& mesh) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Vertex& v : mesh.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  return {lo, hi};
}

bool near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  return glm::length(a - b) <= eps;
}

glm::vec3 pixel(const Image& image, std::uint32_t x, std::uint32_t y) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4u;
  return {image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2]};
}

glm::vec3 decode_normal(const Image& image, std::uint32_t x, std::uint32_t y) {
  return pixel(image, x, y) / 255.0f * 2.0f - 1.0f;
}

// Largest per-channel difference between column (or row) p and column q.
int line_difference(const Image& image, bool columns, std::uint32_t p, std::uint32_t q) {
  int worst = 0;
  for (std::uint32_t k = 0; k < (columns ? image.height : image.width); ++k) {
    const glm::vec3 a = columns ? pixel(image, p, k) : pixel(image, k, p);
    const glm::vec3 b = columns ? pixel(image, q, k) : pixel(image, k, q);
    for (int ch = 0; ch < 3; ++ch) {
      worst = std::max(worst, static_cast<int>(std::abs(a[ch] - b[ch])));
    }
  }
  return worst;
}

// Tileable: the seam between the last and first column (row) differs no more than the
// neighbouring columns (rows) inside the image do.
void check_tileable(const Image& image) {
  for (bool columns : {true, false}) {
    const std::uint32_t n = columns ? image.width : image.height;
    int interior = 0;
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      interior = std::max(interior, line_difference(image, columns, i, i + 1));
    }
    INFO((columns ? "columns" : "rows"));
    CHECK(line_difference(image, columns, n - 1, 0) <= interior);
  }
}

} // namespace

TEST_CASE("procedural meshes: every generator is valid and counter-clockwise with a glTF frame") {
  using namespace snell::detail;
  check_mesh_valid(make_box({1.0f, 2.0f, 3.0f}));
  check_mesh_valid(make_box({24.0f, 10.0f, 0.6f}, 1.0f));
  check_mesh_valid(make_plane({4.0f, 6.0f}, 3));
  check_mesh_valid(make_plane({40.0f, 40.0f}, 8, 1.0f));
  check_mesh_valid(make_sphere(0.7f, 16, 8));
  check_mesh_valid(make_sphere(1.0f, 3, 2)); // the coarsest allowed
  check_mesh_valid(make_cylinder(0.4f, 2.2f, 12));
  check_mesh_valid(make_torus(0.7f, 0.2f, 24, 12));
  check_mesh_valid(make_basin({8.0f, 6.0f}, 2.0f, 0.6f, 0.25f, BasinPart::inside));
  check_mesh_valid(make_basin({8.0f, 6.0f}, 2.0f, 0.6f, 0.25f, BasinPart::outside));
}

TEST_CASE("procedural meshes: box extents and faces and uvs") {
  const Mesh box = detail::make_box({1.0f, 2.0f, 3.0f});
  CHECK(box.vertices.size() == 24);
  CHECK(box.indices.size() == 36);
  const auto [lo, hi] = local_bounds(box);
  CHECK(near(lo, {-0.5f, -1.0f, -1.5f}));
  CHECK(near(hi, {0.5f, 1.0f, 1.5f}));
  for (const Vertex& v : box.vertices) {
    // Flat faces: the normal is an axis and the vertex lies on that face's plane.
    const glm::vec3 n = glm::abs(v.normal);
    CHECK(std::max({n.x, n.y, n.z}) == doctest::Approx(1.0f));
    CHECK(glm::dot(v.position, v.normal) == doctest::Approx(glm::dot(hi, glm::abs(v.normal))));
    CHECK(v.uv.x >= 0.0f);
    CHECK(v.uv.x <= 1.0f);
    CHECK(v.uv.y >= 0.0f);
    CHECK(v.uv.y <= 1.0f);
    if (v.normal.y == 0.0f) {
      // Side faces stand upright: the image's top (v = 0) is at the top (+Y), the tangent is
      // horizontal and the bitangent points up.
      CHECK(v.uv.y == doctest::Approx(v.position.y > 0.0f ? 0.0f : 1.0f));
      CHECK(near(glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w, {0, 1, 0}));
    }
  }
  // Metre mode: uvs span the face's size in metres.
  const Mesh wall = detail::make_box({24.0f, 10.0f, 0.6f}, 1.0f);
  float u_lo = 1e9f, u_hi = -1e9f;
  for (const Vertex& v : wall.vertices) {
    if (v.normal.z > 0.5f) {
      u_lo = std::min(u_lo, v.uv.x);
      u_hi = std::max(u_hi, v.uv.x);
    }
  }
  CHECK(u_hi - u_lo == doctest::Approx(24.0f));
}

TEST_CASE("procedural meshes: curved surfaces lie where they should") {
  const Mesh sphere = detail::make_sphere(0.7f, 16, 8);
  for (const Vertex& v : sphere.vertices) {
    CHECK(glm::length(v.position) == doctest::Approx(0.7f).epsilon(1e-5));
    CHECK(near(v.normal, v.position / 0.7f, 1e-5f));
  }
  // Pole triangles are skipped rather than emitted degenerate: 2 * segments * (rings - 1).
  CHECK(sphere.indices.size() == 3u * 2u * 16u * 7u);

  const Mesh cylinder = detail::make_cylinder(0.4f, 2.2f, 12);
  const auto [clo, chi] = local_bounds(cylinder);
  CHECK(clo.y == doctest::Approx(-1.1f));
  CHECK(chi.y == doctest::Approx(1.1f));
  for (const Vertex& v : cylinder.vertices) {
    const float r = std::hypot(v.position.x, v.position.z);
    if (v.normal.y == 0.0f) {
      CHECK(r == doctest::Approx(0.4f));
    } else {
      CHECK(r <= 0.4f + 1e-5f);
      CHECK(std::abs(v.position.y) == doctest::Approx(1.1f));
    }
  }

  const Mesh torus = detail::make_torus(0.7f, 0.2f, 24, 12);
  for (const Vertex& v : torus.vertices) {
    const float ring = std::hypot(v.position.x, v.position.z) - 0.7f;
    CHECK(std::hypot(ring, v.position.y) == doctest::Approx(0.2f).epsilon(1e-4));
  }

  const Mesh plane = detail::make_plane({4.0f, 6.0f}, 3);
  CHECK(plane.vertices.size() == 16);
  for (const Vertex& v : plane.vertices) {
    CHECK(v.position.y == 0.0f);
    CHECK(near(v.normal, {0, 1, 0}));
    CHECK(near(glm::vec3(v.tangent), {1, 0, 0}));
  }
  const auto [plo, phi] = local_bounds(plane);
  CHECK(near(plo, {-2.0f, 0.0f, -3.0f}));
  CHECK(near(phi, {2.0f, 0.0f, 3.0f}));
}

TEST_CASE("procedural meshes: the basin faces into the pool inside and out of it outside") {
  const glm::vec2 inner(8.0f, 6.0f);
  const Mesh in = detail::make_basin(inner, 2.0f, 0.6f, 0.25f, detail::BasinPart::inside);
  const Mesh out = detail::make_basin(inner, 2.0f, 0.6f, 0.25f, detail::BasinPart::outside);
  const auto [ilo, ihi] = local_bounds(in);
  CHECK(near(ilo, {-4.0f, 0.25f, -3.0f}));
  CHECK(near(ihi, {4.0f, 2.0f, 3.0f}));
  for (const Vertex& v : in.vertices) {
    if (v.normal.y > 0.5f) {
      CHECK(v.position.y == doctest::Approx(0.25f)); // the floor faces up
    } else {
      // Inner walls: the normal points toward the pool's vertical axis.
      const glm::vec3 to_axis(-v.position.x, 0.0f, -v.position.z);
      CHECK(glm::dot(v.normal, to_axis) > 0.0f);
    }
  }
  const auto [olo, ohi] = local_bounds(out);
  CHECK(near(olo, {-4.6f, 0.0f, -3.6f}));
  CHECK(near(ohi, {4.6f, 2.0f, 3.6f}));
  for (const Vertex& v : out.vertices) {
    if (v.normal.y > 0.5f) {
      CHECK(v.position.y == doctest::Approx(2.0f)); // the rim
      const bool in_opening =
          std::abs(v.position.x) < 4.0f - 1e-4f && std::abs(v.position.z) < 3.0f - 1e-4f;
      CHECK(!in_opening);
    } else {
      const glm::vec3 from_axis(v.position.x, 0.0f, v.position.z);
      CHECK(glm::dot(v.normal, from_axis) > 0.0f);
    }
    CHECK(v.normal.y >= 0.0f); // no bottom face: the basin stands on the ground
  }
}

TEST_CASE("make_checker_image: cells alternate with colour a in the top-left") {
  const glm::vec3 a(1.0f, 0.5f, 0.0f), b(0.0f, 0.25f, 1.0f);
  const Result<Image> r = make_checker_image(64, 8, a, b);
  REQUIRE(r);
  const Image& image = *r;
  CHECK(image.width == 64);
  CHECK(image.height == 64);
  CHECK(image.rgba8.size() == 64u * 64u * 4u);
  CHECK(image.srgb);
  const glm::vec3 ba(255.0f, 128.0f, 0.0f), bb(0.0f, 64.0f, 255.0f);
  int wrong = 0;
  for (std::uint32_t y = 0; y < 64; ++y) {
    for (std::uint32_t x = 0; x < 64; ++x) {
      const bool even = ((x / 8) + (y / 8)) % 2 == 0;
      wrong += pixel(image, x, y) != (even ? ba : bb);
      wrong += image.rgba8[(y * 64u + x) * 4u + 3] != 255;
    }
  }
  CHECK(wrong == 0);
  check_tileable(image); // an even number of cells tiles
}

TEST_CASE("make_checker_image: arguments out of range are rejected and not clamped") {
  const glm::vec3 a(1.0f), b(0.0f);
  for (auto [size, cells, what] :
       {std::tuple{0u, 1u, "size = 0"},
        std::tuple{max_procedural_image_size + 1, 2u, "size = 8193"},
        std::tuple{64u, 0u, "cells = 0"}, std::tuple{64u, 65u, "cells = 65"}}) {
    const Result<Image> r = make_checker_image(size, cells, a, b);
    REQUIRE(!r);
    CHECK(r.error().code == ErrorCode::invalid_argument);
    CHECK(r.error().message.find("make_checker_image") != std::string::npos);
    CHECK(r.error().message.find(what) != std::string::npos);
  }
  const Result<Image> nan = make_checker_image(8, 2, glm::vec3(std::nanf("")), b);
  REQUIRE(!nan);
  CHECK(nan.error().message.find("a = ") != std::string::npos);
  const Result<Image> over = make_checker_image(8, 2, a, glm::vec3(0.0f, 1.5f, 0.0f));
  REQUIRE(!over);
  CHECK(over.error().message.find("b = ") != std::string::npos);
}

TEST_CASE("make_brick_image: tileable with joints on the edges and deterministic and validated") {
  const Result<Image> r = make_brick_image(256);
  REQUIRE(r);
  const Image& image = *r;
  CHECK(image.width == 256);
  CHECK(image.height == 256);
  CHECK(image.srgb);
  // The top row is mortar (a light joint), and so is the first column in unshifted (even)
  // rows of bricks, so repeats line up.
  const BrickPattern defaults;
  const glm::vec3 joint = defaults.joint * 255.0f;
  for (std::uint32_t k = 0; k < 256; k += 5) {
    CHECK(glm::length(pixel(image, k, 0) - joint) < 40.0f);
    if ((k / 32) % 2 == 0) {
      CHECK(glm::length(pixel(image, 0, k) - joint) < 40.0f);
    }
  }
  // Brick pixels (the middle of the first brick) are darker and redder than mortar.
  const glm::vec3 brick = pixel(image, 32, 16);
  CHECK(brick.r > brick.b);
  CHECK(glm::length(brick - joint) > 60.0f);
  check_tileable(image);

  const Result<Image> again = make_brick_image(256);
  REQUIRE(again);
  CHECK(again->rgba8 == image.rgba8);
  BrickPattern other;
  other.seed = 2;
  const Result<Image> reseeded = make_brick_image(256, other);
  REQUIRE(reseeded);
  CHECK(reseeded->rgba8 != image.rgba8);

  BrickPattern odd;
  odd.rows = 7;
  const Result<Image> bad_rows = make_brick_image(256, odd);
  REQUIRE(!bad_rows);
  CHECK(bad_rows.error().code == ErrorCode::invalid_argument);
  CHECK(bad_rows.error().message.find("pattern.rows = 7") != std::string::npos);
  const Result<Image> too_small = make_brick_image(16); // 8 rows need >= 32 pixels
  REQUIRE(!too_small);
  CHECK(too_small.error().message.find("pattern.rows") != std::string::npos);
  BrickPattern offset;
  offset.row_offset = 1.0f;
  CHECK(!make_brick_image(256, offset));
  BrickPattern mortar;
  mortar.mortar = std::nanf("");
  CHECK(!make_brick_image(256, mortar));
}

TEST_CASE("make_noise_normal_map: unit normals facing out and tileable and deterministic") {
  const Result<Image> r = make_noise_normal_map(128, 0.8f, 7);
  REQUIRE(r);
  const Image& image = *r;
  CHECK(image.width == 128);
  CHECK(image.height == 128);
  CHECK(!image.srgb); // linear data
  int bad_length = 0, bad_z = 0, bad_alpha = 0;
  glm::vec3 mean(0.0f);
  float max_tilt = 0.0f;
  for (std::uint32_t y = 0; y < 128; ++y) {
    for (std::uint32_t x = 0; x < 128; ++x) {
      const glm::vec3 n = decode_normal(image, x, y);
      bad_length += std::abs(glm::length(n) - 1.0f) > 0.02f; // 8-bit quantisation
      bad_z += n.z <= 0.0f;
      bad_alpha += image.rgba8[(y * 128u + x) * 4u + 3] != 255;
      mean += n;
      max_tilt = std::max(max_tilt, std::acos(std::min(1.0f, n.z / glm::length(n))));
    }
  }
  CHECK(bad_length == 0);
  CHECK(bad_z == 0);
  CHECK(bad_alpha == 0);
  // Whole periods of sines average to zero slope: the mean normal is straight up.
  mean /= 128.0f * 128.0f;
  CHECK(std::abs(mean.x) < 0.02f);
  CHECK(std::abs(mean.y) < 0.02f);
  // strength 0.8 bounds the slope: tilt <= atan(0.8) (+ quantisation).
  CHECK(max_tilt <= std::atan(0.8f) + 0.02f);
  CHECK(max_tilt > 0.1f); // and there are ripples
  check_tileable(image);

  const Result<Image> same = make_noise_normal_map(128, 0.8f, 7);
  REQUIRE(same);
  CHECK(same->rgba8 == image.rgba8);
  const Result<Image> other = make_noise_normal_map(128, 0.8f, 8);
  REQUIRE(other);
  CHECK(other->rgba8 != image.rgba8);
}

TEST_CASE("make_noise_normal_map: strength 0 is flat and bad arguments are rejected") {
  const Result<Image> flat = make_noise_normal_map(16, 0.0f, 1);
  REQUIRE(flat);
  for (std::size_t i = 0; i < flat->rgba8.size(); i += 4) {
    CHECK(flat->rgba8[i] == 128);
    CHECK(flat->rgba8[i + 1] == 128);
    CHECK(flat->rgba8[i + 2] == 255);
  }
  for (float strength : {-0.1f, 16.5f, std::nanf(""), std::numeric_limits<float>::infinity()}) {
    const Result<Image> r = make_noise_normal_map(16, strength, 1);
    REQUIRE(!r);
    CHECK(r.error().code == ErrorCode::invalid_argument);
    CHECK(r.error().message.find("strength") != std::string::npos);
  }
  const Result<Image> zero = make_noise_normal_map(0, 1.0f, 1);
  REQUIRE(!zero);
  CHECK(zero.error().message.find("size = 0") != std::string::npos);
}

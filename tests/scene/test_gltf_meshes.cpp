// glTF loading: mesh data (index types, non-indexed, interleaving, containers, primitive modes,
// generated normals and tangents, sparse accessors).
#include "gltf_builder.hpp"

#include <snell/scene.hpp>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>

using namespace gltf_test;

namespace {

snell::Scene load_ok(const std::filesystem::path& path, const snell::GltfLimits& limits = {}) {
  snell::Result<snell::Scene> scene = snell::load_gltf(path, limits);
  if (!scene) {
    FAIL_CHECK(scene.error().message);
    return {};
  }
  return std::move(scene).value();
}

bool near(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  return glm::length(a - b) <= eps;
}

} // namespace

TEST_CASE("gltf: indexed quad with 8, 16 and 32-bit indices") {
  for (const int type : {u8, u16, u32}) {
    CAPTURE(type);
    TempDir dir;
    const snell::Scene scene = load_ok(quad_model(type).write(dir, "quad", Container::glb));
    REQUIRE(scene.meshes.size() == 1);
    const snell::Mesh& mesh = scene.meshes[0];
    CHECK(mesh.name == "quad");
    CHECK(mesh.indices == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
    REQUIRE(mesh.vertices.size() == 4);
    const Quad q;
    for (std::size_t i = 0; i < 4; ++i) {
      CHECK(near(mesh.vertices[i].position, q.positions[i]));
      CHECK(near(mesh.vertices[i].normal, q.normals[i]));
      CHECK(mesh.vertices[i].uv == q.uvs[i]);
    }
    REQUIRE(scene.objects.size() == 1);
    CHECK(scene.objects[0].mesh == 0);
    CHECK(scene.objects[0].name == "quad-node");
  }
}

TEST_CASE("gltf: a non-indexed primitive gets indices 0..n-1") {
  Builder b;
  const int pos =
      b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
  b.set_scene({b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}})});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "soup", Container::external_bin));
  REQUIRE(scene.meshes.size() == 1);
  // No normals either: flat normals keep one vertex per corner, so the order is 0..5 as well.
  CHECK(scene.meshes[0].indices == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5});
  CHECK(scene.meshes[0].vertices[4].position == glm::vec3(1, 0, 1));
}

TEST_CASE("gltf: interleaved and separate accessors give the same vertices") {
  const Quad q;
  Builder separate = quad_model();
  Builder interleaved;
  const Builder::Interleaved a = interleaved.add_interleaved(q.positions, q.normals, q.uvs);
  const int idx = interleaved.add_indices(q.indices, u32);
  const int mesh = interleaved.add_mesh(
      {{"POSITION", a.position}, {"NORMAL", a.normal}, {"TEXCOORD_0", a.uv}}, idx);
  interleaved.set_scene({interleaved.add_node({{"mesh", mesh}})});
  TempDir dir;
  const snell::Scene s1 = load_ok(separate.write(dir, "separate", Container::glb));
  const snell::Scene s2 = load_ok(interleaved.write(dir, "interleaved", Container::glb));
  REQUIRE(s1.meshes.size() == 1);
  REQUIRE(s2.meshes.size() == 1);
  REQUIRE(s2.meshes[0].vertices.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(s2.meshes[0].vertices[i].position == s1.meshes[0].vertices[i].position);
    CHECK(s2.meshes[0].vertices[i].normal == s1.meshes[0].vertices[i].normal);
    CHECK(s2.meshes[0].vertices[i].uv == s1.meshes[0].vertices[i].uv);
    CHECK(s2.meshes[0].vertices[i].tangent == s1.meshes[0].vertices[i].tangent);
  }
  CHECK(s2.meshes[0].indices == s1.meshes[0].indices);
}

TEST_CASE("gltf: external .bin, data: URI and .glb containers load the same scene") {
  const Builder b = quad_model(u8);
  TempDir dir;
  const snell::Scene reference = load_ok(b.write(dir, "ref", Container::glb));
  for (const Container c : {Container::external_bin, Container::data_uri}) {
    CAPTURE(container_name(c));
    const snell::Scene scene = load_ok(b.write(dir, "model", c));
    REQUIRE(scene.meshes.size() == 1);
    REQUIRE(scene.meshes[0].vertices.size() == reference.meshes[0].vertices.size());
    for (std::size_t i = 0; i < scene.meshes[0].vertices.size(); ++i) {
      CHECK(scene.meshes[0].vertices[i].position == reference.meshes[0].vertices[i].position);
    }
    CHECK(scene.name ==
          (c == Container::external_bin || c == Container::data_uri ? "model.gltf" : "model.glb"));
  }
}

TEST_CASE("gltf: normalized integer texture coordinates are mapped to [0,1]") {
  Builder b;
  const Quad q;
  const int pos = b.add_positions(q.positions);
  // u8 normalized: 0 -> 0, 255 -> 1, 51 -> 0.2; u16 normalized: 65535 -> 1.
  const int uv8 =
      b.add_data(std::vector<std::uint8_t>{0, 255, 255, 255, 255, 51, 0, 0}, u8, "VEC2", 2, true);
  const int uv16 = b.add_data(std::vector<std::uint16_t>{0, 65535, 65535, 65535, 65535, 0, 0, 0},
                              u16, "VEC2", 2, true);
  const int idx = b.add_indices(q.indices, u16);
  const int m8 = b.add_mesh({{"POSITION", pos}, {"TEXCOORD_0", uv8}}, idx);
  const int m16 = b.add_mesh({{"POSITION", pos}, {"TEXCOORD_0", uv16}}, idx);
  b.set_scene({b.add_node({{"mesh", m8}}), b.add_node({{"mesh", m16}})});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "uvs", Container::glb));
  REQUIRE(scene.meshes.size() == 2);
  // Flat normals were generated (no NORMAL): vertices are per corner, in index order 0,1,2,0,2,3.
  const std::vector<snell::Vertex>& v8 = scene.meshes[0].vertices;
  REQUIRE(v8.size() == 6);
  CHECK(v8[1].uv == glm::vec2(1.0f, 1.0f));
  CHECK(v8[2].uv.x == doctest::Approx(1.0));
  CHECK(v8[2].uv.y == doctest::Approx(0.2));
  CHECK(scene.meshes[1].vertices[1].uv == glm::vec2(1.0f, 1.0f));
  CHECK(scene.meshes[1].vertices[2].uv == glm::vec2(1.0f, 0.0f));
}

TEST_CASE("gltf: triangle strips and fans become triangle lists with the same winding") {
  Builder b;
  // Strip order for a quad: bottom-left, bottom-right, top-left, top-right.
  const int strip_pos = b.add_positions({{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}});
  // Fan: centre first, then the rim counter-clockwise.
  const int fan_pos = b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}});
  const int s = b.add_mesh({{"POSITION", strip_pos}}, -1, -1, strip);
  const int f = b.add_mesh({{"POSITION", fan_pos}}, -1, -1, fan);
  b.set_scene({b.add_node({{"mesh", s}}), b.add_node({{"mesh", f}})});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "modes", Container::data_uri));
  REQUIRE(scene.meshes.size() == 2);
  CHECK(scene.meshes[0].indices.size() == 6); // 2 triangles
  CHECK(scene.meshes[1].indices.size() == 9); // 3 triangles
  for (const snell::Mesh& mesh : scene.meshes) {
    for (const snell::Vertex& v : mesh.vertices) {
      CHECK(near(v.normal, {0, 0, 1})); // Every triangle kept the counter-clockwise winding.
    }
  }
  // Strip triangle 1 is (v1, v3, v2) per glTF, i.e. bottom-right, top-right, top-left.
  CHECK(scene.meshes[0].vertices[3].position == glm::vec3(1, -1, 0));
  CHECK(scene.meshes[0].vertices[4].position == glm::vec3(1, 1, 0));
  CHECK(scene.meshes[0].vertices[5].position == glm::vec3(-1, 1, 0));
}

TEST_CASE("gltf: points and lines primitives are skipped, triangles kept") {
  Builder b;
  const Quad q;
  const int pos = b.add_positions(q.positions);
  const int idx = b.add_indices(q.indices, u16);
  json mesh = {
      {"name", "mixed"},
      {"primitives", json::array({{{"attributes", {{"POSITION", pos}}}, {"mode", points}},
                                  {{"attributes", {{"POSITION", pos}}}, {"indices", idx}},
                                  {{"attributes", {{"POSITION", pos}}}, {"mode", lines}}})}};
  const int mixed = b.add("meshes", mesh);
  const int only_lines = b.add_mesh({{"POSITION", pos}}, -1, -1, lines);
  b.set_scene({b.add_node({{"mesh", mixed}}), b.add_node({{"mesh", only_lines}})});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "mixed", Container::glb));
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].name == "mixed/1"); // Named after the glTF mesh and primitive.
  REQUIRE(scene.objects.size() == 1);       // The lines-only node contributes nothing.
  CHECK(scene.objects[0].mesh == 0);
}

TEST_CASE("gltf: generated normals are flat and follow the winding") {
  TempDir dir;
  Builder ccw = quad_model(u16, /*with_normals=*/false);
  Builder cw = quad_model(u16, false);
  // Reverse every triangle of the second model: its index data is the last view's bytes.
  const int idx_view =
      cw.doc["accessors"][cw.doc["meshes"][0]["primitives"][0]["indices"].get<int>()]["bufferView"];
  const std::size_t offset = cw.doc["bufferViews"][idx_view]["byteOffset"];
  const std::uint16_t reversed[6] = {0, 2, 1, 0, 3, 2};
  std::memcpy(cw.bin.data() + offset, reversed, sizeof reversed);
  const snell::Scene front = load_ok(ccw.write(dir, "ccw", Container::glb));
  const snell::Scene back = load_ok(cw.write(dir, "cw", Container::glb));
  REQUIRE(front.meshes.size() == 1);
  REQUIRE(back.meshes.size() == 1);
  // Flat normals: one vertex per triangle corner.
  CHECK(front.meshes[0].vertices.size() == 6);
  for (const snell::Vertex& v : front.meshes[0].vertices) {
    CHECK(near(v.normal, {0, 0, 1}));
  }
  for (const snell::Vertex& v : back.meshes[0].vertices) {
    CHECK(near(v.normal, {0, 0, -1}));
  }
}

TEST_CASE("gltf: generated tangents follow +u, are orthogonal to the normal, w = handedness") {
  TempDir dir;
  // Standard mapping: u along +X, v = 0 at the top (+Y): image up is +Y = cross(N, T), so w = +1.
  const snell::Scene scene = load_ok(quad_model().write(dir, "quad", Container::glb));
  REQUIRE(scene.meshes.size() == 1);
  for (const snell::Vertex& v : scene.meshes[0].vertices) {
    CHECK(near(glm::vec3(v.tangent), {1, 0, 0}));
    CHECK(std::abs(glm::dot(glm::vec3(v.tangent), v.normal)) < 1e-5f);
    CHECK(v.tangent.w == 1.0f);
  }
  // Mirrored in u: the tangent follows +u to -X and the frame flips (w = -1).
  Builder mirrored = quad_model();
  const Quad q;
  std::vector<glm::vec2> uvs = q.uvs;
  for (glm::vec2& uv : uvs) {
    uv.x = 1.0f - uv.x;
  }
  mirrored.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = mirrored.add_vec2(uvs);
  const snell::Scene m = load_ok(mirrored.write(dir, "mirrored", Container::glb));
  for (const snell::Vertex& v : m.meshes[0].vertices) {
    CHECK(near(glm::vec3(v.tangent), {-1, 0, 0}));
    CHECK(v.tangent.w == -1.0f);
  }
}

TEST_CASE("gltf: provided normals and tangents are kept (normalised)") {
  Builder b = quad_model();
  const int t = b.add_vec4({{0, 2, 0, -1}, {0, 2, 0, -1}, {0, 2, 0, -1}, {0, 2, 0, -1}});
  b.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = t;
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "tangents", Container::glb));
  for (const snell::Vertex& v : scene.meshes[0].vertices) {
    CHECK(v.tangent == glm::vec4(0, 1, 0, -1));
    CHECK(v.normal == glm::vec3(0, 0, 1));
  }
}

TEST_CASE("gltf: sparse accessors substitute values, accessors without a view are zeros") {
  Builder b = quad_model();
  // Replace POSITION by a zero accessor (no bufferView) with sparse values for vertices 1..3.
  const std::vector<std::uint8_t> idx{1, 2, 3, 0};
  const std::vector<float> values{1, -1, 0, 1, 1, 0, -1, 1, 0};
  const int idx_view = b.add_view(b.append(idx.data(), idx.size()), 3);
  const int val_view = b.add_view(b.append(values.data(), values.size() * 4), values.size() * 4);
  const int sparse =
      b.add("accessors", {{"componentType", f32},
                          {"count", 4},
                          {"type", "VEC3"},
                          {"sparse",
                           {{"count", 3},
                            {"indices", {{"bufferView", idx_view}, {"componentType", u8}}},
                            {"values", {{"bufferView", val_view}}}}}});
  b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = sparse;
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "sparse", Container::glb));
  const std::vector<snell::Vertex>& v = scene.meshes[0].vertices;
  REQUIRE(v.size() == 4);
  CHECK(v[0].position == glm::vec3(0, 0, 0));
  CHECK(v[1].position == glm::vec3(1, -1, 0));
  CHECK(v[2].position == glm::vec3(1, 1, 0));
  CHECK(v[3].position == glm::vec3(-1, 1, 0));
}

TEST_CASE("gltf: a mesh used by two nodes is converted once, each primitive is one mesh") {
  Builder b = quad_model();
  json prim = b.doc["meshes"][0]["primitives"][0];
  b.doc["meshes"][0]["primitives"].push_back(prim);
  b.doc["nodes"].push_back({{"mesh", 0}, {"translation", {0, 0, 5}}});
  b.set_scene({0, 1});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "shared", Container::glb));
  CHECK(scene.meshes.size() == 2);
  REQUIRE(scene.objects.size() == 4);
  CHECK(scene.objects[0].mesh == 0);
  CHECK(scene.objects[1].mesh == 1);
  CHECK(scene.objects[2].mesh == 0);
  CHECK(scene.objects[3].mesh == 1);
  CHECK(scene.objects[2].transform[3] == glm::vec4(0, 0, 5, 1));
}

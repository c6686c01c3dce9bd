// glTF loading: materials (factors, alpha, extensions) and textures (images decoded to RGBA8,
// texture -> image mapping, sRGB flag), and the glass_grid sample asset.
#include "gltf_builder.hpp"

#include <snell/scene.hpp>

#include <doctest/doctest.h>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

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

glm::u8vec4 pixel(const snell::Image& image, std::uint32_t x, std::uint32_t y) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
  return {image.rgba8[i], image.rgba8[i + 1], image.rgba8[i + 2], image.rgba8[i + 3]};
}

} // namespace

TEST_CASE("gltf: material factors, alpha, double-sided, transmission and ior") {
  Builder b = quad_model();
  b.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior",
                             "KHR_materials_emissive_strength"};
  b.doc["extensionsRequired"] = {"KHR_materials_transmission"};
  b.add("materials", {{"name", "glass"},
                      {"pbrMetallicRoughness",
                       {{"baseColorFactor", {0.1, 0.2, 0.3, 0.4}}, {"roughnessFactor", 0.25}}},
                      {"emissiveFactor", {0.5, 0.25, 0}},
                      {"alphaMode", "MASK"},
                      {"alphaCutoff", 0.3},
                      {"doubleSided", true},
                      {"extensions",
                       {{"KHR_materials_transmission", {{"transmissionFactor", 0.8}}},
                        {"KHR_materials_ior", {{"ior", 1.33}}},
                        {"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}});
  b.add("materials", {{"alphaMode", "BLEND"}});
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "mat", Container::glb));
  REQUIRE(scene.materials.size() == 2);
  const snell::Material& m = scene.materials[0];
  CHECK(scene.meshes[0].material == 0);
  CHECK(m.name == "glass");
  CHECK(m.base_color.x == doctest::Approx(0.1));
  CHECK(m.base_color.w == doctest::Approx(0.4));
  CHECK(m.roughness == doctest::Approx(0.25));
  CHECK(m.emissive.x == doctest::Approx(2.0)); // 0.5 * emissiveStrength 4
  CHECK(m.emissive.y == doctest::Approx(1.0));
  CHECK(m.alpha_mode == snell::AlphaMode::mask);
  CHECK(m.alpha_cutoff == doctest::Approx(0.3));
  CHECK(m.double_sided);
  CHECK(m.transmission == doctest::Approx(0.8));
  CHECK(m.ior == doctest::Approx(1.33));
  CHECK(m.base_color_texture == -1);
  // glTF defaults for what the second material leaves out.
  const snell::Material& d = scene.materials[1];
  CHECK(d.alpha_mode == snell::AlphaMode::blend);
  CHECK(d.base_color == glm::vec4(1.0f));
  CHECK(d.roughness == doctest::Approx(1.0)); // glTF's default roughnessFactor
  CHECK(d.transmission == 0.0f);
  CHECK(d.ior == doctest::Approx(1.5));
  CHECK_FALSE(d.double_sided);
}

TEST_CASE("gltf: textures map to images, images decode to RGBA8, normal maps are linear") {
  for (const Container c : {Container::glb, Container::external_bin, Container::data_uri}) {
    CAPTURE(container_name(c));
    Builder b = quad_model();
    // Image 0: 2x2 normal-map blue; image 1: 3x2 with a red top-left pixel. The textures list them
    // in the opposite order, so texture index != image index.
    const int flat_normal = b.add_image_view(solid_png(2, 2, {128, 128, 255, 255}));
    const int colour = b.add_image_view(make_png(3, 2, [](int x, int y) {
      return x == 0 && y == 0 ? glm::u8vec4(255, 0, 0, 255) : glm::u8vec4(0, 0, 255, 128);
    }));
    const int t_colour = b.add_texture(colour);
    const int t_normal = b.add_texture(flat_normal);
    b.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", t_colour}}}}},
                        {"normalTexture", {{"index", t_normal}, {"scale", 0.5}}},
                        {"emissiveTexture", {{"index", t_colour}}}});
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    TempDir dir;
    const snell::Scene scene = load_ok(b.write(dir, "tex", c));
    REQUIRE(scene.images.size() == 2);
    REQUIRE(scene.materials.size() == 1);
    const snell::Material& m = scene.materials[0];
    CHECK(m.base_color_texture == colour);
    CHECK(m.emissive_texture == colour);
    CHECK(m.normal_texture == flat_normal);
    CHECK(m.normal_scale == doctest::Approx(0.5));
    const snell::Image& img = scene.images[static_cast<std::size_t>(colour)];
    CHECK(img.width == 3);
    CHECK(img.height == 2);
    REQUIRE(img.rgba8.size() == 3 * 2 * 4);
    CHECK(pixel(img, 0, 0) == glm::u8vec4(255, 0, 0, 255)); // First row first.
    CHECK(pixel(img, 2, 1) == glm::u8vec4(0, 0, 255, 128));
    CHECK(img.srgb);
    CHECK_FALSE(scene.images[static_cast<std::size_t>(flat_normal)].srgb);
  }
}

TEST_CASE("gltf: images referenced by external files and data: URIs") {
  Builder b = quad_model();
  const std::vector<std::uint8_t> png = solid_png(4, 4, {0, 255, 0, 255});
  b.add_image_uri("textures/green%20tile.png"); // Percent-encoded space, in a subfolder.
  b.add_image_uri("data:image/png;base64," + base64(png));
  b.add_texture(0);
  b.add_texture(1);
  TempDir dir;
  dir.write("textures/green tile.png", png);
  const snell::Scene scene = load_ok(b.write(dir, "uris", Container::external_bin));
  REQUIRE(scene.images.size() == 2);
  for (const snell::Image& img : scene.images) {
    CHECK(img.width == 4);
    CHECK(pixel(img, 3, 3) == glm::u8vec4(0, 255, 0, 255));
  }
  CHECK(scene.images[0].name == "textures/green%20tile.png");
}

TEST_CASE("gltf: a texture without a source image leaves the slot empty") {
  Builder b = quad_model();
  b.add("textures", json::object()); // e.g. a texture that only has a KHR_texture_basisu source
  b.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "nosource", Container::glb));
  REQUIRE(scene.materials.size() == 1);
  CHECK(scene.materials[0].base_color_texture == -1);
}

TEST_CASE("gltf: material values outside their glTF range are refused") {
  struct Case {
    json material;
    const char* reason;
  };
  const Case cases[] = {
      {{{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.5}}}}}},
       "transmissionFactor"},
      {{{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}, "ior"},
      {{{"pbrMetallicRoughness", {{"roughnessFactor", 2.0}}}}, "roughnessFactor"},
      {{{"alphaMode", "SOMETIMES"}}, "alphaMode"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.reason);
    Builder b = quad_model();
    b.add("materials", c.material);
    TempDir dir;
    const snell::Result<snell::Scene> r = snell::load_gltf(b.write(dir, "badmat", Container::glb));
    REQUIRE_FALSE(r);
    CHECK(r.error().code == snell::ErrorCode::parse_error);
    CHECK(contains(r.error().message, "badmat.glb"));
    CHECK(contains(r.error().message, "material 0"));
    CHECK(contains(r.error().message, c.reason));
  }
}

TEST_CASE("gltf: KHR_materials_volume and KHR_materials_dispersion are read, also when required") {
  Builder b = quad_model();
  b.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume",
                             "KHR_materials_dispersion"};
  b.doc["extensionsRequired"] = {"KHR_materials_volume", "KHR_materials_dispersion"};
  b.add("materials", {{"name", "flint"},
                      {"extensions",
                       {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                        {"KHR_materials_volume",
                         {{"thicknessFactor", 0.8},
                          {"attenuationDistance", 2.5},
                          {"attenuationColor", {0.9, 0.5, 0.25}}}},
                        {"KHR_materials_dispersion", {{"dispersion", 1.0}}}}}});
  b.add("materials", {{"name", "plain"}});
  // Both extensions present with none of their keys: their glTF defaults.
  b.add("materials", {{"name", "empty volume"},
                      {"extensions",
                       {{"KHR_materials_volume", json::object()},
                        {"KHR_materials_dispersion", json::object()}}}});
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  TempDir dir;
  const snell::Scene scene = load_ok(b.write(dir, "volume", Container::glb));
  REQUIRE(scene.materials.size() == 3);
  const snell::Material& m = scene.materials[0];
  CHECK(m.transmission == doctest::Approx(1.0));
  CHECK(m.thickness == doctest::Approx(0.8));
  CHECK(m.attenuation_distance == doctest::Approx(2.5));
  CHECK(m.attenuation_color.x == doctest::Approx(0.9));
  CHECK(m.attenuation_color.y == doctest::Approx(0.5));
  CHECK(m.attenuation_color.z == doctest::Approx(0.25));
  CHECK(m.dispersion == doctest::Approx(1.0));
  for (const std::size_t i : {std::size_t{1}, std::size_t{2}}) {
    const snell::Material& d = scene.materials[i];
    CAPTURE(d.name);
    CHECK(d.thickness == 0.0f); // Thin-walled.
    CHECK(d.attenuation_color == glm::vec3(1.0f));
    CHECK(std::isinf(d.attenuation_distance));
    CHECK(d.attenuation_distance > 0.0f);
    CHECK(d.dispersion == 0.0f);
  }
}

TEST_CASE("gltf: volume and dispersion values outside their glTF range are refused") {
  struct Case {
    std::string extension;
    json values;
    std::string field;  // In the message.
    std::string detail; // Also in the message: the value and the valid range, or what is wrong.
  };
  const Case cases[] = {
      {"KHR_materials_volume", {{"thicknessFactor", -0.25}}, "thicknessFactor", "-0.25"},
      {"KHR_materials_volume", {{"thicknessFactor", "thick"}}, "thicknessFactor", "not a number"},
      {"KHR_materials_volume", {{"attenuationDistance", 0.0}}, "attenuationDistance", "(0, inf)"},
      {"KHR_materials_volume", {{"attenuationDistance", -3.0}}, "attenuationDistance", "-3"},
      // A finite double that no float holds.
      {"KHR_materials_volume",
       {{"attenuationDistance", 1e39}},
       "attenuationDistance",
       "1e+39 is not a finite float"},
      {"KHR_materials_volume",
       {{"attenuationColor", {1.5, 0.0, 0.0}}},
       "attenuationColor[0]",
       "1.5 is outside [0, 1]"},
      {"KHR_materials_volume",
       {{"attenuationColor", {0.5, -0.1, 0.5}}},
       "attenuationColor[1]",
       "-0.1"},
      {"KHR_materials_volume", {{"attenuationColor", {0.5, 0.5}}}, "attenuationColor", "3 numbers"},
      {"KHR_materials_volume",
       {{"attenuationColor", {0.5, 0.5, 0.5, 1.0}}},
       "attenuationColor",
       "(it has 4)"},
      {"KHR_materials_volume", {{"attenuationColor", "red"}}, "attenuationColor", "3 numbers"},
      {"KHR_materials_volume",
       {{"attenuationColor", {0.5, "x", 0.5}}},
       "attenuationColor[1]",
       "not a number"},
      {"KHR_materials_dispersion", {{"dispersion", -1.0}}, "dispersion", "[0, inf)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.field);
    CAPTURE(c.detail);
    Builder b = quad_model();
    b.add("materials", {{"name", "ok"}});
    b.add("materials", {{"name", "bad glass"}, {"extensions", {{c.extension, c.values}}}});
    TempDir dir;
    const snell::Result<snell::Scene> r = snell::load_gltf(b.write(dir, "badvol", Container::glb));
    REQUIRE_FALSE(r);
    CHECK(r.error().code == snell::ErrorCode::parse_error);
    CHECK(contains(r.error().message, "badvol.glb"));
    CHECK(contains(r.error().message, "material 1 'bad glass'"));
    CHECK(contains(r.error().message, c.extension));
    CHECK(contains(r.error().message, c.field));
    CHECK(contains(r.error().message, c.detail));
  }
}

TEST_CASE("gltf: samples/assets/glass_grid.gltf loads with its eight glass materials in view") {
  const std::filesystem::path path =
      std::filesystem::path(SNELL_SAMPLE_ASSETS_DIR) / "glass_grid.gltf";
  const snell::Scene scene = load_ok(path);
  std::vector<int> glass; // Material indices with transmission.
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].transmission > 0.0f) {
      CHECK(scene.materials[i].transmission == 1.0f);
      glass.push_back(static_cast<int>(i));
    }
  }
  REQUIRE(glass.size() == 8);
  // Named for what they show (the script's order: spheres by IOR, then the slabs).
  const char* const names[] = {"ior_1.1",     "ior_1.33",  "ior_1.5",   "ior_2.0",
                               "thin_walled", "rough_0.3", "rough_0.6", "dispersion_1.0"};
  for (std::size_t i = 0; i < glass.size(); ++i) {
    CHECK(scene.materials[static_cast<std::size_t>(glass[i])].name == names[i]);
  }
  auto count = [&](auto&& predicate) {
    int n = 0;
    for (const int i : glass) {
      n += predicate(scene.materials[static_cast<std::size_t>(i)]) ? 1 : 0;
    }
    return n;
  };
  for (const float ior : {1.1f, 1.33f, 1.5f, 2.0f}) {
    CAPTURE(ior);
    CHECK(count([ior](const snell::Material& m) { return m.ior == doctest::Approx(ior); }) >= 1);
  }
  CHECK(count([](const snell::Material& m) { return m.dispersion == 1.0f; }) == 1);
  CHECK(count([](const snell::Material& m) { return m.thickness == 0.0f; }) == 1);
  CHECK(count([](const snell::Material& m) { return m.roughness > 0.0f; }) == 2);

  // Every glass object lies wholly inside the file's camera at 16:9 (the CLI's default aspect),
  // so a render shows all eight.
  REQUIRE_FALSE(scene.cameras.empty());
  const snell::CameraDesc& cam = scene.cameras[0];
  const glm::mat4 view_proj = glm::perspective(cam.yfov, 16.0f / 9.0f, cam.z_near, cam.z_far) *
                              glm::lookAt(cam.eye, cam.target, cam.up);
  int glass_objects = 0;
  for (const snell::Object& object : scene.objects) {
    const snell::Mesh& mesh = scene.meshes[static_cast<std::size_t>(object.mesh)];
    if (std::find(glass.begin(), glass.end(), mesh.material) == glass.end()) {
      continue;
    }
    ++glass_objects;
    CAPTURE(object.name);
    float nearest = std::numeric_limits<float>::infinity(); // Smallest clip w: > 0 is in front.
    float extent = 0.0f; // Largest |x| or |y| in normalised device coordinates.
    for (const snell::Vertex& v : mesh.vertices) {
      const glm::vec4 clip = view_proj * object.transform * glm::vec4(v.position, 1.0f);
      nearest = std::min(nearest, clip.w);
      extent = std::max({extent, std::abs(clip.x / clip.w), std::abs(clip.y / clip.w)});
    }
    CHECK(nearest > 0.0f);
    CHECK(extent < 1.0f);
  }
  CHECK(glass_objects == 8);
}

// glTF loading of hostile or broken files: every case returns the expected ErrorCode with a
// message naming the file and the reason, and nothing crashes, hangs or reads outside the model's
// folder. (Run under the asan preset too.)
#include "gltf_builder.hpp"

#include <snell/scene.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace gltf_test;
using snell::ErrorCode;

namespace {

// Loads `path` expecting failure with `code`; checks the message names the file and `reason`.
void expect_error(const std::filesystem::path& path, ErrorCode code, const std::string& reason,
                  const snell::GltfLimits& limits = {}) {
  const snell::Result<snell::Scene> r = snell::load_gltf(path, limits);
  REQUIRE_FALSE(r.has_value());
  INFO("message: " << r.error().message);
  CHECK(static_cast<int>(r.error().code) == static_cast<int>(code));
  CHECK(contains(r.error().message, path.filename().string()));
  CHECK(contains(r.error().message, reason));
}

} // namespace

TEST_CASE("gltf hostile: buffer URIs outside the model's folder are refused") {
  TempDir dir;
  // A file next to the model's folder that must never be read.
  dir.write("secret.bin", std::vector<std::uint8_t>(64, 0xAB));
  struct Case {
    const char* uri;
    const char* reason;
  };
  const Case cases[] = {
      {"/etc/passwd", "absolute path"},
      {"../secret.bin", "escapes the model's folder"},
      {"sub/../../secret.bin", "escapes the model's folder"},
      {"%2e%2e/secret.bin", "escapes the model's folder"}, // percent-encoded ".."
      {"%2E%2E%2Fsecret.bin", "escapes the model's folder"},
      {"..%5csecret.bin", "backslash"},
      {"%2fetc/passwd", "absolute path"},
      {"file:///etc/passwd", "scheme"},
      {"C:/Windows/win.ini", "drive letter"},
      {"a%00b.bin", "control character"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.uri);
    Builder b = quad_model();
    b.doc["buffers"][0]["uri"] = c.uri;
    b.doc["buffers"][0]["byteLength"] = 64;
    const std::filesystem::path model = b.write(dir, "inner/model", Container::data_uri);
    expect_error(model, ErrorCode::access_denied, c.reason);
    const snell::Result<snell::Scene> r = snell::load_gltf(model);
    REQUIRE_FALSE(r);
    CHECK(contains(r.error().message, "buffer 0 URI"));
  }
}

TEST_CASE("gltf hostile: image URIs outside the model's folder are refused") {
  TempDir dir;
  dir.write("outside.png", solid_png(2, 2, {1, 2, 3, 4}));
  Builder b = quad_model();
  b.add_image_uri("../outside.png");
  expect_error(b.write(dir, "inner/img", Container::glb), ErrorCode::access_denied,
               "image 0 URI '../outside.png' refused");
}

TEST_CASE("gltf hostile: '..' that stays inside the folder is fine") {
  TempDir dir;
  Builder b = quad_model();
  b.doc["buffers"][0]["uri"] = "sub/../ok.bin";
  const std::filesystem::path model = b.write(dir, "model", Container::data_uri);
  dir.write("ok.bin", b.bin);
  const snell::Result<snell::Scene> r = snell::load_gltf(model);
  CHECK_MESSAGE(r.has_value(), (r ? "" : r.error().message));
}

TEST_CASE("gltf hostile: a symbolic link pointing outside the folder is refused") {
  TempDir dir;
  Builder b = quad_model();
  const std::filesystem::path secret = dir.write("secret.bin", b.bin);
  std::filesystem::create_directories(dir.path() / "inner");
  std::error_code ec;
  std::filesystem::create_symlink(secret, dir.path() / "inner" / "link.bin", ec);
  if (ec) {
    MESSAGE("cannot create symbolic links here: " << ec.message());
    return;
  }
  b.doc["buffers"][0]["uri"] = "link.bin";
  expect_error(b.write(dir, "inner/model", Container::data_uri), ErrorCode::access_denied,
               "outside the model's folder");
}

TEST_CASE("gltf hostile: missing files") {
  TempDir dir;
  SUBCASE("the model itself") {
    const std::filesystem::path missing = dir.path() / "nothing-here.gltf";
    expect_error(missing, ErrorCode::file_not_found, "not found");
    CHECK(contains(snell::load_gltf(missing).error().message, missing.string()));
  }
  SUBCASE("a directory instead of a file") {
    std::filesystem::create_directories(dir.path() / "folder.gltf");
    expect_error(dir.path() / "folder.gltf", ErrorCode::file_not_found, "is a folder");
  }
  SUBCASE("the external .bin") {
    Builder b = quad_model();
    b.doc["buffers"][0]["uri"] = "missing.bin";
    expect_error(b.write(dir, "model", Container::data_uri), ErrorCode::file_not_found,
                 "'missing.bin' not found");
  }
  SUBCASE("an external image") {
    Builder b = quad_model();
    b.add_image_uri("missing.png");
    expect_error(b.write(dir, "model", Container::glb), ErrorCode::file_not_found,
                 "'missing.png' not found");
  }
}

TEST_CASE("gltf hostile: truncated .glb (every prefix) is a parse_error") {
  TempDir dir;
  Builder b = quad_model();
  b.add_image_view(solid_png(2, 2, {9, 9, 9, 255}));
  const std::vector<std::uint8_t> glb = b.glb_bytes(b.finished(Container::glb, ""));
  for (std::size_t length = 0; length < glb.size(); ++length) {
    CAPTURE(length);
    const std::filesystem::path path =
        dir.write("cut.glb", std::vector<std::uint8_t>(glb.begin(), glb.begin() + length));
    const snell::Result<snell::Scene> r = snell::load_gltf(path);
    REQUIRE_FALSE(r);
    CHECK(r.error().code == ErrorCode::parse_error);
    CHECK(contains(r.error().message, "cut.glb"));
    CHECK(contains(r.error().message, "not a valid glTF file"));
  }
  // tinygltf's own reason is part of the message.
  const std::filesystem::path path =
      dir.write("short.glb", std::vector<std::uint8_t>(glb.begin(), glb.begin() + 12));
  expect_error(path, ErrorCode::parse_error, "Too short data size for glTF Binary");
  const std::filesystem::path half =
      dir.write("half.glb", std::vector<std::uint8_t>(glb.begin(), glb.begin() + glb.size() / 2));
  expect_error(half, ErrorCode::parse_error, "Invalid glTF binary");
}

TEST_CASE("gltf hostile: bad JSON, empty file, wrong root") {
  TempDir dir;
  expect_error(dir.write("bad.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [ }"),
               ErrorCode::parse_error, "parse error");
  expect_error(dir.write("empty.gltf", ""), ErrorCode::parse_error, "empty file");
  expect_error(dir.write("empty.gltf", ""), ErrorCode::parse_error, "JSON string too short");
  expect_error(dir.write("array.gltf", "[1, 2, 3, 4]"), ErrorCode::parse_error,
               "Root element is not a JSON object");
  expect_error(dir.write("empty.glb", ""), ErrorCode::parse_error, "Too short");
  expect_error(dir.write("text.glb", "this is not a binary glTF container"), ErrorCode::parse_error,
               "Invalid magic");
}

TEST_CASE("gltf hostile: deeply nested JSON is refused before anything recurses on it") {
  TempDir dir;
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string text =
      "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + deep + ", \"nodes\": []}";
  expect_error(dir.write("deep.gltf", text), ErrorCode::limit_exceeded, "deeper than 128");
}

TEST_CASE("gltf hostile: images over the size caps are refused before decoding") {
  TempDir dir;
  Builder b = quad_model();
  b.add_image_view(solid_png(32, 32, {255, 0, 0, 255}));
  const std::filesystem::path model = b.write(dir, "big-image", Container::glb);
  snell::GltfLimits limits;
  limits.max_image_dimension = 16;
  expect_error(model, ErrorCode::limit_exceeded, "32x32", limits);
  expect_error(model, ErrorCode::limit_exceeded, "max_image_dimension", limits);
  expect_error(model, ErrorCode::limit_exceeded, "image 0", limits);
  limits = {};
  limits.max_image_pixels = 1000;
  expect_error(model, ErrorCode::limit_exceeded, "max_image_pixels", limits);
  limits = {};
  limits.max_total_image_pixels = 1023;
  expect_error(model, ErrorCode::limit_exceeded, "max_total_image_pixels", limits);
  limits.max_total_image_pixels = 1024; // exactly one 32x32 image fits
  CHECK(snell::load_gltf(model, limits).has_value());
}

TEST_CASE("gltf hostile: an image whose header claims 60000x60000 names the size and the limit") {
  // stb_image will not even describe an image over 2^30 bytes ("unknown image type"); the loader
  // reads the size from the header itself.
  TempDir dir;
  SUBCASE("PNG") {
    std::vector<std::uint8_t> png = solid_png(8, 8, {1, 2, 3, 255});
    for (const std::size_t at : {16u, 20u}) { // IHDR width, height (big-endian 32-bit)
      png[at] = 0;
      png[at + 1] = 0;
      png[at + 2] = 0xEA; // 60000 = 0xEA60
      png[at + 3] = 0x60;
    }
    Builder b = quad_model();
    b.add_image_view(png);
    const std::filesystem::path model = b.write(dir, "huge-png", Container::glb);
    expect_error(model, ErrorCode::limit_exceeded, "60000x60000");
    expect_error(model, ErrorCode::limit_exceeded, "max_image_dimension = 8192");
  }
  SUBCASE("JPEG") {
    // Start of image, then a baseline start-of-frame segment: length 17, precision 8, height
    // and width 60000 (0xEA60), three components; then end of image. Only the header is read.
    const std::vector<std::uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 0x08, 0xEA,
                                            0x60, 0xEA, 0x60, 0x03, 0x01, 0x22, 0x00, 0x02,
                                            0x11, 0x01, 0x03, 0x11, 0x01, 0xFF, 0xD9};
    Builder b = quad_model();
    b.add_image_view(jpeg, "image/jpeg");
    const std::filesystem::path model = b.write(dir, "huge-jpeg", Container::glb);
    expect_error(model, ErrorCode::limit_exceeded, "60000x60000");
  }
}

TEST_CASE("gltf hostile: a folder where a referenced file is expected says so") {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "inner" / "texture.png");
  Builder b = quad_model();
  b.add_image_uri("texture.png");
  expect_error(b.write(dir, "inner/model", Container::data_uri), ErrorCode::file_not_found,
               "'texture.png' is a folder");
}

TEST_CASE("gltf hostile: images that are not PNG/JPEG or are corrupt") {
  TempDir dir;
  SUBCASE("not an image format of glTF") {
    Builder b = quad_model();
    b.add_image_view({'B', 'M', 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    expect_error(b.write(dir, "bmp", Container::glb), ErrorCode::unsupported, "not a PNG or JPEG");
  }
  SUBCASE("a PNG with a corrupt body") {
    std::vector<std::uint8_t> png = solid_png(8, 8, {1, 2, 3, 255});
    for (std::size_t i = 40; i < png.size() - 12; ++i) {
      png[i] ^= 0x5A; // Scramble the IDAT payload, keep the header readable.
    }
    Builder b = quad_model();
    b.add_image_view(png);
    expect_error(b.write(dir, "corrupt", Container::glb), ErrorCode::parse_error, "image 0");
  }
  SUBCASE("a PNG with an empty IDAT chunk still decodes") {
    // stb_image would memcpy from a null buffer for it (undefined behaviour): the loader drops
    // empty IDAT chunks first. Inserted right after IHDR (8-byte signature + 25-byte IHDR).
    std::vector<std::uint8_t> png = solid_png(3, 3, {10, 20, 30, 255});
    const std::uint8_t empty_idat[12] = {0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xAF, 0x06, 0x1E};
    png.insert(png.begin() + 33, std::begin(empty_idat), std::end(empty_idat));
    Builder b = quad_model();
    b.add_image_view(png);
    const snell::Result<snell::Scene> r = snell::load_gltf(b.write(dir, "idat", Container::glb));
    REQUIRE_MESSAGE(r.has_value(), (r ? "" : r.error().message));
    REQUIRE(r->images.size() == 1);
    CHECK(r->images[0].width == 3);
    CHECK(r->images[0].rgba8[0] == 10);
    CHECK(r->images[0].rgba8[3 * 3 * 4 - 2] == 30);
  }
  SUBCASE("an image buffer view outside its buffer") {
    Builder b = quad_model();
    b.add_image_view(solid_png(2, 2, {1, 2, 3, 255}));
    b.doc["bufferViews"].back()["byteOffset"] = 1u << 20;
    expect_error(b.write(dir, "imgview", Container::glb), ErrorCode::parse_error,
                 "lies outside buffer 0");
  }
}

TEST_CASE("gltf hostile: non-finite positions") {
  TempDir dir;
  for (const float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    Builder b = quad_model();
    const int pos = b.add_vec3({{0, 0, 0}, {1, 0, 0}, {0, bad, 0}, {0, 0, 1}});
    b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = pos;
    b.doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    b.doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
    const std::filesystem::path model = b.write(dir, "nan", Container::glb);
    expect_error(model, ErrorCode::parse_error, "not finite");
    expect_error(model, ErrorCode::parse_error, "mesh 0 'quad' primitive 0 POSITION accessor");
    expect_error(model, ErrorCode::parse_error, "element 2");
  }
}

TEST_CASE("gltf hostile: index values past the vertex count") {
  TempDir dir;
  Builder b;
  const int pos = b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  const int idx = b.add_indices({0, 1, 7}, u16);
  b.set_scene({b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}}, idx)}})});
  expect_error(b.write(dir, "idx", Container::glb), ErrorCode::parse_error,
               "index value 7 at position 2 is past the vertex count 3");
}

TEST_CASE("gltf hostile: accessors and buffer views past their containers") {
  TempDir dir;
  SUBCASE("accessor count past its buffer view") {
    Builder b = quad_model();
    b.doc["accessors"][0]["count"] = 1000;
    expect_error(b.write(dir, "acc", Container::glb), ErrorCode::parse_error,
                 "run past the end of bufferView 0");
  }
  SUBCASE("accessor offset past its buffer view") {
    Builder b = quad_model();
    b.doc["accessors"][0]["byteOffset"] = 1ull << 40;
    expect_error(b.write(dir, "acc", Container::glb), ErrorCode::parse_error, "accessor 0");
  }
  SUBCASE("count * stride overflowing 64 bits") {
    Builder b = quad_model();
    b.doc["accessors"][0]["count"] = std::numeric_limits<std::uint64_t>::max();
    expect_error(b.write(dir, "acc", Container::glb), ErrorCode::parse_error, "accessor 0");
  }
  SUBCASE("interleaved stride smaller than the element") {
    Builder b = quad_model();
    b.doc["bufferViews"][0]["byteStride"] = 8;
    expect_error(b.write(dir, "stride", Container::glb), ErrorCode::parse_error,
                 "smaller than an element");
  }
  SUBCASE("buffer view past its buffer") {
    Builder b = quad_model();
    b.doc["bufferViews"][1]["byteLength"] = 100000;
    expect_error(b.write(dir, "view", Container::glb), ErrorCode::parse_error,
                 "bufferView 1 (offset");
  }
  SUBCASE("attribute counts disagree") {
    Builder b = quad_model();
    b.doc["accessors"][1]["count"] = 3; // TEXCOORD_0
    expect_error(b.write(dir, "counts", Container::glb), ErrorCode::parse_error,
                 "TEXCOORD_0 accessor 1 has 3 elements, POSITION has 4");
  }
  SUBCASE("wrong accessor type") {
    Builder b = quad_model();
    b.doc["accessors"][0]["type"] = "VEC2";
    b.doc["accessors"][0].erase("min");
    b.doc["accessors"][0].erase("max");
    expect_error(b.write(dir, "type", Container::glb), ErrorCode::parse_error,
                 "type is VEC2, expected VEC3");
  }
}

TEST_CASE("gltf hostile: dangling references") {
  TempDir dir;
  struct Case {
    const char* name;
    void (*edit)(json&);
    const char* reason;
  };
  const Case cases[] = {
      {"material", [](json& d) { d["meshes"][0]["primitives"][0]["material"] = 3; },
       "material 3 does not exist (0 materials)"},
      {"mesh", [](json& d) { d["nodes"][0]["mesh"] = 9; }, "mesh 9 does not exist"},
      {"child node", [](json& d) { d["nodes"][0]["children"] = {5}; },
       "child node 5 does not exist"},
      {"scene node",
       [](json& d) {
         d["scenes"][0]["nodes"] = {0, 4};
       },
       "node 4 does not exist"},
      {"default scene", [](json& d) { d["scene"] = 2; }, "default scene 2 does not exist"},
      {"camera", [](json& d) { d["nodes"][0]["camera"] = 0; }, "camera 0 does not exist"},
      {"indices accessor", [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 42; },
       "accessor"},
      {"attribute accessor",
       [](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42; },
       "attribute NORMAL: accessor 42 does not exist"},
      {"accessor buffer view", [](json& d) { d["accessors"][0]["bufferView"] = 77; },
       "bufferView 77 does not exist"},
      {"buffer", [](json& d) { d["bufferViews"][0]["buffer"] = 3; }, "buffer 3 does not exist"},
      {"texture",
       [](json& d) {
         d["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 4}}}}}}};
       },
       "baseColorTexture: texture 4 does not exist"},
      {"image",
       [](json& d) {
         d["textures"] = {{{"source", 2}}};
       },
       "image 2 does not exist"},
      {"light", [](json& d) { d["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0; },
       "light 0 does not exist"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    Builder b = quad_model();
    c.edit(b.doc);
    expect_error(b.write(dir, "dangling", Container::glb), ErrorCode::parse_error, c.reason);
  }
}

TEST_CASE("gltf hostile: node cycles, shared children and depth") {
  TempDir dir;
  SUBCASE("two nodes that are each other's child") {
    Builder b = quad_model();
    b.doc["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
    b.set_scene({0});
    expect_error(b.write(dir, "cycle", Container::glb), ErrorCode::parse_error, "cycle");
  }
  SUBCASE("a node that is its own child") {
    Builder b = quad_model();
    b.doc["nodes"][0]["children"] = {0};
    expect_error(b.write(dir, "self", Container::glb), ErrorCode::parse_error, "own ancestor");
  }
  SUBCASE("a node with two parents (exponential instancing)") {
    Builder b = quad_model();
    b.doc["nodes"] = {{{"children", {1, 1}}}, {{"mesh", 0}}};
    b.set_scene({0});
    expect_error(b.write(dir, "dag", Container::glb), ErrorCode::parse_error, "two parents");
  }
  SUBCASE("a scene root that is somebody's child") {
    Builder b = quad_model();
    b.doc["nodes"] = {{{"children", {1}}}, {{"mesh", 0}}};
    b.set_scene({0, 1});
    expect_error(b.write(dir, "root", Container::glb), ErrorCode::parse_error,
                 "is a child of node 0");
  }
  SUBCASE("a chain deeper than max_node_depth") {
    Builder b = quad_model();
    b.doc["nodes"] = json::array();
    for (int i = 0; i < 6; ++i) {
      b.doc["nodes"].push_back(i < 5 ? json{{"children", {i + 1}}} : json{{"mesh", 0}});
    }
    b.set_scene({0});
    const std::filesystem::path model = b.write(dir, "deep", Container::glb);
    snell::GltfLimits limits;
    limits.max_node_depth = 5;
    expect_error(model, ErrorCode::limit_exceeded, "max_node_depth = 5", limits);
    limits.max_node_depth = 6;
    CHECK(snell::load_gltf(model, limits).has_value());
  }
}

TEST_CASE("gltf hostile: absurd buffer byteLength") {
  TempDir dir;
  const std::uint64_t absurd = 1000000000000000ull; // 1e15
  SUBCASE("external buffer") {
    Builder b = quad_model();
    b.doc["buffers"][0]["byteLength"] = absurd;
    expect_error(b.write(dir, "huge", Container::external_bin), ErrorCode::limit_exceeded,
                 "byteLength 1000000000000000 is over the limit GltfLimits::max_file_bytes");
  }
  SUBCASE("data: URI buffer") {
    Builder b = quad_model();
    b.doc["buffers"][0]["byteLength"] = absurd;
    expect_error(b.write(dir, "huge", Container::data_uri), ErrorCode::limit_exceeded,
                 "max_data_uri_bytes");
  }
  SUBCASE(".glb BIN chunk") {
    Builder b = quad_model();
    b.doc["buffers"][0]["byteLength"] = absurd;
    expect_error(b.write(dir, "huge", Container::glb), ErrorCode::parse_error,
                 "exceeds the .glb's BIN chunk");
  }
  SUBCASE("many buffers naming the same file") {
    Builder b = quad_model();
    const json b0 = b.finished(Container::external_bin, "huge.bin")["buffers"][0];
    for (int i = 0; i < 10; ++i) {
      b.doc["buffers"].push_back(b0);
    }
    snell::GltfLimits limits;
    limits.max_total_buffer_bytes = 5 * b.bin.size();
    expect_error(b.write(dir, "huge", Container::external_bin), ErrorCode::limit_exceeded,
                 "max_total_buffer_bytes", limits);
  }
  SUBCASE("byteLength that disagrees with the file") {
    Builder b = quad_model();
    b.doc["buffers"][0]["byteLength"] = b.bin.size() + 4;
    expect_error(b.write(dir, "size", Container::external_bin), ErrorCode::parse_error,
                 "File size mismatch");
  }
}

TEST_CASE("gltf hostile: files over max_file_bytes") {
  TempDir dir;
  const Builder b = quad_model();
  SUBCASE("the model") {
    snell::GltfLimits limits;
    limits.max_file_bytes = 100;
    expect_error(b.write(dir, "big", Container::glb), ErrorCode::limit_exceeded,
                 "over the limit GltfLimits::max_file_bytes = 100", limits);
  }
  SUBCASE("its external .bin") {
    // The model is small enough; its .bin (whose byteLength claims less) is not.
    const std::filesystem::path model = b.write(dir, "bigbin", Container::external_bin);
    snell::GltfLimits limits;
    limits.max_file_bytes = std::filesystem::file_size(model);
    dir.write("bigbin.bin", std::vector<std::uint8_t>(limits.max_file_bytes + 64, 0));
    expect_error(model, ErrorCode::limit_exceeded, "referenced file 'bigbin.bin'", limits);
    expect_error(model, ErrorCode::limit_exceeded, "over the limit GltfLimits::max_file_bytes",
                 limits);
  }
  SUBCASE("a data: URI over max_data_uri_bytes") {
    snell::GltfLimits limits;
    limits.max_data_uri_bytes = 16;
    expect_error(b.write(dir, "datauri", Container::data_uri), ErrorCode::limit_exceeded,
                 "buffer 0: data: URI decodes to about", limits);
  }
}

TEST_CASE("gltf hostile: unsupported content is named") {
  TempDir dir;
  SUBCASE("a required extension Snell does not read") {
    Builder b = quad_model();
    b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expect_error(b.write(dir, "draco", Container::glb), ErrorCode::unsupported,
                 "KHR_draco_mesh_compression");
  }
  SUBCASE("a data: URI of a media type tinygltf cannot decode") {
    Builder b = quad_model();
    b.add_image_uri("data:image/webp;base64,AAAA");
    expect_error(b.write(dir, "webp", Container::glb), ErrorCode::unsupported, "image/webp");
  }
  SUBCASE("an unknown primitive mode") {
    Builder b = quad_model();
    b.doc["meshes"][0]["primitives"][0]["mode"] = 9;
    expect_error(b.write(dir, "mode", Container::glb), ErrorCode::parse_error,
                 "mode 9 is not a glTF mode");
  }
  SUBCASE("a triangle list that is not whole triangles") {
    Builder b;
    const int pos = b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    b.set_scene({b.add_node({{"mesh", b.add_mesh({{"POSITION", pos}})}})});
    expect_error(b.write(dir, "partial", Container::glb), ErrorCode::parse_error,
                 "4 indices do not form whole triangles");
  }
}

TEST_CASE("gltf hostile: vertex, index and object totals") {
  TempDir dir;
  Builder b = quad_model();
  b.doc["nodes"].push_back({{"mesh", 0}});
  b.set_scene({0, 1});
  const std::filesystem::path model = b.write(dir, "totals", Container::glb);
  snell::GltfLimits limits;
  limits.max_total_vertices = 3;
  expect_error(model, ErrorCode::limit_exceeded, "max_total_vertices", limits);
  limits = {};
  limits.max_total_indices = 5;
  expect_error(model, ErrorCode::limit_exceeded, "max_total_indices", limits);
  limits = {};
  limits.max_objects = 1;
  expect_error(model, ErrorCode::limit_exceeded, "max_objects = 1", limits);
  limits.max_objects = 2;
  CHECK(snell::load_gltf(model, limits).has_value());
}

TEST_CASE("gltf hostile: single-byte corruptions of a valid .glb never crash") {
  // A miniature fuzzer that runs everywhere (the libFuzzer test needs clang): every byte of a
  // small valid file is replaced by a few interesting values. Each load must return (a scene or
  // an error with a message), whatever it is.
  Builder b = quad_model(u8);
  b.add_image_view(solid_png(2, 2, {9, 9, 9, 255}));
  b.add_texture(0);
  b.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  const std::vector<std::uint8_t> glb = b.glb_bytes(b.finished(Container::glb, ""));
  TempDir dir;
  std::size_t failures = 0;
  for (std::size_t i = 0; i < glb.size(); ++i) {
    for (const std::uint8_t value : {std::uint8_t{0}, std::uint8_t{0xff}, std::uint8_t{'9'}}) {
      std::vector<std::uint8_t> bytes = glb;
      bytes[i] = value;
      const snell::Result<snell::Scene> r = snell::load_gltf(dir.write("mutant.glb", bytes));
      if (!r) {
        ++failures;
        REQUIRE(contains(r.error().message, "mutant.glb"));
      }
    }
  }
  CHECK(failures > 0); // The corruptions were noticed at least sometimes.
}

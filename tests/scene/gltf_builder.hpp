// Test helper: builds small glTF 2.0 files programmatically (JSON + one binary buffer) and writes
// them as .gltf with an external .bin, .gltf with a base64 data: URI, or .glb, into a temporary
// folder. Tests edit `doc` directly to make hostile variants.
#pragma once

#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include <glm/common.hpp>
#include <glm/gtc/type_precision.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace gltf_test {

using json = nlohmann::json;

// glTF component types and primitive modes, spelled out for readability.
inline constexpr int i8 = 5120, u8 = 5121, i16 = 5122, u16 = 5123, u32 = 5125, f32 = 5126;
inline constexpr int points = 0, lines = 1, triangles = 4, strip = 5, fan = 6;

enum class Container { external_bin, data_uri, glb };

inline const char* container_name(Container c) {
  return c == Container::external_bin ? "gltf+bin" : c == Container::data_uri ? "gltf+data" : "glb";
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += {table[v >> 18], table[(v >> 12) & 63], table[(v >> 6) & 63], table[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const std::uint32_t v = bytes[i] << 16;
    out += {table[v >> 18], table[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8);
    out += {table[v >> 18], table[(v >> 12) & 63], table[(v >> 6) & 63], '='};
  }
  return out;
}

inline std::vector<std::uint8_t> to_bytes(const std::string& s) {
  return std::vector<std::uint8_t>(s.begin(), s.end());
}

/// A fresh folder under the system temp folder, removed (with its contents) on destruction.
class TempDir {
public:
  TempDir() {
    static std::atomic<unsigned> counter{0};
    std::random_device rd;
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ = std::filesystem::temp_directory_path() /
            ("snell-gltf-test-" + std::to_string(rd()) + "-" + std::to_string(stamp) + "-" +
             std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::string& name,
                              const std::vector<std::uint8_t>& bytes) const {
    const std::filesystem::path p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      throw std::runtime_error("cannot write " + p.string());
    }
    return p;
  }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    return write(name, to_bytes(text));
  }

private:
  std::filesystem::path path_;
};

/// A width x height RGBA PNG (stb_image_write), pixel colour from `color(x, y)`.
inline std::vector<std::uint8_t> make_png(int width, int height,
                                          const std::function<glm::u8vec4(int, int)>& color) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width * height * 4));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::u8vec4 c = color(x, y);
      std::memcpy(&pixels[static_cast<std::size_t>((y * width + x) * 4)], &c[0], 4);
    }
  }
  std::vector<std::uint8_t> png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
      },
      &png, width, height, 4, pixels.data(), width * 4);
  return png;
}

inline std::vector<std::uint8_t> solid_png(int width, int height, glm::u8vec4 c) {
  return make_png(width, height, [c](int, int) { return c; });
}

/// Builds one glTF document with a single binary buffer (buffer 0).
class Builder {
public:
  json doc;                      ///< The glTF JSON; edit freely.
  std::vector<std::uint8_t> bin; ///< Contents of buffer 0.

  Builder() { doc = {{"asset", {{"version", "2.0"}}}}; }

  /// Appends bytes to buffer 0 at a 4-byte aligned offset; returns the offset.
  std::size_t append(const void* data, std::size_t size) {
    while (bin.size() % 4 != 0) {
      bin.push_back(0);
    }
    const std::size_t offset = bin.size();
    bin.resize(offset + size);
    if (size != 0) {
      std::memcpy(bin.data() + offset, data, size);
    }
    return offset;
  }

  int add(const char* array, json item) {
    json& items = doc[array];
    if (items.is_null()) {
      items = json::array();
    }
    items.push_back(std::move(item));
    return static_cast<int>(items.size()) - 1;
  }

  int add_view(std::size_t offset, std::size_t length, std::size_t stride = 0) {
    json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
    if (stride != 0) {
      view["byteStride"] = stride;
    }
    return add("bufferViews", view);
  }

  int add_accessor(int view, std::size_t byte_offset, int component_type, std::size_t count,
                   const char* type, bool normalized = false) {
    json a = {{"bufferView", view},
              {"byteOffset", byte_offset},
              {"componentType", component_type},
              {"count", count},
              {"type", type}};
    if (normalized) {
      a["normalized"] = true;
    }
    return add("accessors", a);
  }

  /// Appends `values` (tightly packed), a view and an accessor over them.
  template <class T>
  int add_data(const std::vector<T>& values, int component_type, const char* type,
               std::size_t components, bool normalized = false) {
    const std::size_t offset = append(values.data(), values.size() * sizeof(T));
    const int view = add_view(offset, values.size() * sizeof(T));
    return add_accessor(view, 0, component_type, values.size() / components, type, normalized);
  }

  int add_vec3(const std::vector<glm::vec3>& v) {
    std::vector<float> flat;
    for (const glm::vec3& p : v) {
      flat.insert(flat.end(), {p.x, p.y, p.z});
    }
    return add_data(flat, f32, "VEC3", 3);
  }
  int add_positions(const std::vector<glm::vec3>& v) {
    const int a = add_vec3(v);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : v) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    if (!v.empty()) {
      doc["accessors"][a]["min"] = {lo.x, lo.y, lo.z};
      doc["accessors"][a]["max"] = {hi.x, hi.y, hi.z};
    }
    return a;
  }
  int add_vec2(const std::vector<glm::vec2>& v) {
    std::vector<float> flat;
    for (const glm::vec2& p : v) {
      flat.insert(flat.end(), {p.x, p.y});
    }
    return add_data(flat, f32, "VEC2", 2);
  }
  int add_vec4(const std::vector<glm::vec4>& v) {
    std::vector<float> flat;
    for (const glm::vec4& p : v) {
      flat.insert(flat.end(), {p.x, p.y, p.z, p.w});
    }
    return add_data(flat, f32, "VEC4", 4);
  }

  /// Index accessor with the given component type (u8, u16 or u32).
  int add_indices(const std::vector<std::uint32_t>& indices, int component_type) {
    if (component_type == u8) {
      return add_data(std::vector<std::uint8_t>(indices.begin(), indices.end()), u8, "SCALAR", 1);
    }
    if (component_type == u16) {
      return add_data(std::vector<std::uint16_t>(indices.begin(), indices.end()), u16, "SCALAR", 1);
    }
    return add_data(indices, u32, "SCALAR", 1);
  }

  struct Interleaved {
    int position, normal, uv;
  };
  /// position, normal and uv interleaved in one view with byteStride 32.
  Interleaved add_interleaved(const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& n,
                              const std::vector<glm::vec2>& uv) {
    std::vector<float> data;
    for (std::size_t i = 0; i < p.size(); ++i) {
      data.insert(data.end(), {p[i].x, p[i].y, p[i].z, n[i].x, n[i].y, n[i].z, uv[i].x, uv[i].y});
    }
    const std::size_t offset = append(data.data(), data.size() * sizeof(float));
    const int view = add_view(offset, data.size() * sizeof(float), 32);
    return {add_accessor(view, 0, f32, p.size(), "VEC3"),
            add_accessor(view, 12, f32, p.size(), "VEC3"),
            add_accessor(view, 24, f32, p.size(), "VEC2")};
  }

  /// A mesh with one primitive.
  int add_mesh(json attributes, int indices = -1, int material = -1, int mode = triangles,
               const std::string& name = {}) {
    json prim = {{"attributes", std::move(attributes)}, {"mode", mode}};
    if (indices >= 0) {
      prim["indices"] = indices;
    }
    if (material >= 0) {
      prim["material"] = material;
    }
    json mesh = {{"primitives", json::array({prim})}};
    if (!name.empty()) {
      mesh["name"] = name;
    }
    return add("meshes", mesh);
  }

  int add_node(json node) { return add("nodes", std::move(node)); }

  /// Scene 0 with the given roots, made the default scene.
  void set_scene(const std::vector<int>& roots) {
    doc["scenes"] = json::array({{{"nodes", roots}}});
    doc["scene"] = 0;
  }

  /// An image stored in a buffer view (works in every container).
  int add_image_view(const std::vector<std::uint8_t>& png, const std::string& mime = "image/png") {
    const std::size_t offset = append(png.data(), png.size());
    const int view = add_view(offset, png.size());
    return add("images", {{"bufferView", view}, {"mimeType", mime}});
  }
  int add_image_uri(const std::string& uri) { return add("images", {{"uri", uri}}); }
  int add_texture(int image) { return add("textures", {{"source", image}}); }

  /// The document with buffer 0 completed for `c` (fields a test already set are kept).
  json finished(Container c, const std::string& bin_name) const {
    json d = doc;
    if (!bin.empty()) {
      json& b0 = d["buffers"][0];
      if (!b0.contains("byteLength")) {
        b0["byteLength"] = bin.size();
      }
      if (!b0.contains("uri") && c != Container::glb) {
        b0["uri"] = c == Container::external_bin
                        ? bin_name
                        : "data:application/octet-stream;base64," + base64(bin);
      }
    }
    return d;
  }

  /// The .glb container bytes of `d` (JSON chunk space-padded, BIN chunk zero-padded).
  std::vector<std::uint8_t> glb_bytes(const json& d) const {
    std::string text = d.dump();
    while (text.size() % 4 != 0) {
      text += ' ';
    }
    std::vector<std::uint8_t> padded_bin = bin;
    while (padded_bin.size() % 4 != 0) {
      padded_bin.push_back(0);
    }
    const std::size_t total =
        12 + 8 + text.size() + (padded_bin.empty() ? 0 : 8 + padded_bin.size());
    // Sized up front and filled in place (growing it with insert() trips a false
    // -Wstringop-overflow in GCC 12 at -O3).
    std::vector<std::uint8_t> out(total, 0);
    std::size_t at = 0;
    auto put = [&out, &at](const void* data, std::size_t size) {
      std::memcpy(out.data() + at, data, size);
      at += size;
    };
    auto u32le = [&put](std::uint32_t v) {
      const std::uint8_t b[4] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8),
                                 static_cast<std::uint8_t>(v >> 16),
                                 static_cast<std::uint8_t>(v >> 24)};
      put(b, 4);
    };
    put("glTF", 4);
    u32le(2);
    u32le(static_cast<std::uint32_t>(total));
    u32le(static_cast<std::uint32_t>(text.size()));
    u32le(0x4E4F534Au); // "JSON"
    put(text.data(), text.size());
    if (!padded_bin.empty()) {
      u32le(static_cast<std::uint32_t>(padded_bin.size()));
      u32le(0x004E4942u); // "BIN\0"
      put(padded_bin.data(), padded_bin.size());
    }
    return out;
  }

  /// Writes `<stem>.gltf` (+ `<stem>.bin`) or `<stem>.glb` into `dir`; returns the model's path.
  std::filesystem::path write(const TempDir& dir, const std::string& stem, Container c) const {
    const std::string bin_name = stem + ".bin";
    const json d = finished(c, bin_name);
    if (c == Container::glb) {
      return dir.write(stem + ".glb", glb_bytes(d));
    }
    if (c == Container::external_bin && !bin.empty()) {
      dir.write(bin_name, bin);
    }
    return dir.write(stem + ".gltf", d.dump(1));
  }
};

/// A unit quad in the XY plane, counter-clockwise seen from +Z, u along +X and v = 0 at the top
/// (+Y), as glTF maps images.
struct Quad {
  std::vector<glm::vec3> positions{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  std::vector<glm::vec3> normals{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  std::vector<glm::vec2> uvs{{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
};

/// A document with one quad mesh (positions, normals, uvs, 16-bit indices) under node 0 in
/// scene 0. Returns the builder; node 0 may be edited through doc["nodes"][0].
inline Builder quad_model(int index_type = u16, bool with_normals = true) {
  Builder b;
  const Quad q;
  json attributes = {{"POSITION", b.add_positions(q.positions)}, {"TEXCOORD_0", b.add_vec2(q.uvs)}};
  if (with_normals) {
    attributes["NORMAL"] = b.add_vec3(q.normals);
  }
  const int indices = b.add_indices(q.indices, index_type);
  const int mesh = b.add_mesh(attributes, indices, -1, triangles, "quad");
  b.set_scene({b.add_node({{"mesh", mesh}, {"name", "quad-node"}})});
  return b;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

} // namespace gltf_test

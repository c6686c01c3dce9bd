// libFuzzer target for the glTF loader: every input goes through
// snell::detail::load_gltf_from_memory, the function behind snell::load_gltf (same pre-scan,
// tinygltf callbacks, validation and conversion). Inputs starting with "glTF" are read as .glb,
// others as .gltf JSON. External URIs resolve in a per-process temporary folder holding
// "buffer.bin" and "image.png" (what the seeds in corpus/ refer to), so file access is exercised
// too. A crash, sanitizer report, time-out, or a loaded Scene that breaks the invariants the
// renderer relies on (checked below) is a finding.
#include "gltf_loader.hpp"
#include "mesh_utils.hpp"

#include <snell/scene.hpp>

#include <stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

std::filesystem::path g_folder;

// The contents of buffer.bin: a quad's 4 float positions then 6 uint16 indices (60 bytes), as the
// seed corpus/external.gltf describes them.
std::vector<std::uint8_t> buffer_bin() {
  const float positions[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::vector<std::uint8_t> bytes(sizeof positions + sizeof indices);
  std::memcpy(bytes.data(), positions, sizeof positions);
  std::memcpy(bytes.data() + sizeof positions, indices, sizeof indices);
  return bytes;
}

void write_file(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

void remove_folder() {
  std::error_code ec;
  std::filesystem::remove_all(g_folder, ec);
}

snell::GltfLimits fuzz_limits() {
  // Small limits keep every execution fast and within -rss_limit_mb, and make the limit checks
  // reachable by small inputs.
  snell::GltfLimits limits;
  limits.max_file_bytes = 1u << 20;
  limits.max_data_uri_bytes = 256u << 10;
  limits.max_image_dimension = 256;
  limits.max_image_pixels = 256u * 256u;
  limits.max_total_image_pixels = 4u * 256u * 256u;
  limits.max_total_vertices = 1u << 16;
  limits.max_total_indices = 3u << 16;
  limits.max_node_depth = 32;
  limits.max_total_buffer_bytes = 4u << 20;
  limits.max_objects = 4096;
  return limits;
}

[[noreturn]] void invariant_broken(const char* what) {
  std::fprintf(stderr, "gltf_fuzzer: invariant broken: %s\n", what);
  std::abort();
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) {
        return false;
      }
    }
  }
  return true;
}

void check_texture(int index, const snell::Scene& scene) {
  if (index < -1 || index >= static_cast<int>(scene.images.size())) {
    invariant_broken("material texture index out of range");
  }
}

// What a loaded Scene promises to the renderer.
void check_scene(const snell::Scene& scene, const snell::GltfLimits& limits) {
  std::uint64_t vertices = 0;
  std::uint64_t indices = 0;
  for (const snell::Mesh& mesh : scene.meshes) {
    vertices += mesh.vertices.size();
    indices += mesh.indices.size();
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) {
      invariant_broken("mesh indices are not whole triangles");
    }
    if (snell::detail::first_index_out_of_range(mesh.indices, mesh.vertices.size())) {
      invariant_broken("index past the vertex count");
    }
    if (snell::detail::first_non_finite_vertex(mesh.vertices)) {
      invariant_broken("non-finite vertex attribute");
    }
    for (const snell::Vertex& v : mesh.vertices) {
      if (std::abs(glm::length(v.normal) - 1.0f) > 1e-3f ||
          std::abs(glm::length(glm::vec3(v.tangent)) - 1.0f) > 1e-3f ||
          std::abs(v.tangent.w) != 1.0f) {
        invariant_broken("normal or tangent not unit, or tangent.w not +-1");
      }
    }
    if (mesh.material < -1 || mesh.material >= static_cast<int>(scene.materials.size())) {
      invariant_broken("mesh material out of range");
    }
  }
  if (vertices > limits.max_total_vertices || indices > limits.max_total_indices ||
      scene.objects.size() > limits.max_objects) {
    invariant_broken("totals over the limits");
  }
  for (const snell::Material& m : scene.materials) {
    check_texture(m.base_color_texture, scene);
    check_texture(m.normal_texture, scene);
    check_texture(m.emissive_texture, scene);
  }
  std::uint64_t pixels = 0;
  for (const snell::Image& image : scene.images) {
    pixels += static_cast<std::uint64_t>(image.width) * image.height;
    if (image.width == 0 || image.height == 0 ||
        image.rgba8.size() != static_cast<std::size_t>(image.width) * image.height * 4 ||
        image.width > limits.max_image_dimension || image.height > limits.max_image_dimension) {
      invariant_broken("image size");
    }
  }
  if (pixels > limits.max_total_image_pixels) {
    invariant_broken("decoded pixels over the limit");
  }
  for (const snell::Object& o : scene.objects) {
    if (o.mesh < 0 || o.mesh >= static_cast<int>(scene.meshes.size()) || !finite(o.transform)) {
      invariant_broken("object mesh index or transform");
    }
  }
  for (const snell::CameraDesc& c : scene.cameras) {
    if (!std::isfinite(c.eye.x + c.eye.y + c.eye.z + c.target.x + c.target.y + c.target.z) ||
        !(c.yfov > 0.0f) || !(c.z_near > 0.0f) || !(c.z_far > c.z_near)) {
      invariant_broken("camera");
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::random_device rd;
  g_folder = std::filesystem::temp_directory_path() /
             ("snell-gltf-fuzz-" + std::to_string(rd()) + "-" + std::to_string(rd()));
  std::filesystem::create_directories(g_folder);
  std::atexit(&remove_folder);
  write_file(g_folder / "buffer.bin", buffer_bin());
  const std::uint8_t pixels[16] = {255, 0, 0,   255, 0,   255, 0,   255,
                                   0,   0, 255, 255, 255, 255, 255, 128};
  std::vector<std::uint8_t> png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        out->insert(out->end(), static_cast<std::uint8_t*>(data),
                    static_cast<std::uint8_t*>(data) + size);
      },
      &png, 2, 2, 4, pixels, 8);
  write_file(g_folder / "image.png", png);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const snell::GltfLimits limits = fuzz_limits();
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const snell::Result<snell::Scene> scene = snell::detail::load_gltf_from_memory(
      data, size, g_folder, binary, limits, binary ? "fuzz-input.glb" : "fuzz-input.gltf");
  if (scene) {
    check_scene(*scene, limits);
  } else if (scene.error().message.rfind("fuzz-input", 0) != 0) {
    invariant_broken("error message does not start with the file name");
  }
  return 0;
}

// Snell runtime: the CPU-side scene (meshes, materials, images, objects, cameras, light, sky).
//
// A Scene is plain data with no Vulkan objects: the glTF loader and the built-in procedural
// scenes produce one, the SceneRenderer uploads it. It can be built, inspected and tested
// without a GPU.
#pragma once

#include <snell/result.hpp>
#include <snell/scene_types.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace snell {

/// One vertex as the scene shaders read it (interleaved, 48 bytes).
struct Vertex {
  glm::vec3 position{0.0f};                  ///< Object-space position.
  glm::vec3 normal{0.0f, 1.0f, 0.0f};        ///< Object-space unit normal.
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; ///< xyz unit tangent, w = bitangent sign (glTF).
  glm::vec2 uv{0.0f}; ///< Texture coordinate (glTF: v = 0 is the image's first row).
};

/// An 8-bit RGBA image in memory, rows top first.
struct Image {
  std::string name{};                ///< Source file or generator name (for messages).
  std::uint32_t width = 0;           ///< Pixels; > 0 for a usable image.
  std::uint32_t height = 0;          ///< Pixels; > 0 for a usable image.
  std::vector<std::uint8_t> rgba8{}; ///< width * height * 4 bytes.
  bool srgb = true;                  ///< Colour data (sRGB) or linear data (normal maps).
};

/// glTF alpha modes.
enum class AlphaMode : std::uint8_t { opaque, mask, blend };

/// A surface material (glTF metallic-roughness subset plus the extensions Snell reads).
struct Material {
  std::string name{};
  glm::vec4 base_color{1.0f};  ///< Linear RGBA factor. Default white, opaque.
  int base_color_texture = -1; ///< Index into Scene::images, or -1 for none.
  int normal_texture = -1;     ///< Index into Scene::images (linear), or -1.
  float normal_scale = 1.0f;   ///< glTF normalTexture.scale. Default 1.
  glm::vec3 emissive{0.0f};    ///< Linear emitted radiance factor. Default black.
  int emissive_texture = -1;   ///< Index into Scene::images, or -1.
  float roughness = 0.5f;      ///< [0,1]; drives the Blinn-Phong exponent. Default 0.5.
  float specular = 0.5f;       ///< Specular intensity [0,1]. Default 0.5.
  AlphaMode alpha_mode = AlphaMode::opaque; ///< Default opaque.
  float alpha_cutoff = 0.5f;                ///< For AlphaMode::mask. Default 0.5.
  bool double_sided = false;                ///< Disable back-face culling. Default false.
  float transmission = 0.0f;                ///< KHR_materials_transmission factor [0,1]. Default 0.
  float ior = 1.5f;                         ///< KHR_materials_ior. Default 1.5 (the glTF default).
  /// KHR_materials_volume thicknessFactor: thickness of the volume under the surface, in the
  /// mesh's own coordinate space (scaled by the object's transform along the normal). 0 =
  /// thin-walled (no volume: light passes without a lateral shift). Default 0. [0, inf).
  float thickness = 0.0f;
  /// KHR_materials_volume attenuationColor: linear colour white light has after travelling
  /// attenuation_distance through the volume (Beer-Lambert). Default (1, 1, 1). Each in [0, 1].
  glm::vec3 attenuation_color{1.0f};
  /// KHR_materials_volume attenuationDistance, in world units: the distance at which light is
  /// tinted to attenuation_color. Default +infinity (no attenuation, glTF's default). (0, inf].
  float attenuation_distance = std::numeric_limits<float>::infinity();
  /// KHR_materials_dispersion: 20 / Abbe number (0 = none; crown glass ~0.3, diamond ~0.9).
  /// Spreads the IOR per channel: half-spread = (ior - 1) * 0.025 * dispersion, red below and
  /// blue above `ior` (the extension's reference formula). Default 0. [0, inf).
  float dispersion = 0.0f;
  glm::vec2 uv_scale{1.0f}; ///< Texture coordinate scale (tiling). Default 1.
};

/// A triangle list with one material (a glTF primitive).
struct Mesh {
  std::string name{};
  std::vector<Vertex> vertices{};
  std::vector<std::uint32_t> indices{}; ///< Triangle list; always indexed after loading.
  int material = -1;                    ///< Index into Scene::materials, or -1 for the default.
};

/// An instance of a mesh in the world.
struct Object {
  std::string name{};
  int mesh = -1;                         ///< Index into Scene::meshes.
  glm::mat4 transform{1.0f};             ///< Object to world at time 0.
  std::uint32_t layers = layer::all;     ///< Bit mask of snell::layer values. Default all.
  glm::vec3 spin_axis{0.0f, 1.0f, 0.0f}; ///< Unit axis of an optional spin, in object space.
  float spin_rate = 0.0f;                ///< Radians per second; 0 = static. Default 0.
  /// World transform at `time` seconds: `transform * rotate(spin_rate * time, spin_axis)`.
  [[nodiscard]] glm::mat4 world_at(float time) const;
};

/// A perspective camera.
struct CameraDesc {
  std::string name{};
  glm::vec3 eye{0.0f, 2.0f, 8.0f}; ///< World position.
  glm::vec3 target{0.0f};          ///< World point looked at.
  glm::vec3 up{0.0f, 1.0f, 0.0f};  ///< Approximate up.
  float yfov = 0.7853982f;         ///< Vertical field of view, radians. Default 45 degrees.
  float z_near = 0.1f;             ///< > 0. Default 0.1.
  float z_far = 200.0f;            ///< > z_near, or +inf. Default 200.
};

/// A gradient sky: horizon to zenith above, horizon to ground below.
struct Sky {
  glm::vec3 zenith{0.20f, 0.42f, 0.80f};  ///< Linear colour straight up.
  glm::vec3 horizon{0.75f, 0.85f, 0.95f}; ///< Linear colour at the horizon.
  glm::vec3 ground{0.30f, 0.28f, 0.25f};  ///< Linear colour straight down.
};

/// A named place in a scene that effects can attach to (the pool's water surface, the window
/// quad, the centre sphere of a cube-map probe). Built-in scenes define them; effects look them
/// up by name so that a scene and an effect need not know each other.
struct Anchor {
  std::string name{};       ///< E.g. "water", "window", "probe".
  glm::vec3 position{0.0f}; ///< World-space centre.
  glm::vec3 size{0.0f};     ///< World-space extent (full width, height, depth).
  int object = -1;          ///< The object it belongs to (index into Scene::objects), or -1.
};

/// A complete scene.
struct Scene {
  std::string name{};
  std::vector<Mesh> meshes{};
  std::vector<Material> materials{};
  std::vector<Image> images{};
  std::vector<Object> objects{};
  std::vector<CameraDesc> cameras{}; ///< cameras[0] is the default view when present.
  std::vector<Anchor> anchors{};     ///< Named places for effects (see Anchor).
  DirectionalLight light{};
  Sky sky{};
  /// The anchor called `name`, or nullptr.
  [[nodiscard]] const Anchor* find_anchor(std::string_view name) const;
  /// Axis-aligned bounds of all objects at time 0 (min, max); empty scene: zero box.
  [[nodiscard]] std::pair<glm::vec3, glm::vec3> bounds() const;
};

/// Limits that make loading untrusted files safe. Every refusal names the file and the limit.
struct GltfLimits {
  std::uint64_t max_file_bytes = 256ull
                                 << 20; ///< Any single file (gltf, glb, bin, image). 256 MiB.
  std::uint64_t max_data_uri_bytes = 64ull << 20;     ///< Decoded size of one data: URI. 64 MiB.
  std::uint32_t max_image_dimension = 8192;           ///< Width or height of any image. 8192.
  std::uint64_t max_image_pixels = 8192ull * 8192ull; ///< Width * height of any image.
  std::uint64_t max_total_vertices = 16ull << 20;     ///< Over all meshes. 16 Mi.
  std::uint64_t max_total_indices = 48ull << 20;      ///< Over all meshes. 48 Mi.
  std::uint32_t max_node_depth = 64;                  ///< Deepest node hierarchy accepted. 64.
  /// Sum of the byteLength of all buffers. 1 GiB. (Many buffers may name the same file.)
  std::uint64_t max_total_buffer_bytes = 1ull << 30;
  /// Sum of width * height over all decoded images. 256 Mi (1 GiB as RGBA8).
  std::uint64_t max_total_image_pixels = 256ull << 20;
  /// Objects created (node instances times the triangle primitives of their mesh). 1 Mi.
  std::uint64_t max_objects = 1ull << 20;
};

/// Loads a glTF 2.0 file (`.gltf` with external or embedded buffers, or `.glb`).
///
/// Files are read only through the loader's file-system callbacks: relative URIs resolve under
/// the model's folder; absolute paths, `..` escapes and files over the limits are refused with
/// ErrorCode::access_denied / limit_exceeded. Missing normals and tangents are generated.
/// Node transforms are flattened into Object::transform (negative scales are kept; the renderer
/// flips the winding of objects whose transform has a negative determinant).
[[nodiscard]] Result<Scene> load_gltf(const std::filesystem::path& path,
                                      const GltfLimits& limits = {});

} // namespace snell

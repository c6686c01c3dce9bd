// Snell plugin toolkit: the geometry an effect draws with its own shading (water's rectangle,
// glass panes, transmissive glTF meshes, a probe's sphere). One facility uploads it, from three
// sources: nodes of a Scene (with their world transforms and materials), arrays a host passes,
// or built-in shapes. Surfaces taken from a Scene report their objects, so the effect can name
// them in Effect::drawn_objects and the scene renderer leaves them out.
#pragma once

#include <snell/buffer.hpp>
#include <snell/effect.hpp>
#include <snell/pipeline.hpp>
#include <snell/scene.hpp>
#include <snell/span.hpp>

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace snell {

/// Built-in shapes, in object space (centred on the origin).
enum class Shape : std::uint8_t {
  quad,   ///< 1 x 1 in the XZ plane, facing +Y (y = 0); u along +X, v toward +Z.
  box,    ///< 1 x 1 x 1 cube, flat faces, outward normals.
  sphere, ///< Radius 0.5, 48 segments x 24 rings.
};

/// One uploaded mesh and where it is.
struct Surface {
  Buffer vertices{};             ///< snell::Vertex, binding 0 (RasterState::vertex_input).
  Buffer indices{};              ///< uint32 triangle list.
  std::uint32_t index_count = 0; ///< Indices to draw.
  glm::mat4 world{1.0f};         ///< Object to world (at time 0 for scene objects).
  Material material{};           ///< Its material (the default one when it has none).
  int object = -1;               ///< Index into Scene::objects, or -1 (arrays, shapes).
  glm::vec3 bounds_min{0.0f};    ///< Object-space bounds of the vertices.
  glm::vec3 bounds_max{0.0f};
};

/// A set of uploaded surfaces (move-only; the buffers must not outlive the Context).
class Surfaces {
public:
  /// Chooses scene objects: (object, its mesh, its material) -> draw it with the effect.
  using Selector = std::function<bool(const Object&, const Mesh&, const Material&)>;

  /// The objects of `scene` that `select` picks (all when empty), uploaded with their world
  /// transforms and materials. Errors: out_of_memory, invalid_argument for a mesh without
  /// indices (names the object).
  [[nodiscard]] static Result<Surfaces> from_scene(const Context& ctx, const Scene& scene,
                                                   const Selector& select = {});
  /// One mesh from arrays a host passes (indices: a triangle list into `vertices`). Errors:
  /// invalid_argument (empty arrays, an index out of range, not a multiple of 3).
  [[nodiscard]] static Result<Surfaces> from_arrays(const Context& ctx, Span<const Vertex> vertices,
                                                    Span<const std::uint32_t> indices,
                                                    const glm::mat4& world = glm::mat4(1.0f),
                                                    const Material& material = {});
  /// One built-in shape at `world`.
  [[nodiscard]] static Result<Surfaces> shape(const Context& ctx, Shape shape,
                                              const glm::mat4& world = glm::mat4(1.0f),
                                              const Material& material = {});

  Surfaces() = default;
  [[nodiscard]] std::size_t size() const { return surfaces_.size(); }
  [[nodiscard]] bool empty() const { return surfaces_.empty(); }
  [[nodiscard]] const Surface& operator[](std::size_t i) const { return surfaces_[i]; }
  [[nodiscard]] Surface& operator[](std::size_t i) { return surfaces_[i]; }
  /// The Scene::objects indices of the surfaces taken from a scene (for drawn_objects()).
  [[nodiscard]] Span<const int> objects() const { return objects_; }
  /// Appends every surface of `other`.
  void append(Surfaces&& other);
  /// Binds surface `i`'s vertex and index buffers and draws it (one instance).
  void draw(VkCommandBuffer cmd, std::size_t i) const;

private:
  std::vector<Surface> surfaces_;
  std::vector<int> objects_;
};

/// The pipeline description of an effect's surfaces, drawn in phase 5 inside the host's main
/// rendering: its colour and depth formats from `info`, snell::Vertex input, depth test LESS,
/// no depth write (the opaque depth behind a transmissive surface stays for the effects drawn
/// after it), no blending. `label` names it in errors; `vertex`/`fragment` are SPIR-V; set i of
/// the layout is `set_layouts[i]`. Adjust the returned struct for anything else.
[[nodiscard]] inline GraphicsPipelineDesc
surface_pipeline_desc(const EffectCreateInfo& info, const char* label,
                      Span<const std::uint32_t> vertex, Span<const std::uint32_t> fragment,
                      std::vector<VkDescriptorSetLayout> set_layouts) {
  GraphicsPipelineDesc desc;
  desc.label = label;
  desc.vertex = vertex;
  desc.fragment = fragment;
  desc.set_layouts = std::move(set_layouts);
  desc.state.color_formats = {info.color_format};
  desc.state.depth_format = info.depth_format;
  desc.state.depth_write = false;
  return desc;
}

} // namespace snell

// The embed-host sample's scene and its snell::SceneSource: a pool (floor below the water, a
// deck around it), pillars standing in the water, a box under the water and boxes above it,
// drawn with the host's own pipelines and shaders for whatever view an effect asks for.
#pragma once

#include "host_vulkan.hpp"

#include <snell/scene.hpp>
#include <snell/scene_source.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace embed {

/// The water rectangle of the scene: the pool's opening, at y = height.
struct PoolWater {
  float height = 0.0f;
  glm::vec2 center{0.0f, 0.0f}; ///< (x, z)
  glm::vec2 size{12.0f, 8.0f};  ///< (x, z)
};

/// The host's scene. Implements snell::SceneSource, so effects can draw it into their targets.
class HostScene final : public snell::SceneSource {
public:
  /// One object: a range of the vertex buffer and its snell::layer bits.
  struct Object {
    std::string name;
    std::uint32_t first_vertex = 0;
    std::uint32_t vertex_count = 0;
    std::uint32_t layers = snell::layer::all;
  };

  HostScene() = default;
  HostScene(const HostScene&) = delete;
  HostScene& operator=(const HostScene&) = delete;
  ~HostScene() override;

  /// Builds the geometry around `water`, uploads it and creates the shaders; throws HostError.
  /// Pipelines are created on first use, per (colour format, depth format).
  void init(const HostDevice& device, const PoolWater& water);

  /// snell::SceneSource: draws the objects whose layers intersect `view.layer_mask`, then the
  /// sky, for `view` (matrices, clip plane, front face, attachment formats). Viewport and scissor
  /// are the caller's (Snell's targets set them in begin_rendering). Never throws: a pipeline
  /// that cannot be created, or a multiview view, is returned as an error and nothing is drawn.
  [[nodiscard]] snell::Result<void> draw_scene(VkCommandBuffer cmd,
                                               const snell::SceneView& view) override;
  [[nodiscard]] const std::vector<Object>& objects() const { return objects_; }

  /// The light every view is lit with (also handed to the effects in snell::FrameInfo).
  snell::DirectionalLight light;
  /// The colour the host clears its main target to: the sky's horizon (linear RGB).
  static constexpr float kSkyClear[4] = {0.62f, 0.74f, 0.90f, 1.0f};

private:
  struct Pipelines {
    VkPipeline geometry = VK_NULL_HANDLE;
    VkPipeline sky = VK_NULL_HANDLE;
  };
  /// The pipelines for this pair of attachment formats, created on first use.
  const Pipelines* pipelines_for(VkFormat color, VkFormat depth);

  const HostDevice* dev_ = nullptr;
  std::vector<Object> objects_;
  VkBuffer vertices_ = VK_NULL_HANDLE;
  VkDeviceMemory vertex_memory_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkShaderModule scene_vert_ = VK_NULL_HANDLE, scene_frag_ = VK_NULL_HANDLE;
  VkShaderModule sky_vert_ = VK_NULL_HANDLE, sky_frag_ = VK_NULL_HANDLE;
  std::map<std::pair<VkFormat, VkFormat>, Pipelines> pipelines_;
  std::string error_;
};

} // namespace embed

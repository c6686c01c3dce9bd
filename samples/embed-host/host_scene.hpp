// The embed-host sample's scene and its snell::SceneSource: a pool (floor below the water, a
// deck around it), pillars standing in the water, a box under the water and boxes above it, a
// chrome ball on the deck shaded from Snell's probe (the host's own material, with Snell's
// snell/probe.glsl), and a wall behind the camera, drawn with the host's own pipelines and
// shaders for whatever view an effect asks for.
#pragma once

#include "host_vulkan.hpp"

#include <snell/probe_directory.hpp>
#include <snell/scene.hpp>
#include <snell/scene_source.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

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

/// The chrome ball standing on the deck: a metal mirror the host shades from a probe.
struct ChromeBall {
  glm::vec3 center{0.0f}; ///< World position, m.
  float radius = 1.0f;    ///< m.
  /// Reflectance at normal incidence, linear RGB (Schlick's F0 of the metal): a bright mirror.
  glm::vec3 f0{0.80f, 0.80f, 0.82f};
  float roughness = 0.0f; ///< The lookup's blur, a fraction of the cube's mip levels.
};

/// The host's scene. Implements snell::SceneSource, so effects can draw it into their targets.
class HostScene final : public snell::SceneSource {
public:
  /// One object: a range of the vertex buffer, its snell::layer bits, and (for --check's
  /// predictions) its bounds and colour.
  struct Object {
    std::string name;
    std::uint32_t first_vertex = 0;
    std::uint32_t vertex_count = 0;
    std::uint32_t layers = snell::layer::all;
    glm::vec3 lo{0.0f}, hi{0.0f}; ///< World bounds (a box object is exactly its bounds).
    glm::vec4 color{0.0f};        ///< rgb: linear colour; a: tile contrast.
    bool chrome = false;          ///< Drawn with the chrome material (the probe's cube).
  };

  HostScene() = default;
  HostScene(const HostScene&) = delete;
  HostScene& operator=(const HostScene&) = delete;
  ~HostScene() override;

  /// Builds the geometry around `water`, uploads it and creates the shaders, and the chrome
  /// material's descriptor sets (one per frame in flight); throws HostError. Pipelines are
  /// created on first use, per (colour format, depth format).
  void init(const HostDevice& device, const PoolWater& water, std::uint32_t frames_in_flight);

  /// Points the chrome material at `probe` for the frame `frame_index`, or draws the chrome ball
  /// with a flat colour this frame when `probe` is nullptr. Call it once per frame, after the
  /// probe's record_passes (phase 2: the cube this frame publishes) and before any draw_scene
  /// that may draw the ball. The frame's slot (frame_index % frames in flight) is rewritten only
  /// when the probe's cube or sampler changed, and only once the host has waited for the frame
  /// that last used the slot; nothing in this frame's command buffer has bound it yet.
  void use_probe(const snell::ProbeView* probe, std::uint64_t frame_index);

  /// snell::SceneSource: draws the objects whose layers intersect `view.layer_mask` (the chrome
  /// ball with the chrome material when use_probe gave it a probe this frame), then the sky, for
  /// `view` (matrices, clip plane, eye, front face, attachment formats). Viewport and scissor
  /// are the caller's (Snell's targets set them in begin_rendering). Never throws: a pipeline
  /// that cannot be created, or a multiview view, is returned as an error and nothing is drawn.
  [[nodiscard]] snell::Result<void> draw_scene(VkCommandBuffer cmd,
                                               const snell::SceneView& view) override;
  [[nodiscard]] const std::vector<Object>& objects() const { return objects_; }
  [[nodiscard]] const ChromeBall& chrome_ball() const { return ball_; }

  /// The light every view is lit with (also handed to the effects in snell::FrameInfo).
  snell::DirectionalLight light;
  /// The colour the host clears its main target to: the sky's horizon (linear RGB).
  static constexpr float kSkyClear[4] = {0.62f, 0.74f, 0.90f, 1.0f};

private:
  struct Pipelines {
    VkPipeline geometry = VK_NULL_HANDLE;
    VkPipeline sky = VK_NULL_HANDLE;
    VkPipeline chrome = VK_NULL_HANDLE; ///< Colour passes only.
  };
  /// One frame slot of the chrome material: its descriptor set, what the set points at, and
  /// its slice of the uniform buffer.
  struct ProbeSlot {
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkImageView cube = VK_NULL_HANDLE; ///< The cube `set` points at (NULL: never written).
    VkSampler sampler = VK_NULL_HANDLE;
    VkDeviceSize offset = 0; ///< Of its ChromeBlock in chrome_ubo_.
  };
  void create_chrome_material(std::uint32_t frames_in_flight);
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
  // The chrome material: its own shaders, pipeline layout (push constants + one set), and one
  // descriptor set and uniform block per frame in flight.
  ChromeBall ball_;
  VkShaderModule chrome_vert_ = VK_NULL_HANDLE, chrome_frag_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout chrome_set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout chrome_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool chrome_pool_ = VK_NULL_HANDLE;
  VkBuffer chrome_ubo_ = VK_NULL_HANDLE;
  VkDeviceMemory chrome_ubo_memory_ = VK_NULL_HANDLE;
  void* chrome_mapped_ = nullptr;
  std::vector<ProbeSlot> probe_slots_;
  const ProbeSlot* probe_slot_ = nullptr; ///< This frame's slot, or nullptr: a flat ball.
  std::string error_;
};

} // namespace embed

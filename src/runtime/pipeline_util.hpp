// Internal: small builders for shader modules and dynamic-rendering graphics pipelines.
#pragma once

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

namespace snell::detail {

/// Creates a shader module from embedded SPIR-V.
Result<VkShaderModule> create_shader_module(VkDevice device, std::span<const std::uint32_t> code,
                                            std::string_view name);

/// What varies between Snell's graphics pipelines.
struct GraphicsPipelineDesc {
  VkShaderModule vertex = VK_NULL_HANDLE;
  VkShaderModule fragment = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkFormat color_format = VK_FORMAT_UNDEFINED;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  std::uint32_t view_mask = 0;
  bool vertex_input = true; ///< Snell's Vertex layout (else no vertex buffers).
  bool depth_test = true;
  bool depth_write = true;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
  bool alpha_blend = false; ///< Premultiplied-free "over" blending.
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
};

/// Creates a graphics pipeline for dynamic rendering with dynamic viewport, scissor, cull mode
/// and front face.
Result<VkPipeline> create_graphics_pipeline(VkDevice device, const GraphicsPipelineDesc& desc,
                                            std::string_view name);

} // namespace snell::detail

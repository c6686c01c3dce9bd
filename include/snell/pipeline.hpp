// Snell runtime: small builders for shader modules and dynamic-rendering graphics pipelines,
// used by the runtime and by plugins (the caller owns and destroys what they return).
#pragma once

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

namespace snell {

/// Creates a shader module from SPIR-V words (e.g. Snell's embedded `snell::shaders::*`).
/// Errors name `name` and the VkResult.
[[nodiscard]] Result<VkShaderModule>
create_shader_module(VkDevice device, std::span<const std::uint32_t> code, std::string_view name);

/// What varies between Snell's graphics pipelines. Everything else is fixed: one colour
/// attachment, fill mode, no multisampling, no depth clamp (oblique near-plane clipping needs
/// real near clipping), dynamic viewport, scissor, cull mode and front face.
struct GraphicsPipelineDesc {
  VkShaderModule vertex = VK_NULL_HANDLE;      ///< Required; entry point "main".
  VkShaderModule fragment = VK_NULL_HANDLE;    ///< Required; entry point "main".
  VkPipelineLayout layout = VK_NULL_HANDLE;    ///< Required.
  VkFormat color_format = VK_FORMAT_UNDEFINED; ///< The colour attachment's format. Required.
  VkFormat depth_format = VK_FORMAT_UNDEFINED; ///< Depth attachment format; UNDEFINED = none.
  std::uint32_t view_mask = 0;                 ///< Multiview mask (0 = single view). Default 0.
  bool vertex_input = true; ///< Read snell::Vertex from binding 0 (else none). Default true.
  bool depth_test = true;   ///< Test against the depth attachment (if any). Default true.
  bool depth_write = true;  ///< Write depth (if any). Default true.
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS; ///< Default LESS (depth range [0,1]).
  /// Straight-alpha "over" blending: rgb = src.rgb * a + dst.rgb * (1 - a),
  /// alpha = a + dst.a * (1 - a). Default false (opaque).
  bool alpha_blend = false;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST; ///< Default triangle list.
};

/// Creates a graphics pipeline for dynamic rendering. Errors name `name` and the VkResult.
[[nodiscard]] Result<VkPipeline>
create_graphics_pipeline(VkDevice device, const GraphicsPipelineDesc& desc, std::string_view name);

} // namespace snell

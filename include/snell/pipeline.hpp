// Snell runtime: shader modules and pipelines for dynamic rendering and compute. `Pipeline` is
// the RAII object plugins use (it owns its layout); the free functions are its building blocks,
// shared with the runtime's own renderers (the caller owns what they return).
#pragma once

#include <snell/result.hpp>
#include <snell/span.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace snell {

class Context;

/// Creates a shader module from SPIR-V words (e.g. an embedded `snell::<plugin>::shaders::*`).
/// Errors name `name` and the VkResult.
[[nodiscard]] Result<VkShaderModule>
create_shader_module(VkDevice device, Span<const std::uint32_t> code, std::string_view name);

/// The fixed-function state of a graphics pipeline. Not configurable: fill mode, no depth clamp
/// (oblique near-plane clipping needs real near clipping), dynamic viewport, scissor, cull mode
/// and front face (mirrored passes swap the front face per draw).
struct RasterState {
  /// One format per colour attachment, in attachment order. Default: none (depth only).
  std::vector<VkFormat> color_formats{};
  VkFormat depth_format = VK_FORMAT_UNDEFINED; ///< Depth attachment format; UNDEFINED = none.
  /// Samples per pixel of the attachments. Default 1.
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  std::uint32_t view_mask = 0; ///< Multiview mask (0 = single view; 0b111111 cube). Default 0.
  bool vertex_input = true;    ///< Read snell::Vertex from binding 0 (else none). Default true.
  /// With vertex_input: the snell::Vertex attributes bound, one bit per shader location
  /// (0 position, 1 normal, 2 tangent, 3 uv). Default 0xF (all). Pipeline::create binds only
  /// those its vertex shader declares as inputs.
  std::uint32_t vertex_attributes = 0xFu;
  bool depth_test = true;  ///< Test against the depth attachment (if any). Default true.
  bool depth_write = true; ///< Write depth (if any). Default true.
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS; ///< Default LESS (depth range [0,1]).
  /// Straight-alpha "over" blending on every attachment: rgb = src.rgb * a + dst.rgb * (1 - a),
  /// alpha = a + dst.a * (1 - a). Default false (opaque).
  bool alpha_blend = false;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST; ///< Default triangle list.
};

/// Creates a graphics pipeline from modules (entry points "main") and a layout the caller owns.
/// `constants`: specialization constants of both stages, constant_id i = constants[i] (32-bit
/// each; bool constants take 0 or 1). Default none. Errors name `name` and the VkResult.
[[nodiscard]] Result<VkPipeline>
create_graphics_pipeline(VkDevice device, VkShaderModule vertex, VkShaderModule fragment,
                         VkPipelineLayout layout, const RasterState& state, std::string_view name,
                         Span<const std::uint32_t> constants = {});

/// The input locations a vertex shader's SPIR-V declares (one bit per location; all bits when
/// the words cannot be read as SPIR-V).
[[nodiscard]] std::uint32_t vertex_input_locations(Span<const std::uint32_t> spirv);

/// A graphics pipeline described with SPIR-V: what Pipeline::create takes.
struct GraphicsPipelineDesc {
  const char* label = "graphics pipeline"; ///< Names the pipeline in errors. Required non-null.
  Span<const std::uint32_t> vertex{};      ///< Vertex shader SPIR-V (entry "main"). Required.
  Span<const std::uint32_t> fragment{};    ///< Fragment shader SPIR-V (entry "main"). Required.
  std::vector<VkDescriptorSetLayout> set_layouts{};  ///< Set i = set_layouts[i]. Default none.
  std::vector<VkPushConstantRange> push_constants{}; ///< Default none.
  RasterState state{}; ///< Attachments, samples, view mask, depth, blending, topology.
  /// Specialization constants of both stages: constant_id i takes constants[i] (32-bit each).
  /// Branches on them are removed when the pipeline is built: one shader, cheap variants (on
  /// lavapipe every branch of a shader costs, taken or not). Default none.
  std::vector<std::uint32_t> constants{};
};

/// A compute pipeline described with SPIR-V.
struct ComputePipelineDesc {
  const char* label = "compute pipeline"; ///< Names the pipeline in errors. Required non-null.
  Span<const std::uint32_t> compute{};    ///< Compute shader SPIR-V (entry "main"). Required.
  std::vector<VkDescriptorSetLayout> set_layouts{};  ///< Default none.
  std::vector<VkPushConstantRange> push_constants{}; ///< Default none.
  /// Specialization constants: constant_id i takes constants[i] (32-bit each), e.g. a loop
  /// count, which lavapipe then compiles in instead of re-specialising per dispatch. Default
  /// none.
  std::vector<std::uint32_t> constants{};
};

/// A pipeline and its layout (RAII, move-only). Must not outlive its Context.
class Pipeline {
public:
  /// Builds a graphics pipeline. Errors: invalid_argument (a missing shader), vulkan_error
  /// naming `desc.label` and the VkResult.
  [[nodiscard]] static Result<Pipeline> create(const Context& ctx,
                                               const GraphicsPipelineDesc& desc);
  /// Builds a compute pipeline.
  [[nodiscard]] static Result<Pipeline> create(const Context& ctx, const ComputePipelineDesc& desc);

  Pipeline() = default;
  Pipeline(Pipeline&& other) noexcept;
  Pipeline& operator=(Pipeline&& other) noexcept;
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;
  ~Pipeline();

  /// vkCmdBindPipeline at the pipeline's bind point.
  void bind(VkCommandBuffer cmd) const;
  [[nodiscard]] VkPipeline handle() const { return pipeline_; }
  [[nodiscard]] VkPipelineLayout layout() const { return layout_; }
  /// GRAPHICS or COMPUTE.
  [[nodiscard]] VkPipelineBindPoint bind_point() const { return bind_point_; }
  [[nodiscard]] explicit operator bool() const { return pipeline_ != VK_NULL_HANDLE; }

private:
  void reset();
  VkDevice device_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipelineBindPoint bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
};

} // namespace snell

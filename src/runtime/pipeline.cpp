#include <snell/pipeline.hpp>

#include <snell/context.hpp>

#include <snell/scene.hpp>

#include "vk_util.hpp"

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace snell {

using detail::vk_init;

Result<VkShaderModule> create_shader_module(VkDevice device, Span<const std::uint32_t> code,
                                            std::string_view name) {
  if (code.empty()) {
    return fail(ErrorCode::invalid_argument, std::string(name) + ": no SPIR-V code");
  }
  auto ci = vk_init<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  ci.codeSize = code.size() * sizeof(std::uint32_t);
  ci.pCode = code.data();
  VkShaderModule module = VK_NULL_HANDLE;
  SNELL_VK_TRY(vkCreateShaderModule(device, &ci, nullptr, &module), name);
  return module;
}

Result<VkPipeline> create_graphics_pipeline(VkDevice device, VkShaderModule vertex,
                                            VkShaderModule fragment, VkPipelineLayout layout,
                                            const RasterState& desc, std::string_view name,
                                            Span<const std::uint32_t> constants) {
  // constant_id i = constants[i], 4 bytes each, for both stages.
  std::vector<VkSpecializationMapEntry> entries(constants.size());
  for (std::size_t i = 0; i < constants.size(); ++i) {
    entries[i] = {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(4 * i), 4};
  }
  const VkSpecializationInfo specialization{static_cast<std::uint32_t>(entries.size()),
                                            entries.data(), 4 * constants.size(), constants.data()};
  VkPipelineShaderStageCreateInfo stages[2];
  stages[0] =
      vk_init<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex;
  stages[0].pName = "main";
  stages[0].pSpecializationInfo = constants.empty() ? nullptr : &specialization;
  stages[1] = stages[0];
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment;

  const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, normal))},
      {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, tangent))},
      {3, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<std::uint32_t>(offsetof(Vertex, uv))},
  };
  VkVertexInputAttributeDescription used[4]{};
  auto vi = vk_init<VkPipelineVertexInputStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  if (desc.vertex_input) {
    vi.vertexBindingDescriptionCount = 1;
    vi.pVertexBindingDescriptions = &binding;
    // Only the locations the vertex shader reads: a bound attribute it does not consume is a
    // validation (performance) message.
    for (const VkVertexInputAttributeDescription& a : attributes) {
      if ((desc.vertex_attributes & (1u << a.location)) != 0) {
        used[vi.vertexAttributeDescriptionCount++] = a;
      }
    }
    vi.pVertexAttributeDescriptions = used;
  }
  auto ia = vk_init<VkPipelineInputAssemblyStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  ia.topology = desc.topology;
  auto vp = vk_init<VkPipelineViewportStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  vp.viewportCount = 1;
  vp.scissorCount = 1;
  auto rs = vk_init<VkPipelineRasterizationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.lineWidth = 1.0f;
  // depthClampEnable stays false: oblique near-plane clipping relies on real near clipping.
  auto ms = vk_init<VkPipelineMultisampleStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  ms.rasterizationSamples = desc.samples;
  auto ds = vk_init<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  ds.depthTestEnable = desc.depth_test && desc.depth_format != VK_FORMAT_UNDEFINED;
  ds.depthWriteEnable = desc.depth_write && desc.depth_format != VK_FORMAT_UNDEFINED;
  ds.depthCompareOp = desc.depth_compare;
  VkPipelineColorBlendAttachmentState blend{};
  blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (desc.alpha_blend) {
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE; // alpha "over": a + dst.a * (1 - a)
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  const std::vector<VkPipelineColorBlendAttachmentState> blends(desc.color_formats.size(), blend);
  auto cb = vk_init<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  cb.attachmentCount = static_cast<std::uint32_t>(blends.size());
  cb.pAttachments = blends.data();
  const VkDynamicState dynamic[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                    VK_DYNAMIC_STATE_CULL_MODE, VK_DYNAMIC_STATE_FRONT_FACE};
  auto dyn = vk_init<VkPipelineDynamicStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dyn.dynamicStateCount = 4;
  dyn.pDynamicStates = dynamic;
  auto rendering =
      vk_init<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  rendering.viewMask = desc.view_mask;
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(desc.color_formats.size());
  rendering.pColorAttachmentFormats = desc.color_formats.data();
  rendering.depthAttachmentFormat = desc.depth_format;
  auto ci = vk_init<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  ci.pNext = &rendering;
  ci.stageCount = 2;
  ci.pStages = stages;
  ci.pVertexInputState = &vi;
  ci.pInputAssemblyState = &ia;
  ci.pViewportState = &vp;
  ci.pRasterizationState = &rs;
  ci.pMultisampleState = &ms;
  ci.pDepthStencilState = &ds;
  ci.pColorBlendState = &cb;
  ci.pDynamicState = &dyn;
  ci.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  SNELL_VK_TRY(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline), name);
  return pipeline;
}

namespace {

Result<VkPipelineLayout> create_layout(VkDevice device,
                                       const std::vector<VkDescriptorSetLayout>& set_layouts,
                                       const std::vector<VkPushConstantRange>& push_constants,
                                       const std::string& label) {
  auto ci = vk_init<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  ci.setLayoutCount = static_cast<std::uint32_t>(set_layouts.size());
  ci.pSetLayouts = set_layouts.data();
  ci.pushConstantRangeCount = static_cast<std::uint32_t>(push_constants.size());
  ci.pPushConstantRanges = push_constants.data();
  VkPipelineLayout layout = VK_NULL_HANDLE;
  SNELL_VK_TRY(vkCreatePipelineLayout(device, &ci, nullptr, &layout), label + " layout");
  return layout;
}

/// Destroys the modules when leaving scope (they are only needed during pipeline creation).
struct ModuleScope {
  VkDevice device;
  VkShaderModule modules[2] = {};
  ~ModuleScope() {
    for (VkShaderModule m : modules) {
      if (m != VK_NULL_HANDLE) {
        vkDestroyShaderModule(device, m, nullptr);
      }
    }
  }
};

} // namespace

std::uint32_t vertex_input_locations(Span<const std::uint32_t> spirv) {
  // Instructions follow the 5-word header: word 0 holds (word count << 16) | opcode.
  constexpr std::uint32_t kOpDecorate = 71, kOpVariable = 59, kLocation = 30, kInput = 1;
  std::map<std::uint32_t, std::uint32_t> locations; // id -> Location
  std::set<std::uint32_t> inputs;                   // ids of Input variables
  for (std::size_t i = 5; i < spirv.size();) {
    const std::uint32_t count = spirv[i] >> 16, op = spirv[i] & 0xFFFFu;
    if (count == 0 || i + count > spirv.size()) {
      return ~0u; // not SPIR-V we can read: bind every attribute
    }
    if (op == kOpDecorate && count >= 4 && spirv[i + 2] == kLocation) {
      locations[spirv[i + 1]] = spirv[i + 3];
    } else if (op == kOpVariable && count >= 4 && spirv[i + 3] == kInput) {
      inputs.insert(spirv[i + 2]);
    }
    i += count;
  }
  std::uint32_t mask = 0;
  for (const auto& [id, location] : locations) {
    if (inputs.count(id) != 0 && location < 32) {
      mask |= 1u << location;
    }
  }
  return mask;
}

Result<Pipeline> Pipeline::create(const Context& ctx, const GraphicsPipelineDesc& desc) {
  const std::string label = desc.label != nullptr ? desc.label : "graphics pipeline";
  if (desc.vertex.empty() || desc.fragment.empty()) {
    return fail(ErrorCode::invalid_argument,
                label + ": GraphicsPipelineDesc needs vertex and fragment SPIR-V");
  }
  const VkDevice device = ctx.device();
  Pipeline p;
  p.device_ = device;
  p.bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
  auto layout = create_layout(device, desc.set_layouts, desc.push_constants, label);
  if (!layout) {
    return layout.error();
  }
  p.layout_ = *layout;
  ModuleScope scope{device};
  auto vert = create_shader_module(device, desc.vertex, label + " vertex shader");
  if (!vert) {
    return vert.error();
  }
  scope.modules[0] = *vert;
  auto frag = create_shader_module(device, desc.fragment, label + " fragment shader");
  if (!frag) {
    return frag.error();
  }
  scope.modules[1] = *frag;
  RasterState state = desc.state;
  state.vertex_attributes &= vertex_input_locations(desc.vertex);
  auto pipeline =
      create_graphics_pipeline(device, *vert, *frag, p.layout_, state, label, desc.constants);
  if (!pipeline) {
    return pipeline.error();
  }
  p.pipeline_ = *pipeline;
  return p;
}

Result<Pipeline> Pipeline::create(const Context& ctx, const ComputePipelineDesc& desc) {
  const std::string label = desc.label != nullptr ? desc.label : "compute pipeline";
  if (desc.compute.empty()) {
    return fail(ErrorCode::invalid_argument, label + ": ComputePipelineDesc needs compute SPIR-V");
  }
  const VkDevice device = ctx.device();
  Pipeline p;
  p.device_ = device;
  p.bind_point_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  auto layout = create_layout(device, desc.set_layouts, desc.push_constants, label);
  if (!layout) {
    return layout.error();
  }
  p.layout_ = *layout;
  ModuleScope scope{device};
  auto comp = create_shader_module(device, desc.compute, label + " compute shader");
  if (!comp) {
    return comp.error();
  }
  scope.modules[0] = *comp;
  auto ci = vk_init<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  ci.stage =
      vk_init<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
  ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  ci.stage.module = *comp;
  ci.stage.pName = "main";
  // constant_id i = constants[i], 4 bytes each.
  std::vector<VkSpecializationMapEntry> entries(desc.constants.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    entries[i] = {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(4 * i), 4};
  }
  const VkSpecializationInfo specialization{static_cast<std::uint32_t>(entries.size()),
                                            entries.data(), 4 * desc.constants.size(),
                                            desc.constants.data()};
  ci.stage.pSpecializationInfo = desc.constants.empty() ? nullptr : &specialization;
  ci.layout = p.layout_;
  SNELL_VK_TRY(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline_),
               label);
  return p;
}

Pipeline::Pipeline(Pipeline&& other) noexcept {
  *this = std::move(other);
}

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    bind_point_ = other.bind_point_;
  }
  return *this;
}

Pipeline::~Pipeline() {
  reset();
}

void Pipeline::reset() {
  if (device_ != VK_NULL_HANDLE) {
    vkDestroyPipeline(device_, pipeline_, nullptr);
    vkDestroyPipelineLayout(device_, layout_, nullptr);
  }
  device_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
}

void Pipeline::bind(VkCommandBuffer cmd) const {
  vkCmdBindPipeline(cmd, bind_point_, pipeline_);
}

} // namespace snell

#include "thumbnails.hpp"

#include "viewer_shaders.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace snell::viewer {
namespace {

Error vk_failure(const std::string& what, VkResult result) {
  Error e{ErrorCode::vulkan_error,
          what + " failed (VkResult " + std::to_string(static_cast<int>(result)) + ")"};
  e.vk_result = result;
  return e;
}

struct PushConstants {
  float rect[4];
  float params[4];
};

} // namespace

Result<void> Thumbnails::init(const Context& ctx, VkRenderPass render_pass,
                              std::uint32_t frames_in_flight) {
  ctx_ = &ctx;
  device_ = ctx.device();
  VkDescriptorSetLayoutBinding binding{};
  binding.binding = 0;
  binding.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  binding.descriptorCount = 1;
  binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
  VkDescriptorSetLayoutCreateInfo sli{};
  sli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  sli.bindingCount = 1;
  sli.pBindings = &binding;
  if (VkResult r = vkCreateDescriptorSetLayout(device_, &sli, nullptr, &set_layout_);
      r != VK_SUCCESS) {
    return vk_failure("thumbnail descriptor set layout", r);
  }
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                 sizeof(PushConstants)};
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &set_layout_;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  if (VkResult r = vkCreatePipelineLayout(device_, &pli, nullptr, &layout_); r != VK_SUCCESS) {
    return vk_failure("thumbnail pipeline layout", r);
  }

  VkShaderModule modules[2] = {};
  const std::span<const std::uint32_t> code[2] = {shaders::thumbnail_vert, shaders::thumbnail_frag};
  for (int i = 0; i < 2; ++i) {
    VkShaderModuleCreateInfo mi{};
    mi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    mi.codeSize = code[i].size_bytes();
    mi.pCode = code[i].data();
    if (VkResult r = vkCreateShaderModule(device_, &mi, nullptr, &modules[i]); r != VK_SUCCESS) {
      if (modules[0] != VK_NULL_HANDLE) {
        vkDestroyShaderModule(device_, modules[0], nullptr);
      }
      return vk_failure("thumbnail shader module", r);
    }
  }
  VkPipelineShaderStageCreateInfo stages[2]{};
  for (int i = 0; i < 2; ++i) {
    stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  VkPipelineVertexInputStateCreateInfo vertex_input{};
  vertex_input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  VkPipelineViewportStateCreateInfo viewport{};
  viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{};
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blend.attachmentCount = 1;
  blend.pAttachments = &blend_attachment;
  VkPipelineDepthStencilStateCreateInfo depth{};
  depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{};
  dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkGraphicsPipelineCreateInfo gi{};
  gi.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  gi.stageCount = 2;
  gi.pStages = stages;
  gi.pVertexInputState = &vertex_input;
  gi.pInputAssemblyState = &assembly;
  gi.pViewportState = &viewport;
  gi.pRasterizationState = &raster;
  gi.pMultisampleState = &multisample;
  gi.pDepthStencilState = &depth;
  gi.pColorBlendState = &blend;
  gi.pDynamicState = &dynamic;
  gi.layout = layout_;
  gi.renderPass = render_pass;
  gi.subpass = 0;
  const VkResult created =
      vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &gi, nullptr, &pipeline_);
  vkDestroyShaderModule(device_, modules[0], nullptr);
  vkDestroyShaderModule(device_, modules[1], nullptr);
  if (created != VK_SUCCESS) {
    return vk_failure("thumbnail pipeline", created);
  }

  for (std::uint32_t i = 0; i < frames_in_flight; ++i) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kMaxPerFrame};
    VkDescriptorPoolCreateInfo pi{};
    pi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    pi.maxSets = kMaxPerFrame;
    pi.poolSizeCount = 1;
    pi.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (VkResult r = vkCreateDescriptorPool(device_, &pi, nullptr, &pool); r != VK_SUCCESS) {
      return vk_failure("thumbnail descriptor pool", r);
    }
    pools_.push_back(pool);
  }
  return {};
}

void Thumbnails::begin_frame(std::uint32_t slot, VkCommandBuffer cmd, VkExtent2D extent) {
  slot_ = slot % static_cast<std::uint32_t>(std::max<std::size_t>(pools_.size(), 1));
  cmd_ = cmd;
  extent_ = extent;
  draws_.clear();
  if (!pools_.empty()) {
    vkResetDescriptorPool(device_, pools_[slot_], 0); // the slot's last frame has completed
  }
}

bool Thumbnails::image(const DebugTarget& target, float width, float height) {
  const ImVec2 pos = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(width, height));
  if (!ImGui::IsItemVisible() || target.view == VK_NULL_HANDLE) {
    return true;
  }
  if (pools_.empty() || draws_.size() >= kMaxPerFrame) {
    ImGui::GetWindowDrawList()->AddRect(pos, ImVec2(pos.x + width, pos.y + height),
                                        IM_COL32(128, 128, 128, 255));
    return false;
  }
  VkDescriptorSetAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  ai.descriptorPool = pools_[slot_];
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &set_layout_;
  VkDescriptorSet set = VK_NULL_HANDLE;
  if (vkAllocateDescriptorSets(device_, &ai, &set) != VK_SUCCESS) {
    return false;
  }
  const bool depth = target.kind == DebugKind::depth;
  VkDescriptorImageInfo image_info{};
  image_info.sampler =
      ctx_->sampler(depth ? StandardSampler::nearest_clamp : StandardSampler::linear_clamp);
  image_info.imageView = target.view;
  image_info.imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set;
  write.dstBinding = 0;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &image_info;
  vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);

  auto d = std::make_unique<Draw>();
  d->self = this;
  d->set = set;
  d->depth = depth;
  d->x0 = pos.x;
  d->y0 = pos.y;
  d->x1 = pos.x + width;
  d->y1 = pos.y + height;
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddCallback(&Thumbnails::callback, d.get());
  list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
  draws_.push_back(std::move(d));
  return true;
}

void Thumbnails::callback(const ImDrawList* /*list*/, const ImDrawCmd* cmd) {
  const auto* d = static_cast<const Draw*>(cmd->UserCallbackData);
  d->self->draw(*d, *cmd);
}

void Thumbnails::draw(const Draw& d, const ImDrawCmd& cmd) const {
  // The UI's display size is the framebuffer's (no HiDPI scaling in this viewer: ImGui's
  // FramebufferScale is applied by the caller's extent), so screen pixels are framebuffer pixels.
  const float w = static_cast<float>(extent_.width);
  const float h = static_cast<float>(extent_.height);
  const ImVec2 scale =
      ImGui::GetDrawData() != nullptr ? ImGui::GetDrawData()->FramebufferScale : ImVec2(1.0f, 1.0f);
  const float cx0 = std::clamp(std::max(d.x0, cmd.ClipRect.x) * scale.x, 0.0f, w);
  const float cy0 = std::clamp(std::max(d.y0, cmd.ClipRect.y) * scale.y, 0.0f, h);
  const float cx1 = std::clamp(std::min(d.x1, cmd.ClipRect.z) * scale.x, 0.0f, w);
  const float cy1 = std::clamp(std::min(d.y1, cmd.ClipRect.w) * scale.y, 0.0f, h);
  if (cx1 - cx0 < 1.0f || cy1 - cy0 < 1.0f || w < 1.0f || h < 1.0f) {
    return; // clipped away
  }
  const VkViewport viewport{0.0f, 0.0f, w, h, 0.0f, 1.0f};
  const VkRect2D scissor{
      {static_cast<std::int32_t>(cx0), static_cast<std::int32_t>(cy0)},
      {static_cast<std::uint32_t>(cx1 - cx0), static_cast<std::uint32_t>(cy1 - cy0)}};
  PushConstants pc{};
  pc.rect[0] = d.x0 * scale.x / w * 2.0f - 1.0f;
  pc.rect[1] = d.y0 * scale.y / h * 2.0f - 1.0f;
  pc.rect[2] = d.x1 * scale.x / w * 2.0f - 1.0f;
  pc.rect[3] = d.y1 * scale.y / h * 2.0f - 1.0f;
  pc.params[0] = d.depth ? 1.0f : 0.0f;
  vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &d.set, 0, nullptr);
  vkCmdPushConstants(cmd_, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(PushConstants), &pc);
  vkCmdSetViewport(cmd_, 0, 1, &viewport);
  vkCmdSetScissor(cmd_, 0, 1, &scissor);
  vkCmdDraw(cmd_, 4, 1, 0, 0);
}

Thumbnails::~Thumbnails() {
  if (device_ == VK_NULL_HANDLE) {
    return;
  }
  for (VkDescriptorPool pool : pools_) {
    vkDestroyDescriptorPool(device_, pool, nullptr);
  }
  vkDestroyPipeline(device_, pipeline_, nullptr);
  vkDestroyPipelineLayout(device_, layout_, nullptr);
  vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
}

} // namespace snell::viewer

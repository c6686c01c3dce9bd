#include "debug_overlay.hpp"

#include <snell/pipeline.hpp>

#include "snell_runtime_shaders.hpp"
#include "vk_util.hpp"

#include <glm/vec4.hpp>

#include <utility>

namespace snell::detail {

Result<DebugOverlay> DebugOverlay::create(const Context::Impl& ctx, VkFormat color_format) {
  DebugOverlay o;
  o.ctx_ = &ctx;
  const VkDevice d = ctx.device;
  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                             VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  auto lci =
      vk_init<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  lci.bindingCount = 1;
  lci.pBindings = &binding;
  SNELL_VK_TRY(vkCreateDescriptorSetLayout(d, &lci, nullptr, &o.set_layout_), "debug overlay");
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, 32};
  auto pli = vk_init<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &o.set_layout_;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  SNELL_VK_TRY(vkCreatePipelineLayout(d, &pli, nullptr, &o.layout_), "debug overlay");
  auto vert = create_shader_module(d, shaders::blit_vert, "blit.vert");
  auto frag = create_shader_module(d, shaders::blit_frag, "blit.frag");
  if (!vert || !frag) {
    if (vert) {
      vkDestroyShaderModule(d, *vert, nullptr);
    }
    if (frag) {
      vkDestroyShaderModule(d, *frag, nullptr);
    }
    return !vert ? vert.error() : frag.error();
  }
  GraphicsPipelineDesc desc;
  desc.vertex = *vert;
  desc.fragment = *frag;
  desc.layout = o.layout_;
  desc.color_format = color_format;
  desc.vertex_input = false;
  desc.depth_test = false;
  desc.depth_write = false;
  desc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  auto pipeline = create_graphics_pipeline(d, desc, "debug overlay pipeline");
  vkDestroyShaderModule(d, *vert, nullptr);
  vkDestroyShaderModule(d, *frag, nullptr);
  if (!pipeline) {
    return pipeline.error();
  }
  o.pipeline_ = *pipeline;
  auto sci = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  sci.magFilter = sci.minFilter = VK_FILTER_LINEAR;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  SNELL_VK_TRY(vkCreateSampler(d, &sci, nullptr, &o.sampler_), "debug overlay sampler");
  sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
  SNELL_VK_TRY(vkCreateSampler(d, &sci, nullptr, &o.depth_sampler_), "debug overlay sampler");
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  auto dpci = vk_init<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  dpci.maxSets = 4;
  dpci.poolSizeCount = 1;
  dpci.pPoolSizes = &size;
  SNELL_VK_TRY(vkCreateDescriptorPool(d, &dpci, nullptr, &o.pool_), "debug overlay pool");
  const VkDescriptorSetLayout layouts[4] = {o.set_layout_, o.set_layout_, o.set_layout_,
                                            o.set_layout_};
  auto ai = vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  ai.descriptorPool = o.pool_;
  ai.descriptorSetCount = 4;
  ai.pSetLayouts = layouts;
  SNELL_VK_TRY(vkAllocateDescriptorSets(d, &ai, o.sets_), "debug overlay sets");
  return o;
}

DebugOverlay::DebugOverlay(DebugOverlay&& o) noexcept {
  swap(o);
}
DebugOverlay& DebugOverlay::operator=(DebugOverlay&& o) noexcept {
  DebugOverlay moved(std::move(o));
  swap(moved);
  return *this;
}
void DebugOverlay::swap(DebugOverlay& o) noexcept {
  std::swap(ctx_, o.ctx_);
  std::swap(set_layout_, o.set_layout_);
  std::swap(layout_, o.layout_);
  std::swap(pipeline_, o.pipeline_);
  std::swap(sampler_, o.sampler_);
  std::swap(depth_sampler_, o.depth_sampler_);
  std::swap(pool_, o.pool_);
  std::swap(sets_, o.sets_);
}
DebugOverlay::~DebugOverlay() {
  if (ctx_ == nullptr) {
    return;
  }
  const VkDevice d = ctx_->device;
  vkDestroyDescriptorPool(d, pool_, nullptr);
  vkDestroySampler(d, sampler_, nullptr);
  vkDestroySampler(d, depth_sampler_, nullptr);
  vkDestroyPipeline(d, pipeline_, nullptr);
  vkDestroyPipelineLayout(d, layout_, nullptr);
  vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
}

void DebugOverlay::draw(VkCommandBuffer cmd, std::span<const DebugTarget> targets,
                        std::uint32_t width, std::uint32_t height) {
  (void)width;
  (void)height;
  // Corners clockwise from the top-left, in NDC (y down with a standard viewport), each thumbnail
  // a quarter of the output with a small margin.
  const glm::vec4 rects[4] = {{-0.98f, -0.98f, -0.48f, -0.48f},
                              {0.48f, -0.98f, 0.98f, -0.48f},
                              {0.48f, 0.48f, 0.98f, 0.98f},
                              {-0.98f, 0.48f, -0.48f, 0.98f}};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
  vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
  for (std::size_t i = 0; i < targets.size() && i < 4; ++i) {
    const VkDescriptorImageInfo image{targets[i].depth ? depth_sampler_ : sampler_, targets[i].view,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    auto write = vk_init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = sets_[i];
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &image;
    // The sets are only used by this one-at-a-time frame (the caller waits on every frame), so
    // updating them while recording the next frame is safe.
    vkUpdateDescriptorSets(ctx_->device, 1, &write, 0, nullptr);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &sets_[i], 0,
                            nullptr);
    const glm::vec4 push[2] = {rects[i], glm::vec4(targets[i].depth ? 1.0f : 0.0f, 0, 0, 0)};
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), push);
    vkCmdDraw(cmd, 4, 1, 0, 0);
  }
}

} // namespace snell::detail

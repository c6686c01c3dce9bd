#include "debug_overlay.hpp"

#include <snell/pipeline.hpp>

#include "snell_runtime_shaders.hpp"
#include "vk_util.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace snell::detail {

Result<DebugOverlay> DebugOverlay::create(const ContextState& ctx, VkFormat color_format) {
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
  RasterState desc;
  desc.color_formats = {color_format};
  desc.vertex_input = false;
  desc.depth_test = false;
  desc.depth_write = false;
  desc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  auto pipeline =
      create_graphics_pipeline(d, *vert, *frag, o.layout_, desc, "debug overlay pipeline");
  vkDestroyShaderModule(d, *vert, nullptr);
  vkDestroyShaderModule(d, *frag, nullptr);
  if (!pipeline) {
    return pipeline.error();
  }
  o.pipeline_ = *pipeline;
  auto sci = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  sci.magFilter = sci.minFilter = VK_FILTER_LINEAR;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sci.maxLod = VK_LOD_CLAMP_NONE; // mip_level thumbnails pick a level with textureLod
  SNELL_VK_TRY(vkCreateSampler(d, &sci, nullptr, &o.sampler_), "debug overlay sampler");
  sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
  sci.maxLod = 0.0f;
  SNELL_VK_TRY(vkCreateSampler(d, &sci, nullptr, &o.depth_sampler_), "debug overlay sampler");
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kMaxThumbnails};
  auto dpci = vk_init<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  dpci.maxSets = kMaxThumbnails;
  dpci.poolSizeCount = 1;
  dpci.pPoolSizes = &size;
  SNELL_VK_TRY(vkCreateDescriptorPool(d, &dpci, nullptr, &o.pool_), "debug overlay pool");
  VkDescriptorSetLayout layouts[kMaxThumbnails];
  for (VkDescriptorSetLayout& l : layouts) {
    l = o.set_layout_;
  }
  auto ai = vk_init<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  ai.descriptorPool = o.pool_;
  ai.descriptorSetCount = kMaxThumbnails;
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

void DebugOverlay::draw(VkCommandBuffer cmd, Span<const DebugTarget> targets, std::uint32_t width,
                        std::uint32_t height) {
  (void)width;
  (void)height;
  const std::size_t n = std::min<std::size_t>(targets.size(), kMaxThumbnails);
  // Rectangles in NDC (y down with a standard viewport). Up to four: the corners, clockwise
  // from the top-left, a quarter of the output each. More: a grid over the whole output.
  std::vector<glm::vec4> rects;
  if (n <= 4) {
    rects = {{-0.98f, -0.98f, -0.48f, -0.48f},
             {0.48f, -0.98f, 0.98f, -0.48f},
             {0.48f, 0.48f, 0.98f, 0.98f},
             {-0.98f, 0.48f, -0.48f, 0.98f}};
  } else {
    const auto cols = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    const std::size_t rows = (n + cols - 1) / cols;
    const float cw = 2.0f / static_cast<float>(cols);
    const float rh = 2.0f / static_cast<float>(rows);
    for (std::size_t i = 0; i < n; ++i) {
      const float x0 = -1.0f + cw * static_cast<float>(i % cols);
      const float y0 = -1.0f + rh * static_cast<float>(i / cols);
      rects.emplace_back(x0 + 0.01f, y0 + 0.01f, x0 + cw - 0.01f, y0 + rh - 0.01f);
    }
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
  vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
  for (std::size_t i = 0; i < n; ++i) {
    const DebugTarget& t = targets[i];
    if (t.view == VK_NULL_HANDLE) {
      continue;
    }
    const bool depth = t.kind == DebugKind::depth;
    const VkDescriptorImageInfo image{depth ? depth_sampler_ : sampler_, t.view,
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
    // params: x = depth visualisation, y = the mip level shown (a view of all levels).
    const float lod = t.kind == DebugKind::mip_level ? static_cast<float>(t.mip) : 0.0f;
    const glm::vec4 push[2] = {rects[i], glm::vec4(depth ? 1.0f : 0.0f, lod, 0, 0)};
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), push);
    vkCmdDraw(cmd, 4, 1, 0, 0);
  }
}

} // namespace snell::detail

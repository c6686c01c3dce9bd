// DescriptorSets: one set per frame in flight, brought up to date lazily (see the header).
#include <snell/context.hpp>
#include <snell/toolkit/descriptors.hpp>
#include <snell/toolkit/vk_check.hpp>

#include <map>
#include <utility>

namespace snell {

Result<DescriptorSets> DescriptorSets::create(const Context& ctx, const DescriptorSetDesc& desc) {
  const std::string label = desc.label != nullptr ? desc.label : "descriptor set";
  if (desc.bindings.empty()) {
    return fail(ErrorCode::invalid_argument, label + ": DescriptorSetDesc::bindings is empty");
  }
  if (desc.frames_in_flight < 1 || desc.frames_in_flight > 16) {
    return fail(ErrorCode::invalid_argument, label + ": DescriptorSetDesc::frames_in_flight = " +
                                                 std::to_string(desc.frames_in_flight) +
                                                 " is outside [1, 16]");
  }
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  std::map<VkDescriptorType, std::uint32_t> counts;
  for (const DescriptorBinding& b : desc.bindings) {
    if (b.count == 0) {
      return fail(ErrorCode::invalid_argument,
                  label + ": binding " + std::to_string(b.binding) + " has count 0");
    }
    bindings.push_back({b.binding, b.type, b.count, b.stages, nullptr});
    counts[b.type] += b.count * desc.frames_in_flight;
  }
  DescriptorSets s;
  s.device_ = ctx.device();
  s.label_ = label;
  s.bindings_ = desc.bindings;
  auto lci = vk_struct<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  lci.bindingCount = static_cast<std::uint32_t>(bindings.size());
  lci.pBindings = bindings.data();
  SNELL_VK_TRY(vkCreateDescriptorSetLayout(s.device_, &lci, nullptr, &s.layout_), label);
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& [type, count] : counts) {
    sizes.push_back({type, count});
  }
  auto pci = vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pci.maxSets = desc.frames_in_flight;
  pci.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  pci.pPoolSizes = sizes.data();
  SNELL_VK_TRY(vkCreateDescriptorPool(s.device_, &pci, nullptr, &s.pool_), label + " pool");
  const std::vector<VkDescriptorSetLayout> layouts(desc.frames_in_flight, s.layout_);
  s.sets_.resize(desc.frames_in_flight);
  s.applied_.assign(desc.frames_in_flight, 0);
  auto ai = vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  ai.descriptorPool = s.pool_;
  ai.descriptorSetCount = desc.frames_in_flight;
  ai.pSetLayouts = layouts.data();
  SNELL_VK_TRY(vkAllocateDescriptorSets(s.device_, &ai, s.sets_.data()), label + " sets");
  return s;
}

DescriptorSets::DescriptorSets(DescriptorSets&& other) noexcept {
  *this = std::move(other);
}

DescriptorSets& DescriptorSets::operator=(DescriptorSets&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    bindings_ = std::move(other.bindings_);
    sets_ = std::move(other.sets_);
    applied_ = std::move(other.applied_);
    writes_ = std::move(other.writes_);
    version_ = other.version_;
    label_ = std::move(other.label_);
  }
  return *this;
}

DescriptorSets::~DescriptorSets() {
  reset();
}

void DescriptorSets::reset() {
  if (device_ != VK_NULL_HANDLE) {
    vkDestroyDescriptorPool(device_, pool_, nullptr); // frees the sets
    vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
  }
  device_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  sets_.clear();
}

void DescriptorSets::store(const Write& write) {
  for (Write& w : writes_) {
    if (w.binding == write.binding && w.element == write.element) {
      w = write;
      ++version_;
      return;
    }
  }
  writes_.push_back(write);
  ++version_;
}

void DescriptorSets::set_buffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize offset,
                                VkDeviceSize range, std::uint32_t element) {
  Write w;
  w.binding = binding;
  w.element = element;
  w.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  for (const DescriptorBinding& b : bindings_) {
    if (b.binding == binding) {
      w.type = b.type;
    }
  }
  w.buffer = {buffer, offset, range};
  store(w);
}

void DescriptorSets::set_image(std::uint32_t binding, VkImageView view, VkSampler sampler,
                               VkImageLayout layout, std::uint32_t element) {
  Write w;
  w.binding = binding;
  w.element = element;
  w.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  for (const DescriptorBinding& b : bindings_) {
    if (b.binding == binding) {
      w.type = b.type;
    }
  }
  w.image = {sampler, view, layout};
  store(w);
}

VkDescriptorSet DescriptorSets::acquire(std::uint64_t frame_index) {
  if (sets_.empty()) {
    return VK_NULL_HANDLE;
  }
  const std::size_t slot = static_cast<std::size_t>(frame_index % sets_.size());
  if (applied_[slot] != version_) {
    // This slot's previous frame (frame_index - frames_in_flight) has completed: the host waited
    // for it before recording this frame, so the set may be rewritten now.
    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(writes_.size());
    for (const Write& w : writes_) {
      auto vw = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
      vw.dstSet = sets_[slot];
      vw.dstBinding = w.binding;
      vw.dstArrayElement = w.element;
      vw.descriptorCount = 1;
      vw.descriptorType = w.type;
      const bool image = w.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER ||
                         w.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ||
                         w.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      if (image) {
        vw.pImageInfo = &w.image;
      } else {
        vw.pBufferInfo = &w.buffer;
      }
      writes.push_back(vw);
    }
    vkUpdateDescriptorSets(device_, static_cast<std::uint32_t>(writes.size()), writes.data(), 0,
                           nullptr);
    applied_[slot] = version_;
  }
  return sets_[slot];
}

void DescriptorSets::bind(VkCommandBuffer cmd, VkPipelineBindPoint bind_point,
                          VkPipelineLayout layout, std::uint64_t frame_index,
                          const std::uint32_t* dynamic_offsets, std::uint32_t dynamic_offset_count,
                          std::uint32_t set_index) {
  const VkDescriptorSet set = acquire(frame_index);
  vkCmdBindDescriptorSets(cmd, bind_point, layout, set_index, 1, &set, dynamic_offset_count,
                          dynamic_offsets);
}

Result<void> create_surface_bindings(const Context& ctx, const SurfaceBindingsDesc& desc,
                                     UniformRing& ring, DescriptorSets& sets) {
  auto made_ring = UniformRing::create(ctx, {.block_size = desc.block_size,
                                             .frames_in_flight = desc.frames_in_flight,
                                             .label = desc.label});
  if (!made_ring) {
    return made_ring.error();
  }
  DescriptorSetDesc sd;
  sd.bindings.push_back({.binding = 0,
                         .type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                         .stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT});
  for (std::uint32_t i = 1; i <= desc.images; ++i) {
    sd.bindings.push_back({.binding = i});
  }
  sd.bindings.insert(sd.bindings.end(), desc.extra.begin(), desc.extra.end());
  sd.frames_in_flight = desc.frames_in_flight;
  sd.label = desc.label;
  auto made_sets = DescriptorSets::create(ctx, sd);
  if (!made_sets) {
    return made_sets.error();
  }
  made_sets->set_buffer(0, made_ring->buffer(), 0, made_ring->block_size());
  ring = std::move(*made_ring);
  sets = std::move(*made_sets);
  return {};
}

} // namespace snell

// GPU buffers: one allocation per buffer (the runtime creates few, long-lived buffers).
#include <snell/buffer.hpp>

#include "context_impl.hpp"
#include "runtime_internal.hpp"
#include "vk_util.hpp"

#include <cstring>
#include <utility>

namespace snell {

using detail::vk_init;

Result<Buffer> Buffer::create(const Context& context, const BufferDesc& desc) {
  return create_buffer(*context_state(context), desc);
}

Result<Buffer> create_buffer(const ContextState& ctx, const BufferDesc& desc) {
  const std::string name = desc.debug_name != nullptr ? desc.debug_name : "buffer";
  if (desc.size == 0) {
    return fail(ErrorCode::invalid_argument, name + ": BufferDesc::size must be > 0");
  }
  if (desc.usage == 0) {
    return fail(ErrorCode::invalid_argument, name + ": BufferDesc::usage must not be 0");
  }
  Buffer b;
  b.ctx_ = &ctx;
  b.size_ = desc.size;
  VkBufferCreateInfo ci = vk_init<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  ci.size = desc.size;
  ci.usage =
      desc.usage | (desc.memory == MemoryUsage::gpu_only ? VK_BUFFER_USAGE_TRANSFER_DST_BIT : 0);
  ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  SNELL_VK_TRY(vkCreateBuffer(ctx.device, &ci, nullptr, &b.buffer_), name);
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(ctx.device, b.buffer_, &req);
  VkMemoryPropertyFlags props = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  if (desc.memory != MemoryUsage::gpu_only) {
    props = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  }
  auto type = ctx.find_memory_type(
      req.memoryTypeBits,
      desc.memory == MemoryUsage::readback ? props | VK_MEMORY_PROPERTY_HOST_CACHED_BIT : props);
  if (!type) {
    type = ctx.find_memory_type(req.memoryTypeBits, props);
  }
  if (!type) {
    return fail(ErrorCode::out_of_memory, name + ": " + type.error().message);
  }
  VkMemoryAllocateInfo ai = vk_init<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = *type;
  SNELL_VK_TRY(vkAllocateMemory(ctx.device, &ai, nullptr, &b.memory_), name);
  SNELL_VK_TRY(vkBindBufferMemory(ctx.device, b.buffer_, b.memory_, 0), name);
  if (desc.memory != MemoryUsage::gpu_only) {
    SNELL_VK_TRY(vkMapMemory(ctx.device, b.memory_, 0, VK_WHOLE_SIZE, 0, &b.mapped_), name);
  }
  return b;
}

Buffer::Buffer(Buffer&& other) noexcept
    : ctx_(std::exchange(other.ctx_, nullptr)),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)), size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, nullptr)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    ctx_ = std::exchange(other.ctx_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

Buffer::~Buffer() {
  reset();
}

void Buffer::reset() {
  if (ctx_ == nullptr) {
    return;
  }
  if (buffer_ != VK_NULL_HANDLE) {
    vkDestroyBuffer(ctx_->device, buffer_, nullptr);
  }
  if (memory_ != VK_NULL_HANDLE) {
    vkFreeMemory(ctx_->device, memory_, nullptr);
  }
  ctx_ = nullptr;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  size_ = 0;
}

Result<void> Buffer::upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (buffer_ == VK_NULL_HANDLE) {
    return fail(ErrorCode::invalid_argument, "Buffer::upload on an empty buffer");
  }
  if (offset > size_ || bytes > size_ - offset) {
    return fail(ErrorCode::invalid_argument, "Buffer::upload: range [" + std::to_string(offset) +
                                                 ", " + std::to_string(offset + bytes) +
                                                 ") exceeds the buffer size " +
                                                 std::to_string(size_));
  }
  if (bytes == 0) {
    return {};
  }
  if (mapped_ != nullptr) {
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
    return {};
  }
  // Staging path: a temporary host buffer and a blocking copy (uploads happen at load time).
  auto staging = create_buffer(*ctx_, BufferDesc{.size = bytes,
                                                 .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                 .memory = MemoryUsage::upload,
                                                 .debug_name = "staging"});
  if (!staging) {
    return staging.error();
  }
  std::memcpy(staging->mapped(), data, bytes);
  const VkBuffer dst = buffer_;
  return ctx_->submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, offset, bytes};
    vkCmdCopyBuffer(cmd, staging->handle(), dst, 1, &region);
  });
}

} // namespace snell

// Snell runtime: GPU buffers (RAII, move-only).
#pragma once

#include <snell/context.hpp>

#include <cstddef>
#include <cstdint>

namespace snell {

/// Where a buffer lives.
enum class MemoryUsage : std::uint8_t {
  gpu_only, ///< Device-local; filled with Buffer::upload (through a staging buffer).
  upload,   ///< Host-visible, coherent, persistently mapped: CPU writes each frame.
  readback, ///< Host-visible, coherent (cached when available): the GPU writes, CPU reads.
};

/// Parameters of Buffer::create.
struct BufferDesc {
  VkDeviceSize size = 0;        ///< Bytes, > 0. No default size: 0 is rejected.
  VkBufferUsageFlags usage = 0; ///< Vulkan usage bits, != 0. TRANSFER_DST is added for gpu_only.
  MemoryUsage memory = MemoryUsage::gpu_only; ///< Default gpu_only.
  const char* debug_name = "buffer";          ///< Used in error messages. Default "buffer".
};

/// A VkBuffer with its own memory. Must not outlive the Context it was created from.
class Buffer {
public:
  /// Creates the buffer. Errors: invalid_argument (size 0, no usage), out_of_memory, vulkan_error.
  [[nodiscard]] static Result<Buffer> create(const Context& ctx, const BufferDesc& desc);

  Buffer() = default;
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer();

  /// Copies `bytes` bytes to offset `offset`: directly when mapped, else through a staging
  /// buffer and a blocking transfer. Errors: invalid_argument when the range exceeds the size.
  [[nodiscard]] Result<void> upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);

  [[nodiscard]] VkBuffer handle() const { return buffer_; }
  [[nodiscard]] VkDeviceSize size() const { return size_; }
  /// Host pointer for upload/readback buffers, nullptr for gpu_only.
  [[nodiscard]] void* mapped() const { return mapped_; }
  [[nodiscard]] explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

private:
  friend Result<Buffer> create_buffer(const ContextState& ctx, const BufferDesc& desc);
  void reset();
  const ContextState* ctx_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

} // namespace snell

// Snell plugin toolkit: per-frame uniform blocks in one persistently mapped buffer, bound as a
// dynamic uniform buffer. The ring has one region per frame in flight, and blocks are aligned
// to the device's minUniformBufferOffsetAlignment, so a frame never overwrites a block that an
// earlier frame still reads.
#pragma once

#include <snell/buffer.hpp>
#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace snell {

/// Parameters of UniformRing::create.
struct UniformRingDesc {
  VkDeviceSize block_size = 0;        ///< Bytes of one block (the std140 struct), > 0. Required.
  std::uint32_t blocks_per_frame = 1; ///< Blocks one frame may push, 1..4096. Default 1.
  /// Frames the host may have in flight (EffectCreateInfo::frames_in_flight), 1..16. Default 2.
  std::uint32_t frames_in_flight = 2;
  const char* label = "uniform ring"; ///< Names the ring in errors. Default "uniform ring".
};

/// A ring of uniform blocks (RAII, move-only). Bind buffer() with range block_size() as
/// VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC and pass push()'s offset as the dynamic offset.
class UniformRing {
public:
  /// Errors: invalid_argument naming the field, out_of_memory.
  [[nodiscard]] static Result<UniformRing> create(const Context& ctx, const UniformRingDesc& desc);

  /// Copies `bytes` (<= block_size) into the next free block of frame `frame_index` and returns
  /// its dynamic offset. Errors: invalid_argument (too many bytes), limit_exceeded (more than
  /// blocks_per_frame pushes in one frame).
  [[nodiscard]] Result<std::uint32_t> push(std::uint64_t frame_index, const void* data,
                                           VkDeviceSize bytes);
  /// push() of one struct.
  template <class T>
  [[nodiscard]] Result<std::uint32_t> push(std::uint64_t frame_index, const T& block) {
    return push(frame_index, &block, sizeof(T));
  }

  [[nodiscard]] VkBuffer buffer() const { return buffer_.handle(); }
  /// The descriptor range: the block size as given.
  [[nodiscard]] VkDeviceSize block_size() const { return block_size_; }
  /// Distance between blocks: block_size rounded up to minUniformBufferOffsetAlignment.
  [[nodiscard]] VkDeviceSize stride() const { return stride_; }
  [[nodiscard]] explicit operator bool() const { return static_cast<bool>(buffer_); }

private:
  Buffer buffer_;
  VkDeviceSize block_size_ = 0, stride_ = 0;
  std::uint32_t blocks_per_frame_ = 1, frames_in_flight_ = 2;
  std::uint64_t current_frame_ = ~0ull;
  std::uint32_t used_ = 0;
  std::string label_;
};

} // namespace snell

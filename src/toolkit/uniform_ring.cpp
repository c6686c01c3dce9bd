// UniformRing: frames_in_flight regions of blocks_per_frame aligned blocks each.
#include <snell/context.hpp>
#include <snell/toolkit/uniform_ring.hpp>

#include <algorithm>
#include <cstring>

namespace snell {

Result<UniformRing> UniformRing::create(const Context& ctx, const UniformRingDesc& desc) {
  const std::string label = desc.label != nullptr ? desc.label : "uniform ring";
  if (desc.block_size == 0) {
    return fail(ErrorCode::invalid_argument, label + ": UniformRingDesc::block_size is 0");
  }
  if (desc.blocks_per_frame < 1 || desc.blocks_per_frame > 4096) {
    return fail(ErrorCode::invalid_argument, label + ": UniformRingDesc::blocks_per_frame = " +
                                                 std::to_string(desc.blocks_per_frame) +
                                                 " is outside [1, 4096]");
  }
  if (desc.frames_in_flight < 1 || desc.frames_in_flight > 16) {
    return fail(ErrorCode::invalid_argument, label + ": UniformRingDesc::frames_in_flight = " +
                                                 std::to_string(desc.frames_in_flight) +
                                                 " is outside [1, 16]");
  }
  const VkDeviceSize align =
      std::max<VkDeviceSize>(1, ctx.limits().minUniformBufferOffsetAlignment);
  UniformRing ring;
  ring.block_size_ = desc.block_size;
  ring.stride_ = (desc.block_size + align - 1) / align * align;
  ring.blocks_per_frame_ = desc.blocks_per_frame;
  ring.frames_in_flight_ = desc.frames_in_flight;
  ring.label_ = label;
  auto buffer = Buffer::create(
      ctx, BufferDesc{.size = ring.stride_ * desc.blocks_per_frame * desc.frames_in_flight,
                      .usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                      .memory = MemoryUsage::upload,
                      .debug_name = desc.label});
  if (!buffer) {
    return buffer.error();
  }
  ring.buffer_ = std::move(*buffer);
  return ring;
}

Result<std::uint32_t> UniformRing::push(std::uint64_t frame_index, const void* data,
                                        VkDeviceSize bytes) {
  if (bytes > block_size_) {
    return fail(ErrorCode::invalid_argument, label_ + ": a block of " + std::to_string(bytes) +
                                                 " bytes exceeds block_size " +
                                                 std::to_string(block_size_));
  }
  if (frame_index != current_frame_) {
    current_frame_ = frame_index;
    used_ = 0;
  }
  if (used_ >= blocks_per_frame_) {
    return fail(ErrorCode::limit_exceeded,
                label_ + ": more than blocks_per_frame = " + std::to_string(blocks_per_frame_) +
                    " pushes in frame " + std::to_string(frame_index));
  }
  const VkDeviceSize slot = frame_index % frames_in_flight_;
  const VkDeviceSize offset = (slot * blocks_per_frame_ + used_) * stride_;
  ++used_;
  std::memcpy(static_cast<char*>(buffer_.mapped()) + offset, data, static_cast<std::size_t>(bytes));
  return static_cast<std::uint32_t>(offset);
}

} // namespace snell

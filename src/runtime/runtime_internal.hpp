// Internal: runtime functions on the context's state, for objects that keep only that (the
// public API takes a Context).
#pragma once

#include <snell/buffer.hpp>
#include <snell/images.hpp>
#include <snell/readback.hpp>

#include "context_impl.hpp"

namespace snell {

/// Buffer::create on the context's state (staging buffers of other resources).
Result<Buffer> create_buffer(const ContextState& ctx, const BufferDesc& desc);

/// RenderTarget::create whose initial clear (to the samplable state) is recorded into
/// `clear_into` when it is not null, instead of a blocking submit: for targets made while a
/// command buffer is being recorded (a snapshot that follows the host's extent).
Result<RenderTarget> create_render_target(const Context& ctx, const RenderTargetDesc& desc,
                                          VkCommandBuffer clear_into);

namespace detail {
/// read_rgba8 / read_float on the context's state.
Result<Image> read_rgba8(const ContextState& ctx, const RenderTarget& target, std::uint32_t level);
Result<FloatImage> read_float(const ContextState& ctx, const RenderTarget& target,
                              std::uint32_t level);
} // namespace detail

} // namespace snell

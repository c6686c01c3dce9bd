// Sampled 2D textures (uploaded once, mips generated on the GPU) and samplers.
#include <snell/buffer.hpp>
#include <snell/images.hpp>

#include "barriers.hpp"
#include "image_alloc.hpp"
#include "runtime_internal.hpp"
#include "vk_util.hpp"

#include "../scene/image_header.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

namespace snell {

using detail::vk_init;

using detail::ImageBarrier;

Result<Texture2D> Texture2D::create(const Context& context, const Image& image, bool mips) {
  const ContextState& ctx = *context_state(context);
  const std::string name = "texture '" + image.name + "'";
  if (auto r = detail::check_extent(ctx, name, image.width, image.height); !r) {
    return r.error();
  }
  const VkDeviceSize bytes = VkDeviceSize{image.width} * image.height * 4;
  if (image.rgba8.size() != bytes) {
    return fail(ErrorCode::invalid_argument,
                name + ": rgba8 holds " + std::to_string(image.rgba8.size()) + " bytes, expected " +
                    std::to_string(bytes) + " for " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " RGBA8");
  }
  Texture2D t;
  t.ctx_ = &ctx;
  t.width_ = image.width;
  t.height_ = image.height;
  t.mips_ = mips ? full_mip_count(image.width, image.height) : 1;
  const VkFormat format = image.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  VkImageCreateInfo ci = vk_init<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  ci.imageType = VK_IMAGE_TYPE_2D;
  ci.format = format;
  ci.extent = {image.width, image.height, 1};
  ci.mipLevels = t.mips_;
  ci.arrayLayers = 1;
  ci.samples = VK_SAMPLE_COUNT_1_BIT;
  ci.tiling = VK_IMAGE_TILING_OPTIMAL;
  ci.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
             VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (auto r = detail::create_image(ctx, ci, t.image_, t.memory_, name); !r) {
    return r.error();
  }
  auto view = detail::create_view(ctx, t.image_, VK_IMAGE_VIEW_TYPE_2D, format,
                                  VK_IMAGE_ASPECT_COLOR_BIT, 0, t.mips_, 0, 1, name);
  if (!view) {
    return view.error();
  }
  t.view_ = *view;
  auto staging = create_buffer(ctx, BufferDesc{.size = bytes,
                                               .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                               .memory = MemoryUsage::upload,
                                               .debug_name = "staging"});
  if (!staging) {
    return staging.error();
  }
  std::memcpy(staging->mapped(), image.rgba8.data(), bytes);
  const VkImage img = t.image_;
  const std::uint32_t levels = t.mips_;
  auto r = ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    detail::barrier(cmd,
                    ImageBarrier{img, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1,
                                 VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                 VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                                 VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.width, image.height, 1};
    vkCmdCopyBufferToImage(cmd, staging->handle(), img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region);
    detail::generate_mips(cmd, img, image.width, image.height, levels, 1,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
  });
  if (!r) {
    return r.error();
  }
  return t;
}

Result<Texture2D> Texture2D::load(const Context& ctx, const std::filesystem::path& file, bool srgb,
                                  bool mips) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) {
    return fail(ErrorCode::file_not_found, file.string() + ": no such image file");
  }
  if (std::filesystem::is_directory(status)) {
    return fail(ErrorCode::file_not_found,
                file.string() + ": is a folder; expected an image file (PNG, JPEG, ...)");
  }
  if (!std::filesystem::is_regular_file(status)) {
    return fail(ErrorCode::file_not_found, file.string() + ": not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  constexpr std::uintmax_t kMaxBytes = std::uintmax_t{256} << 20;
  if (ec || size == 0 || size > kMaxBytes) {
    return fail(size == 0 || ec ? ErrorCode::parse_error : ErrorCode::limit_exceeded,
                file.string() + ": image file size " + std::to_string(size) +
                    " bytes is outside 1.." + std::to_string(kMaxBytes));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    return fail(ErrorCode::file_not_found, file.string() + ": cannot open the image file");
  }
  std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size))) {
    return fail(ErrorCode::io_error, file.string() + ": read failed");
  }
  const auto limit_text = [&](std::uint64_t w, std::uint64_t h, const char* format) {
    return file.string() + ": " + format + " image is " + std::to_string(w) + "x" +
           std::to_string(h) + " pixels; each side must be in 1.." +
           std::to_string(kMaxImageDimension);
  };
  // The size the header claims first: stb_image cannot describe an image it would not decode
  // (over 2^30 bytes) and would report "unknown image type".
  if (const auto header = detail::read_image_header(bytes.data(), bytes.size());
      header && (header->width > kMaxImageDimension || header->height > kMaxImageDimension)) {
    return fail(ErrorCode::limit_exceeded,
                limit_text(header->width, header->height, header->format));
  }
  int w = 0, h = 0, comp = 0;
  if (stbi_info_from_memory(bytes.data(), static_cast<int>(size), &w, &h, &comp) == 0) {
    return fail(ErrorCode::parse_error,
                file.string() + ": not a decodable image (" + stbi_failure_reason() + ")");
  }
  if (w <= 0 || h <= 0 || static_cast<std::uint32_t>(w) > kMaxImageDimension ||
      static_cast<std::uint32_t>(h) > kMaxImageDimension) {
    return fail(ErrorCode::limit_exceeded,
                limit_text(static_cast<std::uint64_t>(std::max(w, 0)),
                           static_cast<std::uint64_t>(std::max(h, 0)), "the"));
  }
  unsigned char* pixels =
      stbi_load_from_memory(bytes.data(), static_cast<int>(size), &w, &h, &comp, 4);
  if (pixels == nullptr) {
    return fail(ErrorCode::parse_error,
                file.string() + ": decoding failed (" + stbi_failure_reason() + ")");
  }
  Image image;
  image.name = file.string();
  image.width = static_cast<std::uint32_t>(w);
  image.height = static_cast<std::uint32_t>(h);
  image.srgb = srgb;
  image.rgba8.assign(pixels, pixels + std::size_t{image.width} * image.height * 4);
  stbi_image_free(pixels);
  return create(ctx, image, mips);
}

Texture2D::Texture2D(Texture2D&& other) noexcept {
  swap(other);
}
Texture2D& Texture2D::operator=(Texture2D&& other) noexcept {
  Texture2D moved(std::move(other));
  swap(moved);
  return *this;
}
Texture2D::~Texture2D() {
  reset();
}
void Texture2D::swap(Texture2D& o) noexcept {
  std::swap(ctx_, o.ctx_);
  std::swap(image_, o.image_);
  std::swap(memory_, o.memory_);
  std::swap(view_, o.view_);
  std::swap(width_, o.width_);
  std::swap(height_, o.height_);
  std::swap(mips_, o.mips_);
}
void Texture2D::reset() {
  detail::destroy(ctx_, view_);
  detail::destroy(ctx_, image_, memory_);
  ctx_ = nullptr;
}

Result<Sampler> Sampler::create(const Context& context, const SamplerDesc& desc) {
  const ContextState& ctx = *context_state(context);
  if (!(desc.max_anisotropy >= 1.0f)) {
    return fail(ErrorCode::invalid_argument, "SamplerDesc::max_anisotropy must be >= 1, got " +
                                                 std::to_string(desc.max_anisotropy));
  }
  VkSamplerCreateInfo ci = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  ci.magFilter = desc.linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  ci.minFilter = ci.magFilter;
  ci.mipmapMode = desc.linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  const VkSamplerAddressMode mode =
      desc.address == AddressMode::repeat            ? VK_SAMPLER_ADDRESS_MODE_REPEAT
      : desc.address == AddressMode::mirrored_repeat ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                                     : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  ci.addressModeU = ci.addressModeV = ci.addressModeW = mode;
  ci.maxLod = desc.mipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(ctx.physical_device, &features);
  // Only created contexts are known to have enabled anisotropy; adopted ones stay off.
  if (desc.max_anisotropy > 1.0f && features.samplerAnisotropy && ctx.owns) {
    ci.anisotropyEnable = VK_TRUE;
    ci.maxAnisotropy = std::min(desc.max_anisotropy, ctx.limits.maxSamplerAnisotropy);
  }
  Sampler s;
  s.ctx_ = &ctx;
  SNELL_VK_TRY(vkCreateSampler(ctx.device, &ci, nullptr, &s.sampler_), "sampler");
  return s;
}
Sampler::Sampler(Sampler&& other) noexcept {
  swap(other);
}
Sampler& Sampler::operator=(Sampler&& other) noexcept {
  Sampler moved(std::move(other));
  swap(moved);
  return *this;
}
Sampler::~Sampler() {
  if (ctx_ != nullptr && sampler_ != VK_NULL_HANDLE) {
    vkDestroySampler(ctx_->device, sampler_, nullptr);
  }
}
void Sampler::swap(Sampler& o) noexcept {
  std::swap(ctx_, o.ctx_);
  std::swap(sampler_, o.sampler_);
}

} // namespace snell

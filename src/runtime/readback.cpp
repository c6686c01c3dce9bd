// Readback of targets to the CPU (copy to a host buffer, blocking) and PNG output.
#include <snell/buffer.hpp>
#include <snell/output_file.hpp>
#include <snell/readback.hpp>

#include "barriers.hpp"
#include "context_impl.hpp"
#include "runtime_internal.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

namespace snell {
namespace {

using detail::ImageBarrier;

/// Copies one subresource (in SHADER_READ_ONLY_OPTIMAL) into a host buffer and back.
Result<std::vector<std::uint8_t>> read_subresource(const ContextState& ctx, VkImage image,
                                                   VkImageAspectFlags aspect, std::uint32_t width,
                                                   std::uint32_t height, std::uint32_t level,
                                                   std::uint32_t layer, std::uint32_t texel_bytes) {
  const VkDeviceSize bytes = VkDeviceSize{width} * height * texel_bytes;
  auto buffer = create_buffer(ctx, BufferDesc{.size = bytes,
                                              .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                              .memory = MemoryUsage::readback,
                                              .debug_name = "readback"});
  if (!buffer) {
    return buffer.error();
  }
  auto r = ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    detail::barrier(cmd,
                    ImageBarrier{image, aspect, level, 1, layer, 1,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                 VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                                 VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT});
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, level, layer, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer->handle(), 1,
                           &region);
    detail::barrier(
        cmd, ImageBarrier{image, aspect, level, 1, layer, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_NONE, detail::kReadStages, detail::kReadAccess});
  });
  if (!r) {
    return r.error();
  }
  std::vector<std::uint8_t> out(bytes);
  std::memcpy(out.data(), buffer->mapped(), bytes);
  return out;
}

float half_to_float(std::uint16_t h) {
  const std::uint32_t sign = (h >> 15) & 1u, exp = (h >> 10) & 0x1Fu, mant = h & 0x3FFu;
  float v;
  if (exp == 0) {
    v = std::ldexp(static_cast<float>(mant), -24);
  } else if (exp == 31) {
    v = mant != 0 ? NAN : INFINITY;
  } else {
    v = std::ldexp(static_cast<float>(mant | 0x400u), static_cast<int>(exp) - 25);
  }
  return sign != 0 ? -v : v;
}

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float linear_to_srgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

std::uint32_t level_extent(std::uint32_t size, std::uint32_t level) {
  return std::max(1u, size >> level);
}

Result<FloatImage> to_float(const std::vector<std::uint8_t>& bytes, ColorFormat format,
                            std::uint32_t w, std::uint32_t h) {
  FloatImage out{w, h, std::vector<float>(std::size_t{w} * h * 4)};
  for (std::size_t i = 0; i < out.rgba.size(); ++i) {
    if (format == ColorFormat::rgba16_float) {
      std::uint16_t v;
      std::memcpy(&v, bytes.data() + 2 * i, 2);
      out.rgba[i] = half_to_float(v);
    } else {
      const float c = bytes[i] / 255.0f;
      out.rgba[i] = (format == ColorFormat::rgba8_srgb && i % 4 != 3) ? srgb_to_linear(c) : c;
    }
  }
  return out;
}

} // namespace

Result<Image> read_rgba8(const Context& ctx, const RenderTarget& target, std::uint32_t level) {
  return detail::read_rgba8(*context_state(ctx), target, level);
}

Result<FloatImage> read_float(const Context& ctx, const RenderTarget& target, std::uint32_t level) {
  return detail::read_float(*context_state(ctx), target, level);
}

Result<Image> detail::read_rgba8(const ContextState& ctx, const RenderTarget& target,
                                 std::uint32_t level) {
  if (!target || level >= target.mip_levels()) {
    return fail(ErrorCode::invalid_argument, "read_rgba8: level " + std::to_string(level) +
                                                 " out of range (target has " +
                                                 std::to_string(target.mip_levels()) + ")");
  }
  const std::uint32_t w = level_extent(target.width(), level);
  const std::uint32_t h = level_extent(target.height(), level);
  if (target.color_format() == ColorFormat::rgba16_float) {
    auto f = detail::read_float(ctx, target, level);
    if (!f) {
      return f.error();
    }
    return tonemap(*f);
  }
  auto bytes =
      read_subresource(ctx, target.color_image(), VK_IMAGE_ASPECT_COLOR_BIT, w, h, level, 0, 4);
  if (!bytes) {
    return bytes.error();
  }
  Image out;
  out.name = "readback";
  out.width = w;
  out.height = h;
  out.srgb = target.color_format() == ColorFormat::rgba8_srgb;
  out.rgba8 = std::move(*bytes);
  return out;
}

Result<FloatImage> detail::read_float(const ContextState& ctx, const RenderTarget& target,
                                      std::uint32_t level) {
  if (!target || level >= target.mip_levels()) {
    return fail(ErrorCode::invalid_argument, "read_float: level " + std::to_string(level) +
                                                 " out of range (target has " +
                                                 std::to_string(target.mip_levels()) + ")");
  }
  const std::uint32_t w = level_extent(target.width(), level);
  const std::uint32_t h = level_extent(target.height(), level);
  const std::uint32_t texel = target.color_format() == ColorFormat::rgba16_float ? 8 : 4;
  auto bytes =
      read_subresource(ctx, target.color_image(), VK_IMAGE_ASPECT_COLOR_BIT, w, h, level, 0, texel);
  if (!bytes) {
    return bytes.error();
  }
  return to_float(*bytes, target.color_format(), w, h);
}

Result<Image> read_cube_face_rgba8(const Context& ctx, const CubeTarget& target, std::uint32_t face,
                                   std::uint32_t level) {
  if (!target || face >= 6 || level >= target.mip_levels()) {
    return fail(ErrorCode::invalid_argument, "read_cube_face_rgba8: face " + std::to_string(face) +
                                                 " (0..5) or level " + std::to_string(level) +
                                                 " out of range");
  }
  const std::uint32_t s = level_extent(target.size(), level);
  const bool half = target.color_format() == ColorFormat::rgba16_float;
  auto bytes = read_subresource(*context_state(ctx), target.color_image(),
                                VK_IMAGE_ASPECT_COLOR_BIT, s, s, level, face, half ? 8 : 4);
  if (!bytes) {
    return bytes.error();
  }
  if (half) {
    auto f = to_float(*bytes, target.color_format(), s, s);
    return tonemap(*f);
  }
  Image out;
  out.name = "cube face " + std::to_string(face);
  out.width = s;
  out.height = s;
  out.srgb = target.color_format() == ColorFormat::rgba8_srgb;
  out.rgba8 = std::move(*bytes);
  return out;
}

Result<std::vector<float>> read_depth(const Context& ctx, const RenderTarget& target) {
  if (!target || target.depth_image() == VK_NULL_HANDLE) {
    return fail(ErrorCode::invalid_argument, "read_depth: the target has no depth image");
  }
  auto bytes =
      read_subresource(*context_state(ctx), target.depth_image(), VK_IMAGE_ASPECT_DEPTH_BIT,
                       target.width(), target.height(), 0, 0, 4);
  if (!bytes) {
    return bytes.error();
  }
  std::vector<float> out(std::size_t{target.width()} * target.height());
  std::memcpy(out.data(), bytes->data(), out.size() * sizeof(float));
  return out;
}

Result<FloatImage> read_debug_target(const Context& ctx, const DebugTarget& target) {
  if (target.image == VK_NULL_HANDLE || target.width == 0 || target.height == 0) {
    return fail(ErrorCode::invalid_argument,
                "read_debug_target: '" + target.name + "' has no image to read");
  }
  ColorFormat format = ColorFormat::rgba8_unorm;
  switch (target.format) {
  case VK_FORMAT_R8G8B8A8_UNORM:
    break;
  case VK_FORMAT_R8G8B8A8_SRGB:
    format = ColorFormat::rgba8_srgb;
    break;
  case VK_FORMAT_R16G16B16A16_SFLOAT:
    format = ColorFormat::rgba16_float;
    break;
  case VK_FORMAT_D32_SFLOAT: {
    auto bytes = read_subresource(*context_state(ctx), target.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                                  target.width, target.height, target.mip, target.layer, 4);
    if (!bytes) {
      return bytes.error();
    }
    FloatImage out{target.width, target.height,
                   std::vector<float>(std::size_t{target.width} * target.height * 4, 1.0f)};
    for (std::size_t i = 0; i < std::size_t{target.width} * target.height; ++i) {
      std::memcpy(&out.rgba[i * 4], bytes->data() + i * 4, 4);
    }
    return out;
  }
  default:
    return fail(ErrorCode::unsupported, "read_debug_target: '" + target.name +
                                            "' has a format Snell cannot read back (" +
                                            std::to_string(static_cast<int>(target.format)) + ")");
  }
  auto bytes = read_subresource(*context_state(ctx), target.image, VK_IMAGE_ASPECT_COLOR_BIT,
                                target.width, target.height, target.mip, target.layer,
                                format == ColorFormat::rgba16_float ? 8 : 4);
  if (!bytes) {
    return bytes.error();
  }
  return to_float(*bytes, format, target.width, target.height);
}

Image tonemap(const FloatImage& image, float exposure) {
  Image out;
  out.name = "tonemapped";
  out.width = image.width;
  out.height = image.height;
  out.rgba8.resize(image.rgba.size());
  for (std::size_t i = 0; i < image.rgba.size(); ++i) {
    float v = image.rgba[i];
    if (!std::isfinite(v)) {
      v = 0.0f;
    }
    if (i % 4 != 3) {
      v = std::max(0.0f, v * exposure);
      v = linear_to_srgb(v / (1.0f + v));
    }
    out.rgba8[i] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  }
  return out;
}

Result<std::vector<std::uint8_t>> encode_png(const Image& image, const PngOptions& options) {
  const std::size_t pixels = std::size_t{image.width} * image.height;
  if (image.width == 0 || image.height == 0 || image.width > kMaxImageDimension ||
      image.height > kMaxImageDimension || image.rgba8.size() != pixels * 4) {
    return fail(ErrorCode::invalid_argument,
                "encode_png: cannot encode an empty or inconsistent image '" + image.name + "' (" +
                    std::to_string(image.width) + "x" + std::to_string(image.height) + ", " +
                    std::to_string(image.rgba8.size()) + " bytes; each side must be in 1.." +
                    std::to_string(kMaxImageDimension) + " and the bytes width * height * 4)");
  }
  if (options.compression_level < 5 || options.compression_level > 32) {
    return fail(ErrorCode::invalid_argument, "PngOptions::compression_level " +
                                                 std::to_string(options.compression_level) +
                                                 " is outside [5, 32]");
  }
  bool opaque = true;
  for (std::size_t i = 3; i < image.rgba8.size() && opaque; i += 4) {
    opaque = image.rgba8[i] == 255;
  }
  std::vector<std::uint8_t> rgb;
  if (opaque) {
    rgb.resize(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
      std::memcpy(&rgb[i * 3], &image.rgba8[i * 4], 3);
    }
  }
  const int channels = opaque ? 3 : 4;
  std::vector<std::uint8_t> png;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  int ok = 0;
  {
    // stb_image_write takes the level from a global of Snell's own copy of it.
    static std::mutex stb_globals;
    const std::lock_guard lock(stb_globals);
    stbi_write_png_compression_level = options.compression_level;
    stbi_write_force_png_filter = -1;
    ok = stbi_write_png_to_func(
        append, &png, static_cast<int>(image.width), static_cast<int>(image.height), channels,
        opaque ? rgb.data() : image.rgba8.data(), static_cast<int>(image.width) * channels);
  }
  if (ok == 0 || png.empty()) {
    return fail(ErrorCode::out_of_memory,
                "encode_png: out of memory encoding the " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " image '" + image.name + "'");
  }
  return png;
}

Result<void> write_png(const std::filesystem::path& path, const Image& image,
                       const PngOptions& options) {
  auto png = encode_png(image, options);
  if (!png) {
    return fail(png.error().code, path.string() + ": " + png.error().message);
  }
  return write_file(path, png->data(), png->size());
}

} // namespace snell

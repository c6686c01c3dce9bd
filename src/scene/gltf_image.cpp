// Internal: the image decoder of the glTF loader (see gltf_image.hpp).
#include "gltf_image.hpp"

#include "gltf_context.hpp"
#include "gltf_uri.hpp"
#include "image_header.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

namespace snell::detail {
namespace {

std::string describe(const tinygltf::Image& image, int index) {
  std::string text = "image " + std::to_string(index);
  if (!image.name.empty()) {
    text += " '" + clip_for_message(image.name) + "'";
  }
  if (!image.uri.empty()) {
    text += " (URI '" + clip_for_message(image.uri) + "')";
  }
  return text;
}

bool has_prefix(const unsigned char* bytes, int size, const unsigned char* magic, int length) {
  return size >= length && std::memcmp(bytes, magic, static_cast<std::size_t>(length)) == 0;
}

// The PNG without its empty IDAT chunks, or an empty vector when it has none (the common case:
// no copy is needed). stb_image (2022-09 Debian build) copies an empty IDAT chunk with
// memcpy(nullptr, ..., 0) before it has allocated its buffer: harmless in practice, but undefined
// behaviour that the sanitizers report. An empty IDAT chunk carries no image data, so dropping it
// changes nothing else.
std::vector<unsigned char> without_empty_idat(const unsigned char* bytes, std::size_t size) {
  auto be32 = [bytes](std::size_t at) {
    return (static_cast<std::uint32_t>(bytes[at]) << 24) |
           (static_cast<std::uint32_t>(bytes[at + 1]) << 16) |
           (static_cast<std::uint32_t>(bytes[at + 2]) << 8) |
           static_cast<std::uint32_t>(bytes[at + 3]);
  };
  std::vector<std::size_t> empty_chunks;
  std::size_t at = 8; // After the signature.
  while (at + 12 <= size) {
    const std::uint64_t length = be32(at);
    if (length == 0 && std::memcmp(bytes + at + 4, "IDAT", 4) == 0) {
      empty_chunks.push_back(at);
    }
    if (length > size - at - 12) {
      break; // Truncated: leave the rest to stb_image, which reports it.
    }
    at += 12 + static_cast<std::size_t>(length);
  }
  std::vector<unsigned char> out;
  if (empty_chunks.empty()) {
    return out;
  }
  out.reserve(size);
  std::size_t from = 0;
  for (const std::size_t chunk : empty_chunks) {
    out.insert(out.end(), bytes + from, bytes + chunk);
    from = chunk + 12; // Length, type and CRC of an empty chunk.
  }
  out.insert(out.end(), bytes + from, bytes + size);
  return out;
}

} // namespace

bool load_image_data(tinygltf::Image* image, int image_index, std::string* err, std::string*, int,
                     int, const unsigned char* bytes, int size, void* user_data) {
  GltfLoadContext& ctx = *static_cast<GltfLoadContext*>(user_data);
  const std::string what = describe(*image, image_index);
  auto refuse = [&](ErrorCode code, const std::string& why) {
    if (!ctx.deny_all) {
      ctx.record(code, what + ": " + why);
    }
    if (err != nullptr) {
      *err += what + ": " + why + "\n";
    }
    return false;
  };
  if (ctx.deny_all) {
    return refuse(ErrorCode::parse_error, "not decoded");
  }
  if (bytes == nullptr || size <= 0) {
    return refuse(ErrorCode::parse_error, "no image data");
  }
  // Only the formats glTF 2.0 allows: stb_image also decodes TGA (which has no signature and
  // accepts nearly anything), PSD, HDR, PIC and PNM, none of which a glTF file may contain and
  // each of which widens what an untrusted file can reach.
  static const unsigned char png_magic[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const unsigned char jpeg_magic[] = {0xff, 0xd8, 0xff};
  if (!has_prefix(bytes, size, png_magic, sizeof png_magic) &&
      !has_prefix(bytes, size, jpeg_magic, sizeof jpeg_magic)) {
    return refuse(ErrorCode::unsupported, "not a PNG or JPEG image (the formats of glTF 2.0)");
  }
  std::vector<unsigned char> cleaned;
  if (has_prefix(bytes, size, png_magic, sizeof png_magic)) {
    cleaned = without_empty_idat(bytes, static_cast<std::size_t>(size));
    if (!cleaned.empty()) {
      bytes = cleaned.data();
      size = static_cast<int>(cleaned.size());
    }
  }
  // The size the header claims, read first: stb_image cannot even describe an image over its
  // own 2^30-byte limit ("unknown image type"), and the limits below name the size.
  std::uint64_t width = 0;
  std::uint64_t height = 0;
  int channels = 0;
  if (const auto header = read_image_header(bytes, static_cast<std::size_t>(size))) {
    width = header->width;
    height = header->height;
  } else {
    int w = 0;
    int h = 0;
    if (stbi_info_from_memory(bytes, size, &w, &h, &channels) == 0) {
      return refuse(ErrorCode::parse_error,
                    std::string("cannot read the image header: ") + stbi_failure_reason());
    }
    width = static_cast<std::uint64_t>(std::max(w, 0));
    height = static_cast<std::uint64_t>(std::max(h, 0));
  }
  const GltfLimits& limits = ctx.limits;
  const std::string size_text = std::to_string(width) + "x" + std::to_string(height);
  if (width == 0 || height == 0) {
    return refuse(ErrorCode::parse_error, "invalid size " + size_text);
  }
  if (width > limits.max_image_dimension || height > limits.max_image_dimension) {
    return refuse(ErrorCode::limit_exceeded,
                  "image is " + size_text + ", over the limit GltfLimits::max_image_dimension = " +
                      std::to_string(limits.max_image_dimension));
  }
  const std::uint64_t pixels = width * height;
  if (pixels > limits.max_image_pixels) {
    return refuse(ErrorCode::limit_exceeded,
                  "image is " + size_text + " = " + std::to_string(pixels) +
                      " pixels, over the limit GltfLimits::max_image_pixels = " +
                      std::to_string(limits.max_image_pixels));
  }
  if (ctx.decoded_pixels + pixels > limits.max_total_image_pixels) {
    return refuse(ErrorCode::limit_exceeded,
                  "decoding it would bring the images to " +
                      std::to_string(ctx.decoded_pixels + pixels) +
                      " pixels, over the limit GltfLimits::max_total_image_pixels = " +
                      std::to_string(limits.max_total_image_pixels));
  }

  int decoded_w = 0;
  int decoded_h = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels_rgba(
      stbi_load_from_memory(bytes, size, &decoded_w, &decoded_h, &channels, 4), &stbi_image_free);
  if (!pixels_rgba) {
    return refuse(ErrorCode::parse_error,
                  std::string("cannot decode the image: ") + stbi_failure_reason());
  }
  if (static_cast<std::uint64_t>(decoded_w) != width ||
      static_cast<std::uint64_t>(decoded_h) != height) {
    return refuse(ErrorCode::parse_error, "decoded size differs from the header's " + size_text);
  }
  ctx.decoded_pixels += pixels;
  image->width = decoded_w;
  image->height = decoded_h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(pixels_rgba.get(), pixels_rgba.get() + pixels * 4);
  return true;
}

} // namespace snell::detail

#include "image_header.hpp"

#include <cstring>

namespace snell::detail {
namespace {

std::uint32_t be16(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 8) | std::uint32_t{p[1]};
}

std::uint32_t be32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

} // namespace

std::optional<ImageHeader> read_image_header(const unsigned char* bytes, std::size_t size) {
  static const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size >= 24 && std::memcmp(bytes, png, sizeof png) == 0) {
    // Signature, then the IHDR chunk: length 13, "IHDR", width, height (big-endian).
    if (be32(bytes + 8) != 13 || std::memcmp(bytes + 12, "IHDR", 4) != 0) {
      return std::nullopt;
    }
    return ImageHeader{"PNG", be32(bytes + 16), be32(bytes + 20)};
  }
  if (size >= 4 && bytes[0] == 0xff && bytes[1] == 0xd8) {
    // JPEG: segments FF <marker> <length, 2 bytes, itself included>; the size is in the first
    // start-of-frame segment (SOF0..SOF15 but DHT C4, JPG C8, DAC CC): precision, height, width.
    std::size_t at = 2;
    while (at + 4 <= size) {
      if (bytes[at] != 0xff) {
        return std::nullopt;
      }
      const unsigned char marker = bytes[at + 1];
      if (marker == 0xff) {
        ++at; // fill byte
        continue;
      }
      const std::uint32_t length = be16(bytes + at + 2);
      if (length < 2) {
        return std::nullopt;
      }
      const bool sof =
          marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
      if (sof) {
        if (length < 7 || at + 9 > size) {
          return std::nullopt;
        }
        return ImageHeader{"JPEG", be16(bytes + at + 7), be16(bytes + at + 5)};
      }
      at += 2 + length;
    }
  }
  return std::nullopt;
}

} // namespace snell::detail

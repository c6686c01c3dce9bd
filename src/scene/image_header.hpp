// Internal: the pixel size a PNG or JPEG header claims, read without decoding. stb_image refuses
// to even describe an image it would not decode (over 2^30 bytes: "unknown image type" after
// trying every format), so the loaders read the size here first and name it against their limit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace snell::detail {

/// An image's format and claimed size.
struct ImageHeader {
  const char* format = ""; ///< "PNG" or "JPEG".
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

/// The size in a PNG's IHDR chunk or a JPEG's start-of-frame segment; nullopt for other formats
/// and for headers that are truncated or malformed (the decoder then reports them).
[[nodiscard]] std::optional<ImageHeader> read_image_header(const unsigned char* bytes,
                                                           std::size_t size);

} // namespace snell::detail

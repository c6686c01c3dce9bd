// Snell runtime: reading targets back to the CPU, and writing PNG files.
#pragma once

#include <snell/effect.hpp>
#include <snell/images.hpp>
#include <snell/scene.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace snell {

/// A float RGBA image on the CPU, rows top first (linear values for float targets).
struct FloatImage {
  std::uint32_t width = 0;   ///< Pixels.
  std::uint32_t height = 0;  ///< Pixels.
  std::vector<float> rgba{}; ///< width * height * 4 values.
};

/// Reads mip `level` of a render target's colour image as stored: RGBA8 bytes for 8-bit formats
/// (sRGB-encoded for rgba8_srgb, linear for rgba8_unorm); float targets are tone-mapped with
/// `tonemap`. The target must be in its finished state (after end_rendering), and no command
/// buffer that uses it may be pending. Errors: invalid_argument for a level out of range.
[[nodiscard]] Result<Image> read_rgba8(const Context& ctx, const RenderTarget& target,
                                       std::uint32_t level = 0);
/// Reads mip `level` as floats (8-bit formats are converted to [0,1], sRGB decoded to linear).
[[nodiscard]] Result<FloatImage> read_float(const Context& ctx, const RenderTarget& target,
                                            std::uint32_t level = 0);
/// Reads one face (layer 0..5) of a cube target at mip `level` (after end_capture).
[[nodiscard]] Result<Image> read_cube_face_rgba8(const Context& ctx, const CubeTarget& target,
                                                 std::uint32_t face, std::uint32_t level = 0);
/// Reads a render target's depth image (after end_rendering) as floats in [0,1].
[[nodiscard]] Result<std::vector<float>> read_depth(const Context& ctx, const RenderTarget& target);

/// Reads an effect's debug target (its `mip` level and `layer`) as floats: colour formats RGBA8
/// UNORM/SRGB (sRGB decoded to linear) and RGBA16F, or D32 depth (in the red channel). The effect's
/// passes must have completed. Errors: unsupported for other formats.
[[nodiscard]] Result<FloatImage> read_debug_target(const Context& ctx, const DebugTarget& target);

/// Tone-maps linear HDR values to sRGB-encoded RGBA8: `exposure` multiplies, then the
/// Reinhard-Jodie curve, then the sRGB transfer function. Alpha is clamped to [0,1].
[[nodiscard]] Image tonemap(const FloatImage& image, float exposure = 1.0f);

/// PNG encoding options (the encoder is stb_image_write's).
struct PngOptions {
  /// Compression effort: how many earlier matches stb_image_write's deflate searches per
  /// position, in [5, 32] (it treats anything below 5 as 5, its fastest). Default 8, stb's own.
  /// The `snell` CLI uses 5: measured sizes and times are in docs/cli.md.
  int compression_level = 8;
};

/// Encodes an RGBA8 image as PNG bytes (rows top first, 8 bits per channel). An image whose
/// alpha is 255 everywhere is stored as RGB (the same pixels when decoded, a quarter less to
/// compress). Errors: invalid_argument for an empty or inconsistent image or a level out of
/// range, out_of_memory when the encoder cannot allocate.
[[nodiscard]] Result<std::vector<std::uint8_t>> encode_png(const Image& image,
                                                           const PngOptions& options = {});

/// Encodes `image` (encode_png) and writes it with write_file (snell/output_file.hpp): all or
/// nothing, every write and the close checked. Errors name the path and the system's reason.
[[nodiscard]] Result<void> write_png(const std::filesystem::path& path, const Image& image,
                                     const PngOptions& options = {});

} // namespace snell

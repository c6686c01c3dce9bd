// Internal to the glass plugin: which of the two registered effects, parameter plumbing shared
// by the effect and its schemas, and the built-in textures.
#pragma once

#include <snell/glass.hpp>
#include <snell/scene.hpp>

#include <cstdint>

namespace snell {

/// The two registered names of the one implementation.
enum class GlassKind : std::uint8_t { glass, ice };

namespace detail {

/// Validates `value` against `kind`'s schema and stores it in `p` (unchanged on error; the
/// whole preset for "preset").
Result<void> apply_glass_param(GlassKind kind, GlassParams& p, std::string_view key,
                               const ParamValue& value);
/// The current value of `key` in `p`.
Result<ParamValue> read_glass_param(GlassKind kind, const GlassParams& p, std::string_view key);
/// Validates every field of `p` (ranges, non-finite values).
Result<void> validate_glass_params(GlassKind kind, const GlassParams& p);

/// The built-in tangent-space normal map of `kind` (glass: gentle low-frequency waviness; ice:
/// frost facets), RGBA8 linear, tileable, `size` x `size`.
Result<Image> builtin_glass_normal_map(GlassKind kind, std::uint32_t size);
/// The built-in colour texture of `kind` (glass: faint smudges; ice: frost), RGBA8 sRGB,
/// tileable, `size` x `size`.
Result<Image> builtin_glass_color(GlassKind kind, std::uint32_t size);

} // namespace detail
} // namespace snell

// Internal to the glass plugin: which of the two registered effects, parameter plumbing shared
// by the effect and its schemas, and the built-in textures.
#pragma once

#include <snell/glass.hpp>
#include <snell/param_table.hpp>
#include <snell/scene.hpp>

#include <cstdint>

namespace snell {

/// The two registered names of the one implementation.
enum class GlassKind : std::uint8_t { glass, ice };

namespace detail {

/// The parameter table of `kind` (schema, set, get, validation; its own defaults and preset).
const ParamTable<GlassParams>& glass_table(GlassKind kind);

/// The built-in tangent-space normal map of `kind` (glass: gentle low-frequency waviness; ice:
/// frost facets), RGBA8 linear, tileable, `size` x `size`.
Result<Image> builtin_glass_normal_map(GlassKind kind, std::uint32_t size);
/// The built-in colour texture of `kind` (glass: faint smudges; ice: frost), RGBA8 sRGB,
/// tileable, `size` x `size`.
Result<Image> builtin_glass_color(GlassKind kind, std::uint32_t size);

} // namespace detail
} // namespace snell

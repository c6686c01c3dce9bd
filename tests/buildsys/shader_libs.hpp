// tests/buildsys: two static libraries that each embed a shader named blit.frag (with different
// colours) through snell_embed_shaders, each in its own namespace.
#pragma once

#include <cstdint>
#include <span>

namespace build_test::a {
/// The SPIR-V library a embedded from lib_a/blit.frag.
std::span<const std::uint32_t> blit_frag();
/// The colour constant compiled into lib_a/blit.frag.
float marker();
} // namespace build_test::a

namespace build_test::b {
/// The SPIR-V library b embedded from lib_b/blit.frag.
std::span<const std::uint32_t> blit_frag();
/// The colour constant compiled into lib_b/blit.frag.
float marker();
} // namespace build_test::b

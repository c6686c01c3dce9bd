// snell_embed_shaders gives every target its own namespace: two static libraries embedding a
// shader of the same file name (blit.frag), linked into one executable, each see their own
// SPIR-V. With a shared namespace both define the same symbol and the linker silently keeps one,
// so one library would run the other's shader (cmake/SnellShaders.cmake).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "shader_libs.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>

namespace {

constexpr std::uint32_t kSpirvMagic = 0x07230203u;
constexpr std::uint32_t kOpConstant = 43u;

/// Whether `spirv` has an OpConstant whose (32-bit) value is the bits of `value`.
bool has_float_constant(std::span<const std::uint32_t> spirv, float value) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  std::size_t i = 5; // after the header
  while (i < spirv.size()) {
    const std::uint32_t count = spirv[i] >> 16u;
    const std::uint32_t opcode = spirv[i] & 0xffffu;
    if (count == 0 || i + count > spirv.size()) {
      return false; // malformed
    }
    if (opcode == kOpConstant && count == 4 && spirv[i + 3] == bits) {
      return true;
    }
    i += count;
  }
  return false;
}

} // namespace

TEST_CASE("embedded shaders: same file name in two libraries, each keeps its own SPIR-V") {
  const std::span<const std::uint32_t> a = build_test::a::blit_frag();
  const std::span<const std::uint32_t> b = build_test::b::blit_frag();
  REQUIRE(a.size() > 5);
  REQUIRE(b.size() > 5);
  CHECK(a[0] == kSpirvMagic);
  CHECK(b[0] == kSpirvMagic);
  REQUIRE(build_test::a::marker() != build_test::b::marker());

  // Two different arrays with different contents.
  CHECK(a.data() != b.data());
  CHECK_FALSE(std::equal(a.begin(), a.end(), b.begin(), b.end()));

  // Each library's span is the SPIR-V of its own blit.frag: its colour, not the other's.
  CHECK(has_float_constant(a, build_test::a::marker()));
  CHECK_FALSE(has_float_constant(a, build_test::b::marker()));
  CHECK(has_float_constant(b, build_test::b::marker()));
  CHECK_FALSE(has_float_constant(b, build_test::a::marker()));
}

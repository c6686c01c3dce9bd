// tests/buildsys: library a exposes the blit.frag it embedded (and the colour compiled into it).
#include "shader_libs.hpp"

#include "build_test_a_shaders.hpp" // generated: snell::build_test_a::shaders

namespace build_test::a {
std::span<const std::uint32_t> blit_frag() {
  return snell::build_test_a::shaders::blit_frag;
}
/// The colour in lib_a/blit.frag.
float marker() {
  return 0.3125f;
}
} // namespace build_test::a

// tests/buildsys: library b exposes the blit.frag it embedded (and the colour compiled into it).
#include "shader_libs.hpp"

#include "build_test_b_shaders.hpp" // generated: snell::build_test_b::shaders

namespace build_test::b {
std::span<const std::uint32_t> blit_frag() {
  return snell::build_test_b::shaders::blit_frag;
}
/// The colour in lib_b/blit.frag.
float marker() {
  return 0.6875f;
}
} // namespace build_test::b

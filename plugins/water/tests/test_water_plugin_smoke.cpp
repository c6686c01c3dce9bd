// Smoke test of the plugin-local test mechanism (snell_add_plugin TESTS): the water plugin's own
// test executable, with the shared GPU fixture, creates "water" through the registry.
#include "gpu_fixture.hpp"

#include <snell/effect.hpp>
#include <snell/water.hpp>

#include <variant>

using namespace snell;

TEST_CASE("plugin smoke: water from the registry, set_param/get_param round trip") {
  test::GpuFixture gpu;
  EffectRegistry registry;
  auto registered = register_builtin_effects(registry);
  REQUIRE_MESSAGE(registered.has_value(), registered.error().message);

  EffectCreateInfo info;
  info.context = &gpu.ctx();
  auto water = registry.create("water", info);
  REQUIRE_MESSAGE(water.has_value(), water.error().message);
  CHECK((*water)->type() == "water");

  auto set = (*water)->set_param("wave_height", 0.75f);
  REQUIRE_MESSAGE(set.has_value(), set.error().message);
  auto value = (*water)->get_param("wave_height");
  REQUIRE_MESSAGE(value.has_value(), value.error().message);
  REQUIRE(std::holds_alternative<float>(*value));
  CHECK(std::get<float>(*value) == doctest::Approx(0.75f));
}

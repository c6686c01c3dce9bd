// Consumer of the installed runtime: builds a built-in scene on the CPU (no GPU needed) and
// references the Vulkan context API so that the whole link closure is exercised.
#include <snell/builtin_scenes.hpp>
#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/water.hpp>

#include <cstdio>

int main() {
  auto scene = snell::make_builtin_scene("pool");
  const bool ok = scene.has_value() && !scene->objects.empty() && scene->find_anchor("water");
  std::printf("%s: make_builtin_scene(\"pool\") through the installed snell::runtime\n",
              ok ? "ok  " : "FAIL");
  // The plugins: the registry knows "water" with its schema (no GPU needed for that).
  snell::EffectRegistry registry;
  const bool registered = snell::register_builtin_effects(registry).has_value() &&
                          registry.schema("water") != nullptr &&
                          snell::water_schema().find("wave_height") != nullptr;
  std::printf("%s: register_builtin_effects through the installed snell::effects\n",
              registered ? "ok  " : "FAIL");
  // Taking the address forces the linker to resolve the runtime's Vulkan-dependent code.
  auto* create = &snell::Context::create;
  return ok && registered && create != nullptr ? 0 : 1;
}

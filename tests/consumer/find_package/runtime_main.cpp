// Consumer of the installed runtime: builds a built-in scene on the CPU (no GPU needed) and
// references the Vulkan context API so that the whole link closure is exercised.
#include <snell/builtin_scenes.hpp>
#include <snell/context.hpp>

#include <cstdio>

int main() {
  auto scene = snell::make_builtin_scene("pool");
  const bool ok = scene.has_value() && !scene->objects.empty() && scene->find_anchor("water");
  std::printf("%s: make_builtin_scene(\"pool\") through the installed snell::runtime\n",
              ok ? "ok  " : "FAIL");
  // Taking the address forces the linker to resolve the runtime's Vulkan-dependent code.
  auto* create = &snell::Context::create;
  return ok && create != nullptr ? 0 : 1;
}

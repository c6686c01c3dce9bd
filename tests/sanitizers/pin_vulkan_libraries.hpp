// Keeps the Vulkan driver and layer libraries loaded until the process exits, in sanitizer
// builds only. The loader dlclose()s them at vkDestroyInstance; LeakSanitizer then sees their
// process-lifetime allocations in "<unknown module>" frames that no suppression can match. With
// the libraries pinned (RTLD_NODELETE), their frames symbolise and tests/sanitizers/lsan.supp
// suppresses exactly those libraries, so leaks in Snell's own code are still reported.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>

namespace snell::test_support {
inline const bool vulkan_libraries_pinned = [] {
  for (const char* lib :
       {"libvulkan.so.1", "libvulkan_lvp.so", "libVkLayer_khronos_validation.so"}) {
    (void)dlopen(lib, RTLD_NOW | RTLD_NODELETE | RTLD_GLOBAL);
  }
  return true;
}();
} // namespace snell::test_support
#endif

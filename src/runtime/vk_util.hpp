// Internal: the runtime's names for the public Vulkan helpers of snell/toolkit/vk_check.hpp.
#pragma once

#include <snell/result.hpp>
#include <snell/toolkit/vk_check.hpp>

#include <vulkan/vulkan.h>

namespace snell::detail {

/// See snell::vk_struct.
template <class T> [[nodiscard]] T vk_init(VkStructureType type) {
  return vk_struct<T>(type);
}
using ::snell::vk_error;
using ::snell::vk_result_name;

} // namespace snell::detail

// Internal: turning VkResult failures into snell::Error values.
#pragma once

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

namespace snell::detail {

/// A zero-initialised Vulkan structure with its sType set (avoids the missing-field-initializer
/// warnings of the `T x{sType}` idiom while keeping every other member zero).
template <class T> [[nodiscard]] T vk_init(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

/// The VkResult enumerant's name ("VK_ERROR_OUT_OF_DEVICE_MEMORY"), or its number.
[[nodiscard]] std::string vk_result_name(VkResult result);

/// An Error naming the failed call, its VkResult and what was being done.
[[nodiscard]] Error vk_error(std::string_view call, VkResult result, std::string_view what = {});

} // namespace snell::detail

/// Returns a vk_error from the enclosing function when a Vulkan call fails.
#define SNELL_VK_TRY(call, what)                                                                   \
  do {                                                                                             \
    const VkResult snell_vk_result_ = (call);                                                      \
    if (snell_vk_result_ != VK_SUCCESS) {                                                          \
      return ::snell::detail::vk_error(#call, snell_vk_result_, (what));                           \
    }                                                                                              \
  } while (false)

// Snell plugin toolkit: Vulkan result checks that keep the VkResult in snell::Error, and the
// zero-initialised-struct helper. One mechanism for the runtime and every plugin.
#pragma once

#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

namespace snell {

/// A zero-initialised Vulkan structure with its sType set (`T x{}` plus sType, without the
/// missing-field-initializer warnings of `T x{sType}`).
template <class T> [[nodiscard]] T vk_struct(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

/// The VkResult enumerant's name ("VK_ERROR_OUT_OF_DEVICE_MEMORY"), or "VkResult(<n>)".
[[nodiscard]] std::string vk_result_name(VkResult result);

/// An Error for a failed Vulkan call: code out_of_memory for the two out-of-memory results,
/// vulkan_error otherwise; the message names `call`, the VkResult and `what` ("water surface
/// pipeline"); Error::vk_result keeps the VkResult.
[[nodiscard]] Error vk_error(std::string_view call, VkResult result, std::string_view what = {});

/// Success for VK_SUCCESS, else vk_error("Vulkan call", result, what).
[[nodiscard]] inline Result<void> check_vk(VkResult result, std::string_view what) {
  if (result == VK_SUCCESS) {
    return {};
  }
  return vk_error("Vulkan call", result, what);
}

} // namespace snell

/// Evaluates the Vulkan call `call`; when it does not return VK_SUCCESS, returns
/// `snell::vk_error("<call text>", result, what)` from the enclosing function (whose return type
/// is a snell::Result). `what` is a string naming the object being made.
#define SNELL_VK_TRY(call, what)                                                                   \
  do {                                                                                             \
    const VkResult snell_vk_result_ = (call);                                                      \
    if (snell_vk_result_ != VK_SUCCESS) {                                                          \
      return ::snell::vk_error(#call, snell_vk_result_, (what));                                   \
    }                                                                                              \
  } while (false)

#include "vk_util.hpp"

namespace snell {

std::string vk_result_name(VkResult result) {
  switch (result) {
#define SNELL_CASE(x)                                                                              \
  case x:                                                                                          \
    return #x;
    SNELL_CASE(VK_SUCCESS)
    SNELL_CASE(VK_NOT_READY)
    SNELL_CASE(VK_TIMEOUT)
    SNELL_CASE(VK_INCOMPLETE)
    SNELL_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    SNELL_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    SNELL_CASE(VK_ERROR_INITIALIZATION_FAILED)
    SNELL_CASE(VK_ERROR_DEVICE_LOST)
    SNELL_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    SNELL_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    SNELL_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    SNELL_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    SNELL_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    SNELL_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    SNELL_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    SNELL_CASE(VK_ERROR_FRAGMENTED_POOL)
    SNELL_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    SNELL_CASE(VK_ERROR_UNKNOWN)
#undef SNELL_CASE
  default:
    return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  }
}

Error vk_error(std::string_view call, VkResult result, std::string_view what) {
  const ErrorCode code =
      (result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY)
          ? ErrorCode::out_of_memory
          : ErrorCode::vulkan_error;
  std::string message(call);
  message += " failed with " + vk_result_name(result);
  if (!what.empty()) {
    message += " (";
    message += what;
    message += ")";
  }
  return Error{code, std::move(message), static_cast<std::int32_t>(result)};
}

} // namespace snell

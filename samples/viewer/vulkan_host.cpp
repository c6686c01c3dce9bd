#include "vulkan_host.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

namespace snell::viewer {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string last_glfw_error;

void on_glfw_error(int code, const char* description) {
  last_glfw_error = "GLFW error " + std::to_string(code) + ": " +
                    (description != nullptr ? description : "(no description)");
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT types,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  auto* log = static_cast<ValidationLog*>(user);
  const bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  const bool performance = !error && types == VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  if (error) {
    ++log->errors;
  } else if (performance) {
    ++log->performance;
  } else {
    ++log->warnings;
  }
  const std::lock_guard<std::mutex> lock(log->mutex);
  if (log->messages.size() < 100) {
    log->messages.emplace_back(
        std::string(error         ? "validation error: "
                    : performance ? "validation performance warning: "
                                  : "validation warning: ") +
        (data != nullptr && data->pMessage != nullptr ? data->pMessage : "(no message)"));
  }
  return VK_FALSE;
}

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

bool has_extension(VkPhysicalDevice pd, const char* name) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(pd, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(pd, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

/// The first queue family with graphics + compute that can present to `surface`, or -1.
int present_family(VkPhysicalDevice pd, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    VkBool32 present = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(pd, i, surface, &present);
    if ((families[i].queueFlags & need) == need && present == VK_TRUE) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// Why `pd` cannot be used ("" when it can): Vulkan 1.3, Snell's features, the swapchain.
std::string unsuitable(VkPhysicalDevice pd, VkSurfaceKHR surface) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(pd, &props);
  if (props.apiVersion < VK_API_VERSION_1_3) {
    return "Vulkan 1.3";
  }
  VkPhysicalDeviceVulkan13Features f13{};
  f13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  VkPhysicalDeviceVulkan11Features f11{};
  f11.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES;
  f11.pNext = &f13;
  VkPhysicalDeviceFeatures2 f2{};
  f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  f2.pNext = &f11;
  vkGetPhysicalDeviceFeatures2(pd, &f2);
  if (!(f13.dynamicRendering && f13.synchronization2 && f11.multiview &&
        f2.features.shaderClipDistance)) {
    return "dynamicRendering, synchronization2, multiview or shaderClipDistance";
  }
  if (!has_extension(pd, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
    return VK_KHR_SWAPCHAIN_EXTENSION_NAME;
  }
  if (present_family(pd, surface) < 0) {
    return "a graphics + compute queue that presents to the window";
  }
  return "";
}

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
  case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
    return 0;
  case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
    return 1;
  case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
    return 2;
  case VK_PHYSICAL_DEVICE_TYPE_CPU:
    return 3;
  default:
    return 4;
  }
}

/// The device request as snell::ContextDesc::device reads it.
bool matches(const VkPhysicalDeviceProperties& props, const std::string& request) {
  const std::string r = lower(request);
  if (r.empty()) {
    return true;
  }
  if (r == "lavapipe" || r == "llvmpipe" || r == "cpu") {
    return props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  }
  if (r == "gpu") {
    return props.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU;
  }
  return lower(props.deviceName).find(r) != std::string::npos;
}

Error vk_failure(const char* what, VkResult result) {
  Error e{ErrorCode::vulkan_error, std::string(what) + " failed (VkResult " +
                                       std::to_string(static_cast<int>(result)) + ")"};
  e.vk_result = result;
  return e;
}

} // namespace

std::string glfw_error() {
  return last_glfw_error;
}

Result<void> VulkanHost::init(const HostOptions& options, ValidationLog& log) {
  glfwSetErrorCallback(on_glfw_error);
  if (glfwInit() != GLFW_TRUE) {
    return fail(ErrorCode::missing_feature, "cannot open a window: " + glfw_error() +
                                                " (is DISPLAY set to a running X server?)");
  }
  glfw_ = true;
  if (glfwVulkanSupported() != GLFW_TRUE) {
    return fail(ErrorCode::missing_feature,
                "GLFW finds no Vulkan loader with surface support: " + glfw_error());
  }
  std::uint32_t glfw_count = 0;
  const char** glfw_extensions = glfwGetRequiredInstanceExtensions(&glfw_count);
  if (glfw_extensions == nullptr) {
    return fail(ErrorCode::missing_feature,
                "the Vulkan driver has no surface extension for this window system: " +
                    glfw_error());
  }
  std::vector<const char*> extensions(glfw_extensions, glfw_extensions + glfw_count);

  // --- Instance (+ validation with synchronization validation, as the runtime's own). -------
  validation = options.validation;
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "snell view";
  app.pEngineName = "snell";
  app.apiVersion = VK_API_VERSION_1_3;
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
  messenger_info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = on_validation;
  messenger_info.pUserData = &log;
  const VkValidationFeatureEnableEXT sync =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{};
  features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &sync;
  features.pNext = &messenger_info;
  const char* layers[] = {kValidationLayer};
  VkInstanceCreateInfo ici{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  if (validation) {
    if (!layer_available(kValidationLayer)) {
      return fail(ErrorCode::missing_feature,
                  "validation requested (--validation or SNELL_VALIDATION=1) but "
                  "VK_LAYER_KHRONOS_validation is not installed (Debian: vulkan-validationlayers)");
    }
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    ici.pNext = &features;
    ici.enabledLayerCount = 1;
    ici.ppEnabledLayerNames = layers;
  }
  ici.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  ici.ppEnabledExtensionNames = extensions.data();
  if (VkResult r = vkCreateInstance(&ici, nullptr, &instance); r != VK_SUCCESS) {
    instance = VK_NULL_HANDLE;
    return vk_failure("vkCreateInstance (Vulkan 1.3 with surface extensions)", r);
  }
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr) {
      return fail(ErrorCode::missing_feature, "vkCreateDebugUtilsMessengerEXT is not available");
    }
    if (VkResult r = create(instance, &messenger_info, nullptr, &messenger); r != VK_SUCCESS) {
      return vk_failure("vkCreateDebugUtilsMessengerEXT", r);
    }
  }

  // --- Window and surface. ---------------------------------------------------------------------
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window = glfwCreateWindow(static_cast<int>(options.width), static_cast<int>(options.height),
                            options.title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    return fail(ErrorCode::missing_feature, "glfwCreateWindow failed: " + glfw_error());
  }
  if (VkResult r = glfwCreateWindowSurface(instance, window, nullptr, &surface); r != VK_SUCCESS) {
    surface = VK_NULL_HANDLE;
    return vk_failure(("glfwCreateWindowSurface (" + glfw_error() + ")").c_str(), r);
  }

  // --- Device: Snell's features, the swapchain, a queue that presents; the request. ----------
  std::string request = options.device;
  if (request.empty()) {
    const char* env = std::getenv("SNELL_DEVICE");
    request = env != nullptr ? env : "";
  }
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  int best_rank = 1000;
  std::string listing;
  for (VkPhysicalDevice pd : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(pd, &props);
    const std::string why = unsuitable(pd, surface);
    listing += "\n  " + std::string(props.deviceName) + (why.empty() ? "" : " (lacks " + why + ")");
    if (why.empty() && matches(props, request) && type_rank(props.deviceType) < best_rank) {
      physical_device = pd;
      best_rank = type_rank(props.deviceType);
      device_name = props.deviceName;
    }
  }
  if (physical_device == VK_NULL_HANDLE) {
    return fail(ErrorCode::no_device,
                "no Vulkan device that can present to the window matches '" +
                    (request.empty() ? std::string("any") : request) +
                    "' (--device or SNELL_DEVICE: lavapipe, gpu or a name substring); devices:" +
                    (listing.empty() ? std::string(" none") : listing));
  }
  queue_family = static_cast<std::uint32_t>(present_family(physical_device, surface));
  vkGetPhysicalDeviceMemoryProperties(physical_device, &memory);

  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(physical_device, &supported);
  features13_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  features13_.dynamicRendering = VK_TRUE;
  features13_.synchronization2 = VK_TRUE;
  features11_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES;
  features11_.multiview = VK_TRUE;
  features11_.pNext = &features13_;
  features2_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features2_.features.shaderClipDistance = VK_TRUE;
  features2_.features.samplerAnisotropy = supported.samplerAnisotropy; // the scene's textures
  features2_.pNext = &features11_;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = queue_family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  const char* device_extensions[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  VkDeviceCreateInfo dci{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.pNext = &features2_;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = 1;
  dci.ppEnabledExtensionNames = device_extensions;
  if (VkResult r = vkCreateDevice(physical_device, &dci, nullptr, &device); r != VK_SUCCESS) {
    device = VK_NULL_HANDLE;
    return vk_failure("vkCreateDevice", r);
  }
  vkGetDeviceQueue(device, queue_family, 0, &queue);
  return {};
}

Result<std::uint32_t> VulkanHost::memory_type(std::uint32_t type_bits,
                                              VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
      return i;
    }
  }
  return fail(ErrorCode::out_of_memory, "no memory type with properties " + std::to_string(flags));
}

VulkanHost::~VulkanHost() {
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr); // the layer reports any object still alive here
  }
  if (surface != VK_NULL_HANDLE) {
    vkDestroySurfaceKHR(instance, surface, nullptr);
  }
  if (window != nullptr) {
    glfwDestroyWindow(window);
  }
  if (messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) {
      destroy(instance, messenger, nullptr);
    }
  }
  if (instance != VK_NULL_HANDLE) {
    vkDestroyInstance(instance, nullptr);
  }
  if (glfw_) {
    glfwTerminate();
  }
}

} // namespace snell::viewer

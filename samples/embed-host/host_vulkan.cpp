#include "host_vulkan.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace embed {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  auto* log = static_cast<ValidationLog*>(user);
  if ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) == 0) {
    ++log->warnings;
    return VK_FALSE;
  }
  ++log->errors;
  const std::lock_guard<std::mutex> lock(log->mutex);
  if (log->messages.size() < 100) {
    log->messages.emplace_back(data != nullptr && data->pMessage != nullptr ? data->pMessage
                                                                            : "(no message)");
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

/// The first queue family with graphics + compute (transfer is implied), or -1.
int graphics_compute_family(VkPhysicalDevice pd) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[i].queueFlags & need) == need) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// Whether `pd` is Vulkan 1.3 with the four features Snell needs.
bool has_snell_features(VkPhysicalDevice pd) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(pd, &props);
  if (props.apiVersion < VK_API_VERSION_1_3) {
    return false;
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
  return f13.dynamicRendering && f13.synchronization2 && f11.multiview &&
         f2.features.shaderClipDistance;
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

} // namespace

void vk_check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) {
    throw HostError(std::string(what) + " failed (VkResult " + std::to_string(result) + ")");
  }
}

// --- HostDevice ---------------------------------------------------------------------------------

void HostDevice::init(const DeviceOptions& options, ValidationLog& log) {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "snell-embed-host";
  app.pEngineName = "embed-host";
  app.apiVersion = VK_API_VERSION_1_3;

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
  messenger_info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger_info.pfnUserCallback = on_validation;
  messenger_info.pUserData = &log;
  // Synchronization validation too: it checks the host's barriers around Snell's passes.
  const VkValidationFeatureEnableEXT sync =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{};
  features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &sync;
  features.pNext = &messenger_info; // also reports problems of vkCreate/DestroyInstance

  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME,
                              VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
  VkInstanceCreateInfo ici{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  if (options.validation) {
    if (!layer_available(kValidationLayer)) {
      throw HostError("validation requested but VK_LAYER_KHRONOS_validation is not installed "
                      "(Debian: vulkan-validationlayers)");
    }
    ici.pNext = &features;
    ici.enabledLayerCount = 1;
    ici.ppEnabledLayerNames = layers;
    ici.enabledExtensionCount = 2;
    ici.ppEnabledExtensionNames = extensions;
  }
  vk_check(vkCreateInstance(&ici, nullptr, &instance), "vkCreateInstance (Vulkan 1.3)");
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr) {
      throw HostError("vkCreateDebugUtilsMessengerEXT is not available");
    }
    vk_check(create(instance, &messenger_info, nullptr, &messenger),
             "vkCreateDebugUtilsMessengerEXT");
  }

  // Pick a device: Vulkan 1.3, Snell's features, a graphics + compute queue, the request.
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  int best_rank = 1000;
  std::string seen;
  for (VkPhysicalDevice pd : devices) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(pd, &props);
    seen += seen.empty() ? "" : ", ";
    seen += props.deviceName;
    if (matches(props, options.device) && has_snell_features(pd) &&
        graphics_compute_family(pd) >= 0 && type_rank(props.deviceType) < best_rank) {
      physical_device = pd;
      best_rank = type_rank(props.deviceType);
      device_name = props.deviceName;
    }
  }
  if (physical_device == VK_NULL_HANDLE) {
    throw HostError("no Vulkan 1.3 device with dynamicRendering, synchronization2, multiview, "
                    "shaderClipDistance and a graphics + compute queue matches '" +
                    (options.device.empty() ? std::string("any") : options.device) +
                    "' (devices: " + (seen.empty() ? std::string("none") : seen) + ")");
  }
  queue_family = static_cast<std::uint32_t>(graphics_compute_family(physical_device));
  vkGetPhysicalDeviceMemoryProperties(physical_device, &memory);

  // The features Snell needs (see snell::AdoptInfo), enabled on the host's own device.
  VkPhysicalDeviceVulkan13Features f13{};
  f13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  f13.dynamicRendering = VK_TRUE;
  f13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceVulkan11Features f11{};
  f11.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES;
  f11.multiview = VK_TRUE;
  f11.pNext = &f13;
  VkPhysicalDeviceFeatures2 f2{};
  f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  f2.features.shaderClipDistance = VK_TRUE;
  f2.pNext = &f11;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = queue_family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.pNext = &f2;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  vk_check(vkCreateDevice(physical_device, &dci, nullptr, &device), "vkCreateDevice");
  vkGetDeviceQueue(device, queue_family, 0, &queue);
}

HostDevice::~HostDevice() {
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr); // the layer reports any object still alive here
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
}

std::uint32_t HostDevice::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
      return i;
    }
  }
  throw HostError("no memory type with properties " + std::to_string(flags));
}

// --- HostFrame ----------------------------------------------------------------------------------

namespace {

VkDeviceMemory allocate(const HostDevice& dev, VkMemoryRequirements req,
                        VkMemoryPropertyFlags flags) {
  VkMemoryAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = dev.memory_type(req.memoryTypeBits, flags);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vk_check(vkAllocateMemory(dev.device, &ai, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

} // namespace

void HostFrame::init(const HostDevice& device, VkExtent2D size) {
  dev_ = &device;
  extent = size;
  const VkDevice d = device.device;

  // Colour and depth images, device-local, one dedicated allocation each.
  auto make_image = [&](VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                        VkImage& image, VkDeviceMemory& memory, VkImageView& view) {
    VkImageCreateInfo ci{};
    ci.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    ci.imageType = VK_IMAGE_TYPE_2D;
    ci.format = format;
    ci.extent = {extent.width, extent.height, 1};
    ci.mipLevels = 1;
    ci.arrayLayers = 1;
    ci.samples = VK_SAMPLE_COUNT_1_BIT;
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    vk_check(vkCreateImage(d, &ci, nullptr, &image), "vkCreateImage");
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(d, image, &req);
    memory = allocate(device, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    vk_check(vkBindImageMemory(d, image, memory, 0), "vkBindImageMemory");
    VkImageViewCreateInfo vi{};
    vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {aspect, 0, 1, 0, 1};
    vk_check(vkCreateImageView(d, &vi, nullptr, &view), "vkCreateImageView");
  };
  make_image(kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
             VK_IMAGE_ASPECT_COLOR_BIT, color, color_memory_, color_view);
  make_image(kDepthFormat,
             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
             VK_IMAGE_ASPECT_DEPTH_BIT, depth, depth_memory_, depth_view);

  // Readback buffer: host-visible and coherent, persistently mapped.
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = VkDeviceSize{extent.width} * extent.height * 4;
  bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateBuffer(d, &bi, nullptr, &readback), "vkCreateBuffer (readback)");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(d, readback, &req);
  readback_memory_ = allocate(
      device, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  vk_check(vkBindBufferMemory(d, readback, readback_memory_, 0), "vkBindBufferMemory");
  vk_check(vkMapMemory(d, readback_memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");

  // Command pool + one resettable command buffer, and a fence.
  VkCommandPoolCreateInfo pci{};
  pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = device.queue_family;
  vk_check(vkCreateCommandPool(d, &pci, nullptr, &pool_), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo cai{};
  cai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  cai.commandPool = pool_;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  vk_check(vkAllocateCommandBuffers(d, &cai, &cmd), "vkAllocateCommandBuffers");
  VkFenceCreateInfo fci{};
  fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  vk_check(vkCreateFence(d, &fci, nullptr, &fence_), "vkCreateFence");
}

void HostFrame::submit_and_wait() {
  VkCommandBufferSubmitInfo cbi{};
  cbi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
  cbi.commandBuffer = cmd;
  VkSubmitInfo2 si{};
  si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2;
  si.commandBufferInfoCount = 1;
  si.pCommandBufferInfos = &cbi;
  vk_check(vkQueueSubmit2(dev_->queue, 1, &si, fence_), "vkQueueSubmit2");
  vk_check(vkWaitForFences(dev_->device, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  vk_check(vkResetFences(dev_->device, 1, &fence_), "vkResetFences");
}

std::vector<std::uint8_t> HostFrame::pixels() const {
  const auto* bytes = static_cast<const std::uint8_t*>(mapped_);
  return {bytes, bytes + std::size_t{extent.width} * extent.height * 4};
}

HostFrame::~HostFrame() {
  if (dev_ == nullptr) {
    return;
  }
  const VkDevice d = dev_->device;
  vkDeviceWaitIdle(d);
  vkDestroyFence(d, fence_, nullptr);
  vkDestroyCommandPool(d, pool_, nullptr); // frees `cmd`
  vkDestroyBuffer(d, readback, nullptr);
  vkFreeMemory(d, readback_memory_, nullptr); // unmaps
  vkDestroyImageView(d, depth_view, nullptr);
  vkDestroyImage(d, depth, nullptr);
  vkFreeMemory(d, depth_memory_, nullptr);
  vkDestroyImageView(d, color_view, nullptr);
  vkDestroyImage(d, color, nullptr);
  vkFreeMemory(d, color_memory_, nullptr);
}

} // namespace embed

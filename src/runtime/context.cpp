// Headless Vulkan context: instance, device selection, validation messenger, one-shot submits.
#include "context_impl.hpp"
#include "vk_util.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

namespace snell {
namespace {

using detail::vk_init;

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
  case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
    return "discrete GPU";
  case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
    return "integrated GPU";
  case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
    return "virtual GPU";
  case VK_PHYSICAL_DEVICE_TYPE_CPU:
    return "CPU";
  default:
    return "other";
  }
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

bool env_flag(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && (std::strcmp(v, "1") == 0 || lower(v) == "true" || lower(v) == "on");
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

/// The graphics + compute queue family of a device, or -1.
int pick_queue_family(VkPhysicalDevice pd) {
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

/// Snell's required features, queried or checked on `pd`. `missing` lists what lacks.
struct FeatureChain {
  VkPhysicalDeviceVulkan13Features f13 = vk_init<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  VkPhysicalDeviceVulkan11Features f11 = vk_init<VkPhysicalDeviceVulkan11Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
  VkPhysicalDeviceFeatures2 f2 =
      vk_init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  FeatureChain() {
    f2.pNext = &f11;
    f11.pNext = &f13;
  }
  FeatureChain(const FeatureChain&) = delete;
  FeatureChain& operator=(const FeatureChain&) = delete;
  std::string missing() const {
    std::string m;
    auto need = [&](VkBool32 have, const char* name) {
      if (!have) {
        m += m.empty() ? "" : ", ";
        m += name;
      }
    };
    need(f13.dynamicRendering, "dynamicRendering (Vulkan 1.3)");
    need(f13.synchronization2, "synchronization2 (Vulkan 1.3)");
    need(f11.multiview, "multiview (Vulkan 1.1)");
    need(f2.features.shaderClipDistance, "shaderClipDistance");
    return m;
  }
};

DeviceInfo describe(VkPhysicalDevice pd) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(pd, &props);
  VkPhysicalDeviceDriverProperties driver = vk_init<VkPhysicalDeviceDriverProperties>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
  auto props2 =
      vk_init<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
  props2.pNext = &driver;
  vkGetPhysicalDeviceProperties2(pd, &props2);
  DeviceInfo info;
  info.name = props.deviceName;
  info.type = props.deviceType;
  info.api_version = props.apiVersion;
  info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  const int family = pick_queue_family(pd);
  if (family >= 0) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(pd, &count, families.data());
    if (families[static_cast<std::size_t>(family)].timestampValidBits > 0) {
      info.timestamp_period_ns = props.limits.timestampPeriod;
    }
  }
  if (props.apiVersion < VK_API_VERSION_1_3) {
    info.missing = "Vulkan 1.3";
  } else if (family < 0) {
    info.missing = "a graphics + compute queue";
  } else {
    FeatureChain chain;
    vkGetPhysicalDeviceFeatures2(pd, &chain.f2);
    info.missing = chain.missing();
  }
  info.suitable = info.missing.empty();
  return info;
}

VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user) {
  auto* impl = static_cast<ContextState*>(user);
  const bool error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
  if (error) {
    ++impl->errors;
  } else {
    ++impl->warnings;
  }
  std::string text = error ? "validation error: " : "validation warning: ";
  text += data && data->pMessage ? data->pMessage : "(no message)";
  {
    std::lock_guard<std::mutex> lock(impl->messages_mutex);
    if (impl->messages.size() < 1000) { // bounded: a broken loop must not exhaust memory
      impl->messages.push_back(text);
    }
  }
  return VK_FALSE;
}

Result<VkInstance> create_instance(const ContextDesc& desc, bool validation, ContextState& impl) {
  VkApplicationInfo app = vk_init<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = desc.app_name.c_str();
  app.pEngineName = "snell";
  app.apiVersion = VK_API_VERSION_1_3;
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  VkValidationFeaturesEXT features =
      vk_init<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
  const VkValidationFeatureEnableEXT enabled[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  auto messenger = vk_init<VkDebugUtilsMessengerCreateInfoEXT>(
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = debug_callback;
  messenger.pUserData = &impl;
  VkInstanceCreateInfo ci = vk_init<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  ci.pApplicationInfo = &app;
  if (validation) {
    if (!layer_available(kValidationLayer)) {
      return fail(ErrorCode::missing_feature,
                  "validation requested (ContextDesc::validation or SNELL_VALIDATION=1) but "
                  "VK_LAYER_KHRONOS_validation is not installed (Debian: vulkan-validationlayers)");
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enabled;
    features.pNext = &messenger; // also reports instance creation/destruction problems
    ci.pNext = &features;
  }
  ci.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  ci.ppEnabledLayerNames = layers.data();
  ci.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  ci.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  SNELL_VK_TRY(vkCreateInstance(&ci, nullptr, &instance),
               "is a Vulkan 1.3 driver installed? Debian: mesa-vulkan-drivers");
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr || create(instance, &messenger, nullptr, &impl.messenger) != VK_SUCCESS) {
      vkDestroyInstance(instance, nullptr);
      return fail(ErrorCode::vulkan_error, "vkCreateDebugUtilsMessengerEXT failed");
    }
  }
  return instance;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  devices.resize(count);
  return devices;
}

bool matches(const DeviceInfo& info, const std::string& request) {
  if (request.empty()) {
    return true;
  }
  const std::string r = lower(request);
  if (r == "lavapipe" || r == "llvmpipe" || r == "cpu") {
    return info.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
  }
  if (r == "gpu") {
    return info.type != VK_PHYSICAL_DEVICE_TYPE_CPU;
  }
  return lower(info.name).find(r) != std::string::npos;
}

Result<VkPhysicalDevice> choose_device(VkInstance instance, const std::string& request) {
  VkPhysicalDevice best = VK_NULL_HANDLE;
  int best_rank = 1000;
  std::string listing;
  for (VkPhysicalDevice pd : physical_devices(instance)) {
    const DeviceInfo info = describe(pd);
    listing += "\n  " + info.name + " (" + type_name(info.type) + ")" +
               (info.suitable ? "" : " unsuitable: lacks " + info.missing);
    if (info.suitable && matches(info, request) && type_rank(info.type) < best_rank) {
      best = pd;
      best_rank = type_rank(info.type);
    }
  }
  if (best == VK_NULL_HANDLE) {
    return fail(ErrorCode::no_device,
                "no suitable Vulkan device matches '" + (request.empty() ? "any" : request) +
                    "' (SNELL_DEVICE or ContextDesc::device: lavapipe, gpu or a name substring); "
                    "devices:" +
                    (listing.empty() ? std::string(" none") : listing));
  }
  return best;
}

Result<void> init_common(ContextState& impl) {
  impl.info = describe(impl.physical_device);
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(impl.physical_device, &props);
  impl.limits = props.limits;
  vkGetPhysicalDeviceMemoryProperties(impl.physical_device, &impl.memory);
  VkCommandPoolCreateInfo pci =
      vk_init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pci.flags =
      VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT | VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pci.queueFamilyIndex = impl.queue_family;
  SNELL_VK_TRY(vkCreateCommandPool(impl.device, &pci, nullptr, &impl.pool), "context command pool");
  VkFenceCreateInfo fci = vk_init<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  SNELL_VK_TRY(vkCreateFence(impl.device, &fci, nullptr, &impl.fence), "context fence");
  for (std::uint32_t i = 0; i < kStandardSamplerCount; ++i) {
    const auto which = static_cast<StandardSampler>(i);
    auto ci = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    const bool linear = which != StandardSampler::nearest_clamp;
    ci.magFilter = ci.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    ci.mipmapMode = linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    ci.addressModeU = ci.addressModeV = ci.addressModeW =
        which == StandardSampler::linear_repeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT
                                                : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    ci.maxLod = linear ? VK_LOD_CLAMP_NONE : 0.0f;
    SNELL_VK_TRY(vkCreateSampler(impl.device, &ci, nullptr, &impl.samplers[i]),
                 "context standard sampler");
  }
  return {};
}

} // namespace

ContextState::~ContextState() {
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    if (fence != VK_NULL_HANDLE) {
      vkDestroyFence(device, fence, nullptr);
    }
    for (VkSampler sampler : samplers) {
      if (sampler != VK_NULL_HANDLE) {
        vkDestroySampler(device, sampler, nullptr);
      }
    }
    if (pool != VK_NULL_HANDLE) {
      vkDestroyCommandPool(device, pool, nullptr);
    }
  }
  if (!owns) {
    return;
  }
  if (device != VK_NULL_HANDLE) {
    vkDestroyDevice(device, nullptr);
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

Context::Context(std::unique_ptr<ContextState> impl) : impl_(std::move(impl)) {}
Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&&) noexcept = default;
Context::~Context() = default;

Result<Context> Context::create(const ContextDesc& desc) {
  auto impl = std::make_unique<ContextState>();
  impl->owns = true;
  impl->validation = desc.validation || env_flag("SNELL_VALIDATION");
  auto instance = create_instance(desc, impl->validation, *impl);
  if (!instance) {
    return instance.error();
  }
  impl->instance = *instance;

  std::string request = desc.device;
  if (request.empty()) {
    const char* env = std::getenv("SNELL_DEVICE");
    request = env != nullptr ? env : "";
  }
  auto pd = choose_device(impl->instance, request);
  if (!pd) {
    return pd.error();
  }
  impl->physical_device = *pd;
  impl->queue_family = static_cast<std::uint32_t>(pick_queue_family(*pd));

  FeatureChain supported;
  vkGetPhysicalDeviceFeatures2(*pd, &supported.f2);
  FeatureChain enable;
  enable.f13.dynamicRendering = VK_TRUE;
  enable.f13.synchronization2 = VK_TRUE;
  enable.f11.multiview = VK_TRUE;
  enable.f2.features.shaderClipDistance = VK_TRUE;
  enable.f2.features.samplerAnisotropy = supported.f2.features.samplerAnisotropy;
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qci =
      vk_init<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  qci.queueFamilyIndex = impl->queue_family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci = vk_init<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  dci.pNext = &enable.f2;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  SNELL_VK_TRY(vkCreateDevice(*pd, &dci, nullptr, &impl->device), "creating the logical device");
  vkGetDeviceQueue(impl->device, impl->queue_family, 0, &impl->queue);
  if (auto r = init_common(*impl); !r) {
    return r.error();
  }
  return Context(std::move(impl));
}

Result<Context> Context::adopt(const AdoptInfo& info) {
  if (info.instance == VK_NULL_HANDLE || info.physical_device == VK_NULL_HANDLE ||
      info.device == VK_NULL_HANDLE || info.queue == VK_NULL_HANDLE) {
    return fail(ErrorCode::invalid_argument,
                "AdoptInfo: instance, physical_device, device and queue are all required");
  }
  const DeviceInfo described = describe(info.physical_device);
  if (!described.suitable) {
    return fail(ErrorCode::missing_feature,
                "AdoptInfo: device '" + described.name + "' lacks " + described.missing);
  }
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(info.physical_device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(info.physical_device, &count, families.data());
  const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if (info.queue_family >= count || (families[info.queue_family].queueFlags & need) != need) {
    return fail(ErrorCode::invalid_argument, "AdoptInfo: queue_family " +
                                                 std::to_string(info.queue_family) +
                                                 " does not exist or lacks graphics + compute");
  }
  if (info.enabled_features != nullptr) {
    // Walk the host's chain; absent structures mean "not enabled".
    bool dynamic_rendering = false, sync2 = false, multiview = false, clip_distance = false;
    for (auto* s = static_cast<const VkBaseInStructure*>(info.enabled_features); s != nullptr;
         s = s->pNext) {
      if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2) {
        clip_distance |=
            reinterpret_cast<const VkPhysicalDeviceFeatures2*>(s)->features.shaderClipDistance ==
            VK_TRUE;
      } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES) {
        multiview |=
            reinterpret_cast<const VkPhysicalDeviceVulkan11Features*>(s)->multiview == VK_TRUE;
      } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES) {
        const auto* f = reinterpret_cast<const VkPhysicalDeviceVulkan13Features*>(s);
        dynamic_rendering |= f->dynamicRendering == VK_TRUE;
        sync2 |= f->synchronization2 == VK_TRUE;
      } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES) {
        multiview |=
            reinterpret_cast<const VkPhysicalDeviceMultiviewFeatures*>(s)->multiview == VK_TRUE;
      } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES) {
        dynamic_rendering |= reinterpret_cast<const VkPhysicalDeviceDynamicRenderingFeatures*>(s)
                                 ->dynamicRendering == VK_TRUE;
      } else if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES) {
        sync2 |= reinterpret_cast<const VkPhysicalDeviceSynchronization2Features*>(s)
                     ->synchronization2 == VK_TRUE;
      }
    }
    std::string missing;
    for (const auto& [ok, name] :
         {std::pair{dynamic_rendering, "dynamicRendering"}, std::pair{sync2, "synchronization2"},
          std::pair{multiview, "multiview"}, std::pair{clip_distance, "shaderClipDistance"}}) {
      if (!ok) {
        if (!missing.empty()) {
          missing += ", ";
        }
        missing += name;
      }
    }
    if (!missing.empty()) {
      return fail(ErrorCode::missing_feature,
                  "AdoptInfo: the device was created without " + missing +
                      " enabled (enable them in the VkDeviceCreateInfo pNext chain)");
    }
  }
  auto impl = std::make_unique<ContextState>();
  impl->owns = false;
  impl->instance = info.instance;
  impl->physical_device = info.physical_device;
  impl->device = info.device;
  impl->queue = info.queue;
  impl->queue_family = info.queue_family;
  if (auto r = init_common(*impl); !r) {
    return r.error();
  }
  return Context(std::move(impl));
}

Result<std::vector<DeviceInfo>> Context::enumerate_devices() {
  ContextState scratch;
  scratch.owns = true;
  auto instance = create_instance(ContextDesc{}, false, scratch);
  if (!instance) {
    return instance.error();
  }
  scratch.instance = *instance;
  std::vector<DeviceInfo> out;
  for (VkPhysicalDevice pd : physical_devices(*instance)) {
    out.push_back(describe(pd));
  }
  return out;
}

VkInstance Context::instance() const {
  return impl_->instance;
}
VkPhysicalDevice Context::physical_device() const {
  return impl_->physical_device;
}
VkDevice Context::device() const {
  return impl_->device;
}
VkQueue Context::queue() const {
  return impl_->queue;
}
std::uint32_t Context::queue_family() const {
  return impl_->queue_family;
}
const DeviceInfo& Context::device_info() const {
  return impl_->info;
}
bool Context::owns_device() const {
  return impl_->owns;
}
bool Context::validation_enabled() const {
  return impl_->validation;
}
std::uint32_t Context::validation_error_count() const {
  return impl_->errors.load();
}
std::uint32_t Context::validation_warning_count() const {
  return impl_->warnings.load();
}
std::vector<std::string> Context::validation_messages() const {
  std::lock_guard<std::mutex> lock(impl_->messages_mutex);
  return impl_->messages;
}

const ContextState* context_state(const Context& ctx) noexcept {
  return ctx.impl_.get();
}

const VkPhysicalDeviceLimits& Context::limits() const {
  return impl_->limits;
}

VkSampler Context::sampler(StandardSampler which) const {
  return impl_->samplers[static_cast<std::uint32_t>(which) % kStandardSamplerCount];
}

Result<void> Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const {
  return impl_->submit_and_wait(record);
}

Result<std::uint32_t> Context::find_memory_type(std::uint32_t type_bits,
                                                VkMemoryPropertyFlags properties) const {
  return impl_->find_memory_type(type_bits, properties);
}

Result<void>
ContextState::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const {
  const ContextState* impl_ = this;
  if (submit_owner.load() == std::this_thread::get_id()) {
    return fail(ErrorCode::invalid_argument,
                "Context::submit_and_wait called from inside its own callback (a nested submit "
                "would wait forever): record into the command buffer the callback was given");
  }
  std::lock_guard<std::mutex> lock(impl_->submit_mutex);
  submit_owner.store(std::this_thread::get_id());
  struct ClearOwner {
    std::atomic<std::thread::id>& owner;
    ~ClearOwner() { owner.store(std::thread::id{}); }
  } clear_owner{submit_owner};
  VkCommandBufferAllocateInfo ai =
      vk_init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  ai.commandPool = impl_->pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  SNELL_VK_TRY(vkAllocateCommandBuffers(impl_->device, &ai, &cmd), "one-shot command buffer");
  struct Free {
    VkDevice d;
    VkCommandPool p;
    VkCommandBuffer c;
    ~Free() { vkFreeCommandBuffers(d, p, 1, &c); }
  } free_on_exit{impl_->device, impl_->pool, cmd};
  VkCommandBufferBeginInfo bi =
      vk_init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  SNELL_VK_TRY(vkBeginCommandBuffer(cmd, &bi), "one-shot command buffer");
  record(cmd);
  SNELL_VK_TRY(vkEndCommandBuffer(cmd), "one-shot command buffer");
  VkCommandBufferSubmitInfo cbi =
      vk_init<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
  cbi.commandBuffer = cmd;
  VkSubmitInfo2 si = vk_init<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
  si.commandBufferInfoCount = 1;
  si.pCommandBufferInfos = &cbi;
  SNELL_VK_TRY(vkResetFences(impl_->device, 1, &impl_->fence), "one-shot submit");
  SNELL_VK_TRY(vkQueueSubmit2(impl_->queue, 1, &si, impl_->fence), "one-shot submit");
  SNELL_VK_TRY(vkWaitForFences(impl_->device, 1, &impl_->fence, VK_TRUE, UINT64_MAX),
               "waiting for a one-shot submit");
  return {};
}

Result<std::uint32_t> ContextState::find_memory_type(std::uint32_t type_bits,
                                                     VkMemoryPropertyFlags properties) const {
  const auto& mem = memory;
  for (std::uint32_t i = 0; i < mem.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) != 0 &&
        (mem.memoryTypes[i].propertyFlags & properties) == properties) {
      return i;
    }
  }
  return fail(ErrorCode::out_of_memory, "no memory type with properties " +
                                            std::to_string(properties) + " among allowed types " +
                                            std::to_string(type_bits));
}

} // namespace snell

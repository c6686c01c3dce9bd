#include "gpu_fixture.hpp"

#include <snell/buffer.hpp>

#include <cstdlib>
#include <cstring>
#include <vector>

using namespace snell;

TEST_CASE("context: headless creation picks a suitable device, validation on") {
  test::GpuFixture gpu;
  const DeviceInfo& info = gpu.ctx().device_info();
  MESSAGE("device: " << info.name << " (" << info.driver << ")");
  CHECK(info.suitable);
  CHECK(info.api_version >= VK_API_VERSION_1_3);
  CHECK(gpu.ctx().validation_enabled());
  CHECK(gpu.ctx().owns_device());
  auto devices = Context::enumerate_devices();
  REQUIRE(devices.has_value());
  CHECK_FALSE(devices->empty());
}

TEST_CASE("context: an unknown device name is a clear error listing the devices") {
  ContextDesc desc;
  desc.device = "no-such-gpu-xyz";
  auto ctx = Context::create(desc);
  REQUIRE_FALSE(ctx.has_value());
  CHECK(ctx.error().code == ErrorCode::no_device);
  CHECK(ctx.error().message.find("no-such-gpu-xyz") != std::string::npos);
  CHECK(ctx.error().message.find("devices:") != std::string::npos);
}

TEST_CASE("context: the validation messenger counts errors") {
  // A deliberate misuse (a zero-sized buffer bypassing Snell's own checks) must be caught.
  test::GpuFixture gpu;
  auto ci = VkBufferCreateInfo{};
  ci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  ci.size = 0; // invalid: size must be > 0
  ci.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  const std::uint32_t before = gpu.ctx().validation_error_count();
  const VkResult r = vkCreateBuffer(gpu.ctx().device(), &ci, nullptr, &buffer);
  CHECK(gpu.ctx().validation_error_count() > before);
  if (r == VK_SUCCESS && buffer != VK_NULL_HANDLE) {
    vkDestroyBuffer(gpu.ctx().device(), buffer, nullptr);
  }
  CHECK_FALSE(gpu.ctx().validation_messages().empty());
  // The errors were caused on purpose: the fixture must not fail the test for them.
  gpu.expect_validation_errors(gpu.ctx().validation_error_count());
}

TEST_CASE("context: adopting a host-created device") {
  // The host creates its own instance, device and queue with the features Snell needs.
  auto app = VkApplicationInfo{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.apiVersion = VK_API_VERSION_1_3;
  const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
  auto ici = VkInstanceCreateInfo{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = 1;
  ici.ppEnabledLayerNames = layers;
  VkInstance instance = VK_NULL_HANDLE;
  REQUIRE(vkCreateInstance(&ici, nullptr, &instance) == VK_SUCCESS);
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> pds(count);
  vkEnumeratePhysicalDevices(instance, &count, pds.data());
  REQUIRE(count > 0);
  VkPhysicalDevice pd = pds[0];
  for (VkPhysicalDevice candidate : pds) {
    VkPhysicalDeviceProperties p{};
    vkGetPhysicalDeviceProperties(candidate, &p);
    if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      pd = candidate;
    }
  }
  auto f13 = VkPhysicalDeviceVulkan13Features{};
  f13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  f13.dynamicRendering = VK_TRUE;
  f13.synchronization2 = VK_TRUE;
  auto f11 = VkPhysicalDeviceVulkan11Features{};
  f11.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES;
  f11.multiview = VK_TRUE;
  f11.pNext = &f13;
  auto f2 = VkPhysicalDeviceFeatures2{};
  f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  f2.features.shaderClipDistance = VK_TRUE;
  f2.pNext = &f11;
  const float priority = 1.0f;
  auto qci = VkDeviceQueueCreateInfo{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = 0;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  auto dci = VkDeviceCreateInfo{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.pNext = &f2;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  VkDevice device = VK_NULL_HANDLE;
  REQUIRE(vkCreateDevice(pd, &dci, nullptr, &device) == VK_SUCCESS);
  VkQueue queue = VK_NULL_HANDLE;
  vkGetDeviceQueue(device, 0, 0, &queue);
  {
    // With the host's feature chain: a chain lacking multiview is refused, naming it.
    f11.multiview = VK_FALSE;
    auto refused = Context::adopt(AdoptInfo{.instance = instance,
                                            .physical_device = pd,
                                            .device = device,
                                            .queue = queue,
                                            .queue_family = 0,
                                            .enabled_features = &f2});
    REQUIRE_FALSE(refused.has_value());
    CHECK(refused.error().code == ErrorCode::missing_feature);
    CHECK(refused.error().message.find("multiview") != std::string::npos);
    f11.multiview = VK_TRUE;
    auto ctx = Context::adopt(AdoptInfo{.instance = instance,
                                        .physical_device = pd,
                                        .device = device,
                                        .queue = queue,
                                        .queue_family = 0,
                                        .enabled_features = &f2});
    REQUIRE_MESSAGE(ctx.has_value(), ctx.error().message);
    CHECK_FALSE(ctx->owns_device());
    auto target = RenderTarget::create(*ctx, RenderTargetDesc{.width = 8,
                                                              .height = 4,
                                                              .color = ColorFormat::rgba8_unorm,
                                                              .debug_name = "adopted"});
    REQUIRE(target.has_value());
    const float clear[4] = {0.0f, 1.0f, 0.0f, 1.0f};
    REQUIRE(ctx->submit_and_wait([&](VkCommandBuffer cmd) {
      target->begin_rendering(cmd, clear);
      target->end_rendering(cmd);
    }));
    auto image = read_rgba8(*ctx, *target);
    REQUIRE(image.has_value());
    CHECK(image->rgba8[0] == 0);
    CHECK(image->rgba8[1] == 255);
  }
  // The context destroyed nothing of the host's: the host can still use and destroy them.
  CHECK(vkDeviceWaitIdle(device) == VK_SUCCESS);
  vkDestroyDevice(device, nullptr);
  vkDestroyInstance(instance, nullptr);
}

TEST_CASE("context: adopt rejects missing handles with a clear message") {
  auto ctx = Context::adopt(AdoptInfo{});
  REQUIRE_FALSE(ctx.has_value());
  CHECK(ctx.error().code == ErrorCode::invalid_argument);
  CHECK(ctx.error().message.find("AdoptInfo") != std::string::npos);
}

TEST_CASE("context: a submit_and_wait nested in its own callback is refused, not a deadlock") {
  test::GpuFixture gpu;
  Result<void> inner;
  auto outer = gpu.ctx().submit_and_wait(
      [&](VkCommandBuffer) { inner = gpu.ctx().submit_and_wait([](VkCommandBuffer) {}); });
  CHECK(outer.has_value());
  REQUIRE_FALSE(inner.has_value());
  CHECK(inner.error().message.find("inside its own callback") != std::string::npos);
  // The context is still usable afterwards.
  CHECK(gpu.ctx().submit_and_wait([](VkCommandBuffer) {}).has_value());
}

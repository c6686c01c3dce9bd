// Frame orchestration: offscreen hooks, main pass, debug thumbnails, timestamps, one submit.
#include <snell/frame.hpp>
#include <snell/math.hpp>
#include <snell/readback.hpp>

#include "context_impl.hpp"
#include "debug_overlay.hpp"
#include "vk_util.hpp"

#include <chrono>

namespace snell {

using detail::vk_init;

SceneView make_main_view(const CameraDesc& camera, std::uint32_t width, std::uint32_t height) {
  SceneView v;
  v.view = look_at(camera.eye, camera.target, camera.up);
  const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1u));
  v.proj = flip_clip_y(
      perspective(camera.yfov, aspect, camera.z_near, camera.z_far, DepthRange::zero_to_one));
  v.eye = camera.eye;
  v.layer_mask = layer::main;
  v.flip_front_face = needs_front_face_flip(v.view, v.proj);
  v.extent = {width, height};
  return v;
}

struct FrameRenderer::Impl {
  const Context::Impl* ctx = nullptr;
  FrameDesc desc;
  RenderTarget target;
  GpuTimer timer;
  detail::DebugOverlay overlay;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  ~Impl() {
    if (ctx == nullptr) {
      return;
    }
    vkDeviceWaitIdle(ctx->device);
    vkDestroyFence(ctx->device, fence, nullptr);
    vkDestroyCommandPool(ctx->device, pool, nullptr);
  }
};

FrameRenderer::FrameRenderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FrameRenderer::FrameRenderer(FrameRenderer&&) noexcept = default;
FrameRenderer& FrameRenderer::operator=(FrameRenderer&&) noexcept = default;
FrameRenderer::~FrameRenderer() = default;

Result<FrameRenderer> FrameRenderer::create(const Context& ctx, const FrameDesc& desc) {
  auto impl = std::make_unique<Impl>();
  impl->ctx = ctx.impl();
  impl->desc = desc;
  auto target = RenderTarget::create(
      ctx, RenderTargetDesc{desc.width, desc.height, desc.color, true, false, "frame output"});
  if (!target) {
    return target.error();
  }
  impl->target = std::move(*target);
  auto timer = GpuTimer::create(ctx, 64);
  if (!timer) {
    return timer.error();
  }
  impl->timer = std::move(*timer);
  if (desc.debug_targets) {
    auto overlay = detail::DebugOverlay::create(*ctx.impl(), impl->target.vk_color_format());
    if (!overlay) {
      return overlay.error();
    }
    impl->overlay = std::move(*overlay);
  }
  auto pci = vk_init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = ctx.queue_family();
  SNELL_VK_TRY(vkCreateCommandPool(ctx.device(), &pci, nullptr, &impl->pool), "frame command pool");
  auto ai = vk_init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  ai.commandPool = impl->pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  SNELL_VK_TRY(vkAllocateCommandBuffers(ctx.device(), &ai, &impl->cmd), "frame command buffer");
  auto fci = vk_init<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  SNELL_VK_TRY(vkCreateFence(ctx.device(), &fci, nullptr, &impl->fence), "frame fence");
  return FrameRenderer(std::move(impl));
}

Result<FrameStats> FrameRenderer::render(SceneSource& source, const CameraDesc& camera, float time,
                                         const FrameHooks& hooks) {
  Impl& s = *impl_;
  const auto start = std::chrono::steady_clock::now();
  SceneView view = make_main_view(camera, s.desc.width, s.desc.height);
  view.time = time;
  view.color_format = s.target.vk_color_format();
  view.depth_format = VK_FORMAT_D32_SFLOAT;
  VkCommandBuffer cmd = s.cmd;
  SNELL_VK_TRY(vkResetCommandBuffer(cmd, 0), "frame command buffer");
  auto bi = vk_init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  SNELL_VK_TRY(vkBeginCommandBuffer(cmd, &bi), "frame command buffer");
  s.timer.reset(cmd);
  s.timer.begin(cmd, "frame");
  if (hooks.offscreen) {
    hooks.offscreen(cmd, s.timer, view);
  }
  s.timer.begin(cmd, "main");
  const glm::vec3 clear_rgb(0.0f);
  const float clear[4] = {clear_rgb.r, clear_rgb.g, clear_rgb.b, 1.0f};
  s.target.begin_rendering(cmd, clear);
  source.draw_scene(cmd, view);
  if (hooks.in_main) {
    hooks.in_main(cmd, view);
  }
  s.target.end_rendering(cmd);
  s.timer.end(cmd);
  if (s.desc.debug_targets) {
    std::vector<DebugTarget> thumbs;
    if (hooks.debug_targets) {
      thumbs = hooks.debug_targets();
    }
    thumbs.push_back(DebugTarget{"depth", s.target.depth_view(), true});
    s.timer.begin(cmd, "debug_targets");
    s.target.begin_overlay(cmd);
    s.overlay.draw(cmd, thumbs, s.desc.width, s.desc.height);
    s.target.end_overlay(cmd);
    s.timer.end(cmd);
  }
  s.timer.end(cmd);
  SNELL_VK_TRY(vkEndCommandBuffer(cmd), "frame command buffer");
  auto cbi = vk_init<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
  cbi.commandBuffer = cmd;
  auto si = vk_init<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
  si.commandBufferInfoCount = 1;
  si.pCommandBufferInfos = &cbi;
  SNELL_VK_TRY(vkResetFences(s.ctx->device, 1, &s.fence), "frame fence");
  SNELL_VK_TRY(vkQueueSubmit2(s.ctx->queue, 1, &si, s.fence), "frame submit");
  SNELL_VK_TRY(vkWaitForFences(s.ctx->device, 1, &s.fence, VK_TRUE, UINT64_MAX), "frame wait");
  FrameStats stats;
  stats.cpu_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  auto passes = s.timer.read();
  if (!passes) {
    return passes.error();
  }
  stats.passes = std::move(*passes);
  for (const PassTime& p : stats.passes) {
    if (p.name == "frame") {
      stats.gpu_ms = p.ms;
    }
  }
  return stats;
}

Result<FrameStats> FrameRenderer::render(SceneSource& source, const CameraDesc& camera, float time,
                                         std::span<Effect* const> effects,
                                         const DirectionalLight& light) {
  FrameInfo info;
  info.time = time;
  info.light = light;
  FrameHooks hooks;
  hooks.offscreen = [&](VkCommandBuffer cmd, GpuTimer& timer, const SceneView& view) {
    info.main_view = view;
    info.timer = &timer;
    for (Effect* e : effects) {
      e->update(info);
      e->record_passes(cmd, source);
    }
  };
  hooks.in_main = [&](VkCommandBuffer cmd, const SceneView& /*view*/) {
    for (Effect* e : effects) {
      e->record_draw(cmd, info);
    }
  };
  hooks.debug_targets = [&] {
    std::vector<DebugTarget> out;
    for (Effect* e : effects) {
      for (const DebugTarget& t : e->debug_targets()) {
        out.push_back(t);
      }
    }
    return out;
  };
  auto stats = render(source, camera, time, hooks);
  if (!stats) {
    return stats;
  }
  for (Effect* e : effects) {
    if (const Error* err = e->error()) {
      return *err;
    }
  }
  return stats;
}

const RenderTarget& FrameRenderer::target() const {
  return impl_->target;
}

Result<Image> FrameRenderer::read_color() const {
  return detail::read_rgba8(*impl_->ctx, impl_->target, 0);
}

} // namespace snell

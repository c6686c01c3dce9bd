// Frame orchestration: offscreen hooks, main pass, debug thumbnails, timestamps, one submit.
#include <snell/frame.hpp>
#include <snell/math.hpp>
#include <snell/readback.hpp>
#include <snell/scene_renderer.hpp>
#include <snell/snapshot.hpp>

#include "context_impl.hpp"
#include "debug_overlay.hpp"
#include "runtime_internal.hpp"
#include "vk_util.hpp"

#include <algorithm>
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
  const Context* context = nullptr;
  const ContextState* ctx = nullptr;
  FrameDesc desc;
  RenderTarget target;
  GpuTimer timer;
  SceneSnapshot snapshot;
  detail::DebugOverlay overlay;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  std::uint64_t frame_index = 0;
  ~Impl() {
    if (ctx == nullptr) {
      return;
    }
    vkDeviceWaitIdle(ctx->device); // the renderer owns this frame's objects (not the host's)
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
  impl->context = &ctx;
  impl->ctx = context_state(ctx);
  impl->desc = desc;
  RenderTargetDesc td;
  td.width = desc.width;
  td.height = desc.height;
  td.color = desc.color;
  td.depth = true;
  td.debug_name = "frame output";
  auto target = RenderTarget::create(ctx, td);
  if (!target) {
    return target.error();
  }
  impl->target = std::move(*target);
  auto timer = GpuTimer::create(ctx, 64);
  if (!timer) {
    return timer.error();
  }
  impl->timer = std::move(*timer);
  auto snapshot = SceneSnapshot::create(ctx, SnapshotDesc{});
  if (!snapshot) {
    return snapshot.error();
  }
  impl->snapshot = std::move(*snapshot);
  if (desc.debug_targets) {
    auto overlay =
        detail::DebugOverlay::create(*context_state(ctx), impl->target.vk_color_format());
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

namespace {

/// "<type>: <message>", keeping the code and VkResult.
Error effect_error(const Effect& effect, const Error& e) {
  Error out = e;
  out.message = std::string(effect.type()) + ": " + e.message;
  return out;
}

} // namespace

Result<FrameStats> FrameRenderer::render(SceneSource& source, const CameraDesc& camera, float time,
                                         Span<Effect* const> effects,
                                         const DirectionalLight& light) {
  Impl& s = *impl_;
  const auto start = std::chrono::steady_clock::now();
  FrameStats stats;
  stats.frame_index = ++s.frame_index;
  SceneView view = make_main_view(camera, s.desc.width, s.desc.height);
  view.time = time;
  view.color_format = s.target.vk_color_format();
  view.depth_format = s.target.depth_format();
  FrameInfo info;
  info.time = time;
  info.frame_index = s.frame_index;
  info.main_view = view;
  info.light = light;
  info.timer = &s.timer;
  info.snapshot = &s.snapshot; // copied in phase 4 when an effect wants it

  // Phase 1: update. A failing effect is left out of the frame before anything is recorded.
  std::vector<Effect*> active;
  std::vector<int> hidden;
  for (Effect* e : effects) {
    if (auto r = e->update(info); !r) {
      stats.effect_errors.push_back(effect_error(*e, r.error()));
      continue;
    }
    active.push_back(e);
    for (const int object : e->drawn_objects()) {
      hidden.push_back(object);
    }
  }
  if (auto* renderer = dynamic_cast<SceneRenderer*>(&source)) {
    renderer->set_hidden_objects(hidden);
  }
  const auto drop = [&](Effect* e, const Error& error) {
    stats.effect_errors.push_back(effect_error(*e, error));
    active.erase(std::find(active.begin(), active.end(), e));
  };

  VkCommandBuffer cmd = s.cmd;
  SNELL_VK_TRY(vkResetCommandBuffer(cmd, 0), "frame command buffer");
  auto bi = vk_init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  SNELL_VK_TRY(vkBeginCommandBuffer(cmd, &bi), "frame command buffer");
  s.timer.reset(cmd);
  s.timer.begin(cmd, "frame");

  // Phase 2: offscreen passes.
  for (Effect* e : std::vector<Effect*>(active)) {
    if (auto r = e->record_passes(cmd, info, source); !r) {
      drop(e, r.error());
    }
  }

  // Phase 3: the opaque scene, without what the effects draw over it (Effect::replaced_objects:
  // still in their passes above, only not shaded twice here).
  if (auto* renderer = dynamic_cast<SceneRenderer*>(&source)) {
    std::vector<int> opaque_hidden = hidden;
    for (Effect* e : active) {
      for (const int object : e->replaced_objects()) {
        opaque_hidden.push_back(object);
      }
    }
    renderer->set_hidden_objects(opaque_hidden);
  }
  s.timer.begin(cmd, "opaque");
  const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  s.target.begin_rendering(cmd, clear);
  Result<void> scene_drawn = source.draw_scene(cmd, view);
  s.target.end_rendering(cmd);
  s.timer.end(cmd);

  // Phase 4: one snapshot for every effect that reads it.
  const bool wants_snapshot = std::any_of(active.begin(), active.end(),
                                          [](const Effect* e) { return e->wants_snapshot(); });
  if (wants_snapshot && scene_drawn) {
    s.timer.begin(cmd, "snapshot");
    SnapshotSource src;
    src.color = s.target.color_image();
    src.color_format = s.target.vk_color_format();
    src.color_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    src.depth = s.target.depth_image();
    src.depth_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    src.extent = {s.desc.width, s.desc.height};
    src.view_proj = view.proj * view.view;
    src.mips = std::any_of(active.begin(), active.end(),
                           [](const Effect* e) { return e->wants_snapshot_mips(); });
    // Only what the effects sample is copied ("scissor to what is sampled").
    bool first = true;
    for (const Effect* e : active) {
      if (e->wants_snapshot()) {
        src.region = first ? e->snapshot_region() : union_region(src.region, e->snapshot_region());
        first = false;
      }
    }
    auto r = s.snapshot.record(cmd, src, s.frame_index);
    s.timer.end(cmd);
    if (r) {
      stats.snapshot_copies = 1;
    } else {
      scene_drawn = r; // a snapshot that cannot be made fails the frame, like the scene
    }
  }

  // Phase 5: effect surfaces over the opaque colour and depth (no rendering when none is left:
  // the cheapest pass is the one not begun).
  if (!active.empty()) {
    s.timer.begin(cmd, "surfaces");
    s.target.continue_rendering(cmd);
    for (Effect* e : std::vector<Effect*>(active)) {
      if (auto r = e->record_draw(cmd, info); !r) {
        drop(e, r.error());
      }
    }
    s.target.end_rendering(cmd);
    s.timer.end(cmd);
  }

  // Phase 6: debug thumbnails of every effect's targets.
  if (s.desc.debug_targets) {
    std::vector<DebugTarget> thumbs;
    for (const Effect* e : active) {
      for (const DebugTarget& t : e->debug_targets()) {
        thumbs.push_back(t);
      }
    }
    if (stats.snapshot_copies > 0) {
      for (const DebugTarget& t : s.snapshot.debug_targets()) {
        thumbs.push_back(t);
      }
    }
    DebugTarget depth;
    depth.name = "depth";
    depth.kind = DebugKind::depth;
    depth.view = s.target.depth_view();
    thumbs.push_back(depth);
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
  if (!scene_drawn) {
    return scene_drawn.error();
  }
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

const RenderTarget& FrameRenderer::target() const {
  return impl_->target;
}

Result<Image> FrameRenderer::read_color() const {
  return detail::read_rgba8(*impl_->ctx, impl_->target, 0);
}

} // namespace snell

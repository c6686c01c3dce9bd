// `snell view` (see viewer.hpp for the frame loop and docs/viewer.md for the user's side).
#include "viewer.hpp"

#include "camera.hpp"
#include "commands.hpp"
#include "insight.hpp"
#include "panel.hpp"
#include "script.hpp"
#include "session.hpp"
#include "swapchain.hpp"
#include "thumbnails.hpp"
#include "vulkan_host.hpp"

#include <snell/frame.hpp>
#include <snell/readback.hpp>
#include <snell/snapshot.hpp>
#include <snell/toolkit/deferred_release.hpp>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace snell::viewer {
namespace {

using Clock = std::chrono::steady_clock;

/// Script time advances this much per frame (and per idle tick while minimised).
constexpr double kScriptStep = 1.0 / 60.0;

/// The first failure the Dear ImGui Vulkan backend reported (it has no error channel of its own).
VkResult g_imgui_vk_error = VK_SUCCESS;
void on_imgui_vk_result(VkResult r) {
  if (r != VK_SUCCESS && g_imgui_vk_error == VK_SUCCESS) {
    g_imgui_vk_error = r;
  }
}

Error vk_failure(const std::string& what, VkResult result) {
  Error e{ErrorCode::vulkan_error,
          what + " failed (VkResult " + std::to_string(static_cast<int>(result)) + ")"};
  e.vk_result = result;
  return e;
}

#define VIEWER_VK(call, what)                                                                      \
  do {                                                                                             \
    if (VkResult viewer_vk_result_ = (call); viewer_vk_result_ != VK_SUCCESS) {                    \
      return vk_failure(what, viewer_vk_result_);                                                  \
    }                                                                                              \
  } while (false)

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

double median(std::vector<double> v) {
  if (v.empty()) {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// A screenshot asked for: of the whole window (UI included) or of the scene view only.
struct Shot {
  std::string path;
  bool window = true;
};

/// What one frame in flight owns. Reused every kFramesInFlight frames, after its fence.
struct FrameSlot {
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;        ///< Signalled when the slot's last frame completed.
  VkSemaphore acquired = VK_NULL_HANDLE; ///< The swapchain image may be written.
  GpuTimer timer;
  bool timed = false;        ///< The timer holds a submitted frame's passes.
  double submitted_at = 0.0; ///< Seconds since start, when submitted.
  double cpu_ms = 0.0;       ///< CPU time between this frame's start and the previous one's.
  RenderTarget target;       ///< The scene: colour (rgba8_srgb) + depth, swapchain-sized.
  std::vector<Shot> shots;   ///< Screenshots of this slot's last frame, written after its fence.
  VkBuffer capture = VK_NULL_HANDLE; ///< Window screenshots: the swapchain image copied here.
  VkDeviceMemory capture_memory = VK_NULL_HANDLE;
  void* capture_mapped = nullptr;
  VkDeviceSize capture_size = 0;
  VkExtent2D capture_extent{0, 0};
  VkFormat capture_format = VK_FORMAT_UNDEFINED;
};

class Viewer {
public:
  Viewer(VulkanHost& host, cli::Session& session, const cli::RenderOptions& options,
         std::vector<ScriptAction> script)
      : host_(host), session_(session), options_(options), script_(std::move(script)),
        camera_(session.camera), show_thumbnails_(options.debug_targets) {}
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;
  ~Viewer();

  Result<void> init();
  /// Runs until the window closes, `quit`, --frames or a failure. Returns the exit code.
  int run();

private:
  // --- set-up ---------------------------------------------------------------------------------
  Result<void> create_render_pass();
  Result<void> init_imgui();
  Result<void> recreate_swapchain();
  // --- the loop -------------------------------------------------------------------------------
  /// One frame. Returns false (and no error) when nothing was drawn (out-of-date swapchain).
  Result<bool> frame();
  /// After the slot's fence: GPU times, screenshots of its last frame.
  Result<void> finish_slot(FrameSlot& slot);
  void run_script_actions();
  void apply(const ScriptAction& a);
  void handle_keys();
  void camera_input(float dt);
  void build_ui(const FrameSlot& slot);
  void add_effect(const std::string& name);
  void remove_marked_effects();
  Result<void> record(FrameSlot& slot, std::uint32_t image, const std::vector<Shot>& shots);
  [[nodiscard]] bool minimised() const;
  void report(const std::string& line) const;

  VulkanHost& host_;
  cli::Session& session_;
  const cli::RenderOptions& options_;
  ScriptPlayer script_;
  CameraController camera_;

  Swapchain swapchain_;
  SwapchainDesc swapchain_desc_;
  VkRenderPass ui_pass_ = VK_NULL_HANDLE;
  VkDescriptorPool imgui_pool_ = VK_NULL_HANDLE;
  bool imgui_glfw_ = false, imgui_vulkan_ = false, imgui_context_ = false;
  std::array<FrameSlot, kFramesInFlight> slots_;
  SceneSnapshot snapshot_;
  Thumbnails thumbnails_;
  PassHistory history_;
  DeferredRelease graveyard_{kFramesInFlight}; ///< Removed effects, until their frames finish.

  std::vector<EffectSlot> effects_;
  std::uint32_t next_id_ = 1;
  std::vector<std::string> effect_names_;
  int add_choice_ = 0;
  std::string add_error_;

  std::uint64_t frame_index_ = 0; ///< Frames recorded (FrameInfo::frame_index of the last).
  std::uint64_t ticks_ = 0;       ///< Script clock: frames drawn + idle ticks while minimised.
  double scene_time_ = 0.0;       ///< Interactive animation time (seconds).
  bool paused_ = false;
  bool show_ui_ = true;
  bool show_thumbnails_ = false;
  bool show_passes_ = true;
  bool quit_ = false;
  bool quit_after_frame_ = false; ///< A script's `quit`: after the frame of its time.
  std::uint64_t minimised_ticks_ = 0;
  std::uint32_t out_of_date_ = 0, suboptimal_ = 0; ///< What acquire and present reported.
  bool recreate_ = false;      ///< The swapchain must be recreated before the next frame.
  bool script_hidden_ = false; ///< A script's `minimize` hid the window (no window manager).
  std::uint64_t minimise_tick_ = 0;
  std::vector<Shot> pending_shots_; ///< For the next frame drawn.
  std::uint32_t screenshot_counter_ = 0;
  std::vector<int> pressed_keys_; ///< Key presses since the last frame (GLFW key codes).
  bool dragging_[3] = {false, false, false};
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_frame_ = Clock::now();
  std::vector<double> cpu_frame_ms_, gpu_frame_ms_, gpu_ui_ms_; ///< For the summary at exit.
  std::uint32_t resizes_ = 0;
  int exit_code_ = 0;
};

// --- set-up ------------------------------------------------------------------------------------

Result<void> Viewer::init() {
  effect_names_ = session_.registry.names();
  for (auto& e : session_.effects) {
    EffectSlot slot;
    slot.name = std::string(e->type());
    slot.id = next_id_++;
    slot.schema = session_.registry.schema(slot.name);
    slot.effect = std::move(e);
    effects_.push_back(std::move(slot));
  }
  session_.effects.clear();
  swapchain_desc_.mailbox = options_.present == "mailbox";

  // Callbacks before Dear ImGui's backend installs its own (it chains to these).
  glfwSetWindowUserPointer(host_.window, this);
  glfwSetFramebufferSizeCallback(host_.window, [](GLFWwindow* w, int, int) {
    if (auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(w))) {
      viewer->recreate_ = true;
    }
  });
  glfwSetKeyCallback(host_.window, [](GLFWwindow* w, int key, int, int action, int) {
    auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(w));
    if (viewer != nullptr && action == GLFW_PRESS) {
      viewer->pressed_keys_.push_back(key);
    }
  });

  // The swapchain first (its format makes the UI pass), then its framebuffers.
  auto made = swapchain_.create(host_, swapchain_desc_, VK_NULL_HANDLE);
  if (!made) {
    return made.error();
  }
  if (!*made) {
    // Opened minimised: learn the format from the surface once the window has a size.
    return fail(ErrorCode::unsupported, "the window opened with a 0 x 0 framebuffer");
  }
  SNELL_TRY(create_render_pass());
  SNELL_TRY(swapchain_.make_framebuffers(ui_pass_));

  const VkDevice d = host_.device;
  for (FrameSlot& s : slots_) {
    VkCommandPoolCreateInfo pci{};
    pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = host_.queue_family;
    VIEWER_VK(vkCreateCommandPool(d, &pci, nullptr, &s.pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo cai{};
    cai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    cai.commandPool = s.pool;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    VIEWER_VK(vkAllocateCommandBuffers(d, &cai, &s.cmd), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fci{};
    fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    fci.flags = VK_FENCE_CREATE_SIGNALED_BIT; // nothing to wait for before the first frame
    VIEWER_VK(vkCreateFence(d, &fci, nullptr, &s.fence), "vkCreateFence");
    VkSemaphoreCreateInfo sci{};
    sci.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VIEWER_VK(vkCreateSemaphore(d, &sci, nullptr, &s.acquired), "vkCreateSemaphore");
    SNELL_ASSIGN_OR_RETURN(s.timer, GpuTimer::create(*session_.ctx, 128));
  }
  SNELL_ASSIGN_OR_RETURN(
      snapshot_,
      SceneSnapshot::create(*session_.ctx, SnapshotDesc{.frames_in_flight = kFramesInFlight}));
  SNELL_TRY(thumbnails_.init(*session_.ctx, ui_pass_, kFramesInFlight));
  SNELL_TRY(init_imgui());
  std::printf("snell view: scene %s on %s, %ux%u, %s, %u frames in flight%s\n",
              options_.scene.c_str(), host_.device_name.c_str(), swapchain_.extent().width,
              swapchain_.extent().height, present_mode_name(swapchain_.present_mode()),
              kFramesInFlight, host_.validation ? ", validation on" : "");
  std::fflush(stdout);
  return {};
}

Result<void> Viewer::create_render_pass() {
  // The UI pass over the swapchain image: loads what the blit wrote, stays in
  // COLOR_ATTACHMENT_OPTIMAL; the frame's explicit barriers move it to PRESENT_SRC (or to
  // TRANSFER_SRC first for a window screenshot). Dear ImGui 1.86's Vulkan backend needs a
  // render pass (dynamic rendering came to it later).
  VkAttachmentDescription color{};
  color.format = swapchain_.format();
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  // Thumbnails sample effect targets that earlier passes of the frame wrote: those passes end
  // with barriers for fragment-shader reads (RenderTarget::end_rendering and friends).
  VkSubpassDependency deps[2]{};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].dstAccessMask = 0;
  VkRenderPassCreateInfo rpi{};
  rpi.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  rpi.attachmentCount = 1;
  rpi.pAttachments = &color;
  rpi.subpassCount = 1;
  rpi.pSubpasses = &subpass;
  rpi.dependencyCount = 2;
  rpi.pDependencies = deps;
  VIEWER_VK(vkCreateRenderPass(host_.device, &rpi, nullptr, &ui_pass_), "UI render pass");
  return {};
}

Result<void> Viewer::init_imgui() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  imgui_context_ = true;
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr; // no imgui.ini next to the user's files: every run starts the same
  ImGui::StyleColorsDark();
  // Dear ImGui's colours are sRGB values; the swapchain is sRGB, which encodes what is written:
  // write the linear equivalents so the panel looks as designed.
  ImGuiStyle& style = ImGui::GetStyle();
  for (ImVec4& c : style.Colors) {
    c = ImVec4(srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z), c.w);
  }
  style.WindowRounding = 4.0f;
  if (!ImGui_ImplGlfw_InitForVulkan(host_.window, true)) {
    return fail(ErrorCode::vulkan_error, "ImGui_ImplGlfw_InitForVulkan failed");
  }
  imgui_glfw_ = true;

  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo pi{};
  pi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pi.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pi.maxSets = 4;
  pi.poolSizeCount = 1;
  pi.pPoolSizes = &size;
  VIEWER_VK(vkCreateDescriptorPool(host_.device, &pi, nullptr, &imgui_pool_),
            "ImGui descriptor pool");
  ImGui_ImplVulkan_InitInfo ii{};
  ii.Instance = host_.instance;
  ii.PhysicalDevice = host_.physical_device;
  ii.Device = host_.device;
  ii.QueueFamily = host_.queue_family;
  ii.Queue = host_.queue;
  ii.DescriptorPool = imgui_pool_;
  // ImageCount sizes the backend's ring of vertex/index buffers, one per RenderDrawData call:
  // a buffer is rewritten kFramesInFlight frames later, after that frame's fence.
  ii.MinImageCount = kFramesInFlight;
  ii.ImageCount = kFramesInFlight;
  ii.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  ii.CheckVkResultFn = on_imgui_vk_result;
  if (!ImGui_ImplVulkan_Init(&ii, ui_pass_)) {
    return fail(ErrorCode::vulkan_error, "ImGui_ImplVulkan_Init failed");
  }
  imgui_vulkan_ = true;
  SNELL_TRY(session_.ctx->submit_and_wait(
      [](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); }));
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  if (g_imgui_vk_error != VK_SUCCESS) {
    return vk_failure("Dear ImGui's Vulkan backend", g_imgui_vk_error);
  }
  return {};
}

Result<void> Viewer::recreate_swapchain() {
  // The old swapchain's images may still be read by pending presents and its semaphores waited
  // on: the viewer owns this device, so it waits for the queue to drain (a resize is rare).
  VIEWER_VK(vkDeviceWaitIdle(host_.device), "vkDeviceWaitIdle (swapchain recreation)");
  for (FrameSlot& s : slots_) {
    SNELL_TRY(finish_slot(s)); // idle: every slot's frame is done
  }
  const VkFormat format = swapchain_.format();
  auto made = swapchain_.create(host_, swapchain_desc_, ui_pass_);
  if (!made) {
    return made.error();
  }
  if (!*made) {
    return {}; // minimised: try again when restored
  }
  if (swapchain_.format() != format) {
    return fail(ErrorCode::unsupported, "the surface's format changed");
  }
  recreate_ = false;
  ++resizes_;
  return {};
}

Viewer::~Viewer() {
  if (host_.device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(host_.device);
  }
  if (imgui_vulkan_) {
    ImGui_ImplVulkan_Shutdown();
  }
  if (imgui_glfw_) {
    ImGui_ImplGlfw_Shutdown();
  }
  if (imgui_context_) {
    ImGui::DestroyContext();
  }
  const VkDevice d = host_.device;
  for (FrameSlot& s : slots_) {
    if (s.capture != VK_NULL_HANDLE) {
      vkDestroyBuffer(d, s.capture, nullptr);
      vkFreeMemory(d, s.capture_memory, nullptr);
    }
    vkDestroySemaphore(d, s.acquired, nullptr);
    vkDestroyFence(d, s.fence, nullptr);
    vkDestroyCommandPool(d, s.pool, nullptr);
  }
  if (imgui_pool_ != VK_NULL_HANDLE) {
    vkDestroyDescriptorPool(d, imgui_pool_, nullptr);
  }
  swapchain_.destroy();
  if (ui_pass_ != VK_NULL_HANDLE) {
    vkDestroyRenderPass(d, ui_pass_, nullptr);
  }
  graveyard_.release_all(); // the device is idle
  // The remaining effects go before the session that they were created from.
  effects_.clear();
  glfwSetWindowUserPointer(host_.window, nullptr);
}

// --- the loop ----------------------------------------------------------------------------------

void Viewer::report(const std::string& line) const {
  std::fprintf(stderr, "snell view: %s\n", line.c_str());
}

bool Viewer::minimised() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(host_.window, &w, &h);
  return w == 0 || h == 0 || glfwGetWindowAttrib(host_.window, GLFW_ICONIFIED) == GLFW_TRUE ||
         glfwGetWindowAttrib(host_.window, GLFW_VISIBLE) == GLFW_FALSE;
}

int Viewer::run() {
  while (!quit_) {
    glfwPollEvents();
    if (glfwWindowShouldClose(host_.window) == GLFW_TRUE) {
      break;
    }
    run_script_actions();
    if (quit_) {
      break;
    }
    if (minimised()) {
      // Nothing to present to. Wait for events (a restore), a tick at a time so that a
      // script's clock goes on.
      if (quit_after_frame_) {
        break;
      }
      glfwWaitEventsTimeout(kScriptStep);
      ++ticks_;
      ++minimised_ticks_;
      last_frame_ = Clock::now();
      continue;
    }
    if (recreate_ || !swapchain_.valid()) {
      if (auto r = recreate_swapchain(); !r) {
        report(r.error().message);
        exit_code_ = 1;
        break;
      }
      if (!swapchain_.valid() || recreate_) {
        glfwWaitEventsTimeout(kScriptStep);
        continue;
      }
    }
    auto drawn = frame();
    if (!drawn) {
      report(drawn.error().message);
      exit_code_ = 1;
      break;
    }
    if (*drawn) {
      ++ticks_; // a script's clock: one step a frame drawn
      if ((options_.frames > 0 && frame_index_ >= options_.frames) || quit_after_frame_) {
        quit_ = true;
      }
    }
  }
  // Drain: every frame finished, every screenshot written.
  vkDeviceWaitIdle(host_.device);
  for (FrameSlot& s : slots_) {
    if (auto r = finish_slot(s); !r) {
      report(r.error().message);
      exit_code_ = 1;
    }
  }
  if (!pending_shots_.empty()) {
    report("quit before the frame of " + std::to_string(pending_shots_.size()) +
           " screenshot(s) was drawn");
    exit_code_ = 1;
  }
  std::printf("snell view: %llu frames, %u swapchain recreation(s) (out of date %u, suboptimal "
              "%u), %llu tick(s) minimised; median frame %.2f ms CPU, %.2f ms GPU scene passes + "
              "%.2f ms GPU blit and UI\n",
              static_cast<unsigned long long>(frame_index_), resizes_, out_of_date_, suboptimal_,
              static_cast<unsigned long long>(minimised_ticks_), median(cpu_frame_ms_),
              median(gpu_frame_ms_), median(gpu_ui_ms_));
  std::fflush(stdout);
  return exit_code_;
}

Result<void> Viewer::finish_slot(FrameSlot& s) {
  if (s.timed) {
    s.timed = false;
    auto passes = s.timer.read();
    if (!passes) {
      return passes.error();
    }
    history_.add(s.submitted_at, *passes, s.cpu_ms);
    for (const PassTime& p : *passes) {
      if (p.name == "frame") {
        gpu_frame_ms_.push_back(p.ms);
      } else if (p.name == "ui") {
        gpu_ui_ms_.push_back(p.ms);
      }
    }
    cpu_frame_ms_.push_back(s.cpu_ms);
  }
  for (const Shot& shot : s.shots) {
    Result<Image> image = Image{};
    if (shot.window) {
      Image img;
      img.name = shot.path;
      img.width = s.capture_extent.width;
      img.height = s.capture_extent.height;
      img.rgba8.resize(std::size_t{img.width} * img.height * 4);
      std::memcpy(img.rgba8.data(), s.capture_mapped, img.rgba8.size());
      const bool bgra = s.capture_format == VK_FORMAT_B8G8R8A8_SRGB;
      for (std::size_t i = 0; i < img.rgba8.size(); i += 4) {
        if (bgra) {
          std::swap(img.rgba8[i], img.rgba8[i + 2]);
        }
        img.rgba8[i + 3] = 255;
      }
      image = std::move(img);
    } else {
      image = read_rgba8(*session_.ctx, s.target);
    }
    if (!image) {
      report("screenshot " + shot.path + ": " + image.error().message);
      exit_code_ = 1;
      continue;
    }
    if (auto r = write_png(shot.path, *image); !r) {
      report("screenshot: " + r.error().message);
      exit_code_ = 1;
      continue;
    }
    std::printf("snell view: wrote %s (%ux%u, %s)\n", shot.path.c_str(), image->width,
                image->height, shot.window ? "window" : "scene");
    std::fflush(stdout);
  }
  s.shots.clear();
  return {};
}

void Viewer::run_script_actions() {
  for (const ScriptAction& a : script_.due(static_cast<double>(ticks_) * kScriptStep)) {
    apply(a);
  }
  // Without a window manager (Xvfb) iconifying does nothing: after a few ticks the script's
  // `minimize` hides the window instead, which is what a window manager does to an iconified
  // window.
  if (minimise_tick_ != 0 && ticks_ >= minimise_tick_ + 3 && !minimised()) {
    glfwHideWindow(host_.window);
    script_hidden_ = true;
    minimise_tick_ = 0;
  }
}

void Viewer::apply(const ScriptAction& a) {
  using Kind = ScriptAction::Kind;
  const std::string where = "script line " + std::to_string(a.line) + ": ";
  switch (a.kind) {
  case Kind::set: {
    const std::vector<std::size_t> targets = find_instances(effects_, a.effect);
    if (targets.empty()) {
      report(where + "set: no effect '" + a.effect + "' in the viewer");
      exit_code_ = 1;
      return;
    }
    for (const std::size_t i : targets) {
      EffectSlot& slot = effects_[i];
      const ParamSpec* spec = slot.schema != nullptr ? slot.schema->find(a.key) : nullptr;
      if (spec == nullptr) {
        report(where + "set: " + slot.name + " has no parameter '" + a.key + "'");
        exit_code_ = 1;
        return;
      }
      // The panel's code path: the text as typed, then Effect::set_param, whose refusal the
      // panel shows under the parameter (a script only reports it: refusals are expected).
      auto value = text_to_value(*slot.schema, *spec, a.value);
      Result<void> r = value ? apply_param(slot, a.key, *value) : Result<void>(value.error());
      if (!value) {
        slot.errors[a.key] = value.error().message;
      }
      std::printf("snell view: set %s.%s=%s: %s\n", instance_label(effects_, i).c_str(),
                  a.key.c_str(), a.value.c_str(), r ? "ok" : r.error().message.c_str());
      std::fflush(stdout);
    }
    return;
  }
  case Kind::add: {
    const std::size_t before = effects_.size();
    add_effect(a.effect);
    if (effects_.size() == before) {
      exit_code_ = 1; // add_effect reported why
    }
    return;
  }
  case Kind::remove: {
    std::vector<std::size_t> targets = find_instances(effects_, a.effect);
    if (targets.empty()) {
      report(where + "remove: no effect '" + a.effect + "' in the viewer");
      exit_code_ = 1;
      return;
    }
    effects_[a.effect.find('@') == std::string::npos ? targets.back() : targets.front()].remove =
        true;
    remove_marked_effects();
    return;
  }
  case Kind::camera:
    camera_.look_at(a.a, a.b);
    return;
  case Kind::orbit:
    camera_.orbit(glm::radians(a.a.x), glm::radians(a.a.y));
    return;
  case Kind::pan:
    camera_.pan(a.a.x, a.a.y);
    return;
  case Kind::zoom:
    camera_.zoom(a.a.x);
    return;
  case Kind::fly:
    camera_.fly(a.a.x, a.a.y, a.a.z);
    return;
  case Kind::reset_camera:
    camera_.reset();
    return;
  case Kind::screenshot:
    pending_shots_.push_back(Shot{a.path, a.window});
    return;
  case Kind::debug_targets:
    show_thumbnails_ = a.on;
    return;
  case Kind::panel:
    show_ui_ = a.on;
    return;
  case Kind::resize:
    glfwSetWindowSize(host_.window, static_cast<int>(a.width), static_cast<int>(a.height));
    return;
  case Kind::minimize:
    glfwIconifyWindow(host_.window);
    minimise_tick_ = std::max<std::uint64_t>(ticks_, 1);
    return;
  case Kind::restore:
    minimise_tick_ = 0;
    if (script_hidden_) {
      glfwShowWindow(host_.window);
      script_hidden_ = false;
    }
    glfwRestoreWindow(host_.window);
    return;
  case Kind::quit:
    quit_after_frame_ = true; // the frame of this time is still drawn (and captured)
    return;
  }
}

void Viewer::add_effect(const std::string& name) {
  auto created = session_.registry.create(name, session_.effect_info);
  if (!created) {
    add_error_ = created.error().message;
    report("add " + name + ": " + add_error_);
    return;
  }
  add_error_.clear();
  EffectSlot slot;
  slot.name = name;
  slot.id = next_id_++;
  slot.schema = session_.registry.schema(name);
  slot.effect = std::move(*created);
  effects_.push_back(std::move(slot));
}

void Viewer::remove_marked_effects() {
  for (auto it = effects_.begin(); it != effects_.end();) {
    if (!it->remove) {
      ++it;
      continue;
    }
    // Frames up to the one being built (its thumbnails may show the effect's targets) may still
    // use it: destroyed once they finished. A probe leaves the directory now, so that no later
    // frame's glass samples its cube (dynamic_cubemap publishes with its own address, which is
    // its Effect's: single inheritance).
    session_.probes.withdraw(it->effect.get());
    graveyard_.retire(frame_index_ + 1, std::move(it->effect));
    it = effects_.erase(it);
  }
}

void Viewer::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  for (const int key : pressed_keys_) {
    if (key == GLFW_KEY_F1) {
      show_ui_ = !show_ui_;
    } else if (key == GLFW_KEY_F3) {
      show_thumbnails_ = !show_thumbnails_;
    } else if (key == GLFW_KEY_F12) {
      char name[64];
      std::snprintf(name, sizeof(name), "snell-view-%03u.png", ++screenshot_counter_);
      pending_shots_.push_back(Shot{name, true});
    } else if (io.WantCaptureKeyboard) {
      continue; // typing into the panel
    } else if (key == GLFW_KEY_R || key == GLFW_KEY_HOME) {
      camera_.reset();
    } else if (key == GLFW_KEY_P) {
      paused_ = !paused_;
    } else if (key == GLFW_KEY_ESCAPE) {
      quit_ = true;
    }
  }
  pressed_keys_.clear();
}

void Viewer::camera_input(float dt) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = std::max(io.DisplaySize.y, 1.0f);
  const bool shift = io.KeyShift;
  for (int b = 0; b < 3; ++b) {
    if (ImGui::IsMouseClicked(b) && !io.WantCaptureMouse) {
      dragging_[b] = true; // a drag that starts over the scene belongs to the camera
    }
    if (!io.MouseDown[b]) {
      dragging_[b] = false;
    }
  }
  const float dx = io.MouseDelta.x, dy = io.MouseDelta.y;
  const bool moved = dx != 0.0f || dy != 0.0f;
  if (moved && std::isfinite(dx) && std::isfinite(dy)) {
    constexpr float kRadiansPerPixel = 0.005f;
    if ((dragging_[0] && shift) || dragging_[2]) {
      camera_.pan(dx / height, -dy / height); // the scene follows the mouse
    } else if (dragging_[0]) {
      camera_.orbit(-dx * kRadiansPerPixel, dy * kRadiansPerPixel);
    } else if (dragging_[1]) {
      camera_.look(-dx * kRadiansPerPixel, -dy * kRadiansPerPixel);
    }
  }
  if (io.MouseWheel != 0.0f && !io.WantCaptureMouse) {
    camera_.zoom(io.MouseWheel);
  }
  if (!io.WantCaptureKeyboard) {
    GLFWwindow* w = host_.window;
    auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    const float speed = camera_.fly_speed() * dt * (shift ? 4.0f : 1.0f);
    const float right = down(GLFW_KEY_D) - down(GLFW_KEY_A);
    const float up = down(GLFW_KEY_E) - down(GLFW_KEY_Q);
    const float forward = down(GLFW_KEY_W) - down(GLFW_KEY_S);
    if (right != 0.0f || up != 0.0f || forward != 0.0f) {
      camera_.fly(right * speed, up * speed, forward * speed);
    }
  }
}

void Viewer::build_ui(const FrameSlot& slot) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!show_ui_) {
    return;
  }
  const float margin = 8.0f;
  ImGui::SetNextWindowPos(ImVec2(margin, margin), ImGuiCond_Once);
  ImGui::SetNextWindowSize(ImVec2(390.0f, std::max(io.DisplaySize.y - 2.0f * margin, 100.0f)),
                           ImGuiCond_Once);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("Snell")) {
    ImGui::Text("%s on %s", options_.scene.c_str(), host_.device_name.c_str());
    ImGui::TextDisabled("%ux%u, %s, %u frames in flight", swapchain_.extent().width,
                        swapchain_.extent().height, present_mode_name(swapchain_.present_mode()),
                        kFramesInFlight);
    const std::vector<float> cpu = history_.cpu_series();
    const std::vector<float> gpu = history_.series("frame");
    ImGui::Text("%.2f ms CPU, %.2f ms GPU a frame", cpu.empty() ? 0.0f : cpu.back(),
                gpu.empty() ? 0.0f : gpu.back());
    ImGui::Checkbox("debug targets (F3)", &show_thumbnails_);
    ImGui::SameLine();
    ImGui::Checkbox("GPU passes", &show_passes_);
    ImGui::Checkbox("pause time (P)", &paused_);
    ImGui::SameLine();
    if (ImGui::Button("reset camera (R)")) {
      camera_.reset();
    }
    ImGui::SameLine();
    if (ImGui::Button("screenshot")) {
      char name[64];
      std::snprintf(name, sizeof(name), "snell-view-%03u.png", ++screenshot_counter_);
      pending_shots_.push_back(Shot{name, true});
    }
    const CameraDesc& c = camera_.camera();
    ImGui::TextDisabled("eye %.2f,%.2f,%.2f  target %.2f,%.2f,%.2f", c.eye.x, c.eye.y, c.eye.z,
                        c.target.x, c.target.y, c.target.z);
    if (ImGui::CollapsingHeader("Keys and mouse")) {
      ImGui::TextUnformatted("left drag: orbit   right drag: look (fly)\n"
                             "middle or shift + left drag: pan\n"
                             "wheel: zoom   W A S D: fly   Q E: down, up\n"
                             "shift: 4x faster   R / Home: scene camera\n"
                             "P: pause time   F1: hide UI   F3: debug targets\n"
                             "F12: screenshot (PNG)   Esc: quit");
    }
    ImGui::Separator();
    ImGui::TextUnformatted("Effects");
    const std::string add = draw_add_effect(effect_names_, add_choice_);
    if (!add.empty()) {
      add_effect(add);
    }
    if (!add_error_.empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", add_error_.c_str());
    }
    for (std::size_t i = 0; i < effects_.size(); ++i) {
      draw_effect_section(effects_[i], instance_label(effects_, i));
    }
  }
  ImGui::End();

  if (show_passes_) {
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 330.0f - margin, margin), ImGuiCond_Once);
    ImGui::SetNextWindowSizeConstraints(ImVec2(330.0f, 0.0f), ImVec2(330.0f, FLT_MAX));
    ImGui::SetNextWindowBgAlpha(0.75f);
    if (ImGui::Begin("GPU passes", &show_passes_, ImGuiWindowFlags_AlwaysAutoResize)) {
      history_.draw();
    }
    ImGui::End();
  }

  if (show_thumbnails_) {
    std::vector<DebugTarget> targets;
    for (const EffectSlot& e : effects_) {
      for (const DebugTarget& t : e.effect->debug_targets()) {
        targets.push_back(t);
      }
    }
    for (const DebugTarget& t : snapshot_.debug_targets()) {
      targets.push_back(t);
    }
    DebugTarget depth; // this frame's own depth (the slot's target)
    depth.name = "depth";
    depth.kind = DebugKind::depth;
    depth.view = slot.target ? slot.target.depth_view() : VK_NULL_HANDLE;
    depth.width = slot.target.width();
    depth.height = slot.target.height();
    targets.push_back(depth);
    ImGui::SetNextWindowPos(ImVec2(400.0f + margin, io.DisplaySize.y - 220.0f), ImGuiCond_Once);
    ImGui::SetNextWindowSize(
        ImVec2(std::max(io.DisplaySize.x - 410.0f - 2.0f * margin, 200.0f), 210.0f),
        ImGuiCond_Once);
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("Debug targets (F3)", &show_thumbnails_)) {
      const float thumb_h = 120.0f;
      for (std::size_t i = 0; i < targets.size(); ++i) {
        const DebugTarget& t = targets[i];
        const float aspect = t.height > 0 ? float(t.width) / float(t.height) : 1.0f;
        const float thumb_w = std::clamp(thumb_h * aspect, 40.0f, 3.0f * thumb_h);
        if (i > 0) {
          const float next_x = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x;
          if (next_x + thumb_w < ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) {
            ImGui::SameLine();
          }
        }
        ImGui::BeginGroup();
        ImGui::TextUnformatted(t.name.c_str());
        thumbnails_.image(t, thumb_w, thumb_h);
        ImGui::EndGroup();
        if (ImGui::IsItemHovered()) {
          ImGui::SetTooltip("%s: %ux%u, layer %u, mip %u", t.name.c_str(), t.width, t.height,
                            t.layer, t.mip);
        }
      }
    }
    ImGui::End();
  }
}

Result<bool> Viewer::frame() {
  const VkDevice d = host_.device;
  FrameSlot& s = slots_[(frame_index_ + 1) % kFramesInFlight];
  // The slot's previous frame (two back) must be finished before its objects are reused.
  VIEWER_VK(vkWaitForFences(d, 1, &s.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  SNELL_TRY(finish_slot(s));

  std::uint32_t image = 0;
  const VkResult acquired =
      vkAcquireNextImageKHR(d, swapchain_.handle(), UINT64_MAX, s.acquired, VK_NULL_HANDLE, &image);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    ++out_of_date_;
    recreate_ = true; // the semaphore was not signalled: nothing to undo
    return false;
  }
  if (acquired == VK_SUBOPTIMAL_KHR) {
    ++suboptimal_;
    recreate_ = true; // still usable: draw this frame, recreate after presenting it
  } else if (acquired != VK_SUCCESS) {
    return vk_failure("vkAcquireNextImageKHR", acquired);
  }

  // --- the frame's scene target, at the swapchain's size ------------------------------------
  const VkExtent2D extent = swapchain_.extent();
  if (!s.target || s.target.width() != extent.width || s.target.height() != extent.height) {
    RenderTargetDesc td;
    td.width = extent.width;
    td.height = extent.height;
    td.color = ColorFormat::rgba8_srgb; // as `snell render`'s output
    td.depth = true;
    td.debug_name = "viewer frame";
    SNELL_ASSIGN_OR_RETURN(s.target, RenderTarget::create(*session_.ctx, td));
  }

  // --- UI and input (before anything of the frame is recorded: the panel changes effects) ---
  const auto now = Clock::now();
  const double cpu_ms = std::chrono::duration<double, std::milli>(now - last_frame_).count();
  const float dt = !script_.empty() ? static_cast<float>(kScriptStep)
                                    : std::min(static_cast<float>(cpu_ms / 1000.0), 0.25f);
  last_frame_ = now;
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  {
    // The UI is laid out for the image it is drawn into: the swapchain's extent, which can lead
    // GLFW's idea of the window size by a frame while a resize is under way.
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 scale = io.DisplayFramebufferScale;
    io.DisplaySize = ImVec2(static_cast<float>(extent.width) / std::max(scale.x, 1e-3f),
                            static_cast<float>(extent.height) / std::max(scale.y, 1e-3f));
  }
  ImGui::NewFrame();
  handle_keys();
  camera_input(dt);
  std::vector<Shot> shots = std::move(pending_shots_);
  pending_shots_.clear();
  thumbnails_.begin_frame(static_cast<std::uint32_t>((frame_index_ + 1) % kFramesInFlight), s.cmd,
                          swapchain_.extent());
  build_ui(s);
  ImGui::Render();
  remove_marked_effects();

  ++frame_index_;
  graveyard_.collect(frame_index_); // effects removed two frames ago are no longer in use
  if (!paused_) {
    scene_time_ += dt;
  }
  s.cpu_ms = cpu_ms;
  SNELL_TRY(record(s, image, shots));

  // --- submit and present -----------------------------------------------------------------
  VkSemaphoreSubmitInfo wait{};
  wait.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO;
  wait.semaphore = s.acquired;
  wait.stageMask = VK_PIPELINE_STAGE_2_BLIT_BIT; // the first write of the image: the blit
  VkSemaphoreSubmitInfo signal{};
  signal.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO;
  signal.semaphore = swapchain_.rendered(image);
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cbi{};
  cbi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
  cbi.commandBuffer = s.cmd;
  VkSubmitInfo2 si{};
  si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2;
  si.waitSemaphoreInfoCount = 1;
  si.pWaitSemaphoreInfos = &wait;
  si.commandBufferInfoCount = 1;
  si.pCommandBufferInfos = &cbi;
  si.signalSemaphoreInfoCount = 1;
  si.pSignalSemaphoreInfos = &signal;
  VIEWER_VK(vkResetFences(d, 1, &s.fence), "vkResetFences");
  VIEWER_VK(vkQueueSubmit2(host_.queue, 1, &si, s.fence), "vkQueueSubmit2");
  s.timed = true;
  s.submitted_at = std::chrono::duration<double>(Clock::now() - start_).count();
  s.shots = std::move(shots);

  const VkSemaphore rendered = swapchain_.rendered(image);
  const VkSwapchainKHR swapchain = swapchain_.handle();
  VkPresentInfoKHR pi{};
  pi.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
  pi.waitSemaphoreCount = 1;
  pi.pWaitSemaphores = &rendered;
  pi.swapchainCount = 1;
  pi.pSwapchains = &swapchain;
  pi.pImageIndices = &image;
  const VkResult presented = vkQueuePresentKHR(host_.queue, &pi);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    ++(presented == VK_SUBOPTIMAL_KHR ? suboptimal_ : out_of_date_);
    recreate_ = true;
  } else if (presented != VK_SUCCESS) {
    return vk_failure("vkQueuePresentKHR", presented);
  }
  return true;
}

Result<void> Viewer::record(FrameSlot& s, std::uint32_t image, const std::vector<Shot>& shots) {
  const VkCommandBuffer cmd = s.cmd;
  const VkExtent2D extent = swapchain_.extent();
  // Scripted frames show scene time ticks / 60 exactly (as `snell render --time`); interactive
  // ones the wall clock (P pauses it).
  const float time =
      !script_.empty() ? static_cast<float>(ticks_) / 60.0f : static_cast<float>(scene_time_);
  SceneView view = make_main_view(camera_.camera(), extent.width, extent.height);
  view.time = time;
  view.color_format = s.target.vk_color_format();
  view.depth_format = s.target.depth_format();
  FrameInfo info;
  info.time = time;
  info.frame_index = frame_index_;
  info.main_view = view;
  info.light = session_.scene.light;
  info.timer = &s.timer;
  info.snapshot = &snapshot_;

  // Phase 1: update. A failing effect is left out of this frame (its section says why).
  std::vector<EffectSlot*> active;
  std::vector<int> hidden;
  for (EffectSlot& e : effects_) {
    if (auto r = e.effect->update(info); !r) {
      if (e.frame_error != r.error().message) {
        report(e.name + ": " + r.error().message);
      }
      e.frame_error = r.error().message;
      continue;
    }
    e.frame_error.clear();
    active.push_back(&e);
    for (const int object : e.effect->drawn_objects()) {
      hidden.push_back(object);
    }
  }
  session_.renderer->set_hidden_objects(hidden);
  const auto drop = [&](EffectSlot* e, const Error& error) {
    e->frame_error = error.message;
    report(e->name + ": " + error.message);
    active.erase(std::find(active.begin(), active.end(), e));
  };

  VIEWER_VK(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VIEWER_VK(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
  s.timer.reset(cmd);
  s.timer.begin(cmd, "frame");

  // Phase 2: the effects' offscreen passes.
  for (EffectSlot* e : std::vector<EffectSlot*>(active)) {
    if (auto r = e->effect->record_passes(cmd, info, *session_.renderer); !r) {
      drop(e, r.error());
    }
  }
  // Phase 3: the opaque scene (black clear under the sky, as FrameRenderer), without what the
  // effects cover in the main view (Effect::replaced_objects; kept in their passes above).
  std::vector<int> opaque_hidden = hidden;
  for (const EffectSlot* e : active) {
    for (const int object : e->effect->replaced_objects()) {
      opaque_hidden.push_back(object);
    }
  }
  session_.renderer->set_hidden_objects(opaque_hidden);
  s.timer.begin(cmd, "opaque");
  const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  s.target.begin_rendering(cmd, clear);
  Result<void> scene_drawn = session_.renderer->draw_scene(cmd, view);
  s.target.end_rendering(cmd);
  s.timer.end(cmd);
  // Phase 4: one snapshot for every effect that reads it.
  const bool wants_snapshot = std::any_of(active.begin(), active.end(), [](const EffectSlot* e) {
    return e->effect->wants_snapshot();
  });
  if (wants_snapshot && scene_drawn) {
    s.timer.begin(cmd, "snapshot");
    SnapshotSource src;
    src.color = s.target.color_image();
    src.color_format = s.target.vk_color_format();
    src.color_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    src.depth = s.target.depth_image();
    src.depth_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    src.extent = extent;
    src.view_proj = view.proj * view.view;
    src.mips = std::any_of(active.begin(), active.end(),
                           [](const EffectSlot* e) { return e->effect->wants_snapshot_mips(); });
    bool first = true;
    for (const EffectSlot* e : active) {
      if (e->effect->wants_snapshot()) {
        const VkRect2D region = e->effect->snapshot_region();
        src.region = first ? region : union_region(src.region, region);
        first = false;
      }
    }
    scene_drawn = snapshot_.record(cmd, src, frame_index_);
    s.timer.end(cmd);
  }
  // Phase 5: the effects' surfaces over the opaque colour and depth.
  if (!active.empty() && scene_drawn) {
    s.timer.begin(cmd, "surfaces");
    s.target.continue_rendering(cmd);
    for (EffectSlot* e : std::vector<EffectSlot*>(active)) {
      if (auto r = e->effect->record_draw(cmd, info); !r) {
        drop(e, r.error());
      }
    }
    s.target.end_rendering(cmd);
    s.timer.end(cmd);
  }
  s.timer.end(cmd); // frame

  // --- Presentation: the scene to the swapchain image, then the UI on top. ----------------
  s.timer.begin(cmd, "ui");
  const VkImage swap_image = swapchain_.image(image);
  constexpr VkPipelineStageFlags2 kReadStages =
      VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
      VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_TRANSFER_BIT;
  VkImageMemoryBarrier2 to_blit[2]{};
  for (VkImageMemoryBarrier2& b : to_blit) {
    b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  }
  // The scene colour: finished (SHADER_READ_ONLY, made visible to the read stages) -> source.
  to_blit[0].srcStageMask = kReadStages;
  to_blit[0].dstStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  to_blit[0].dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
  to_blit[0].oldLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  to_blit[0].newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  to_blit[0].image = s.target.color_image();
  // The swapchain image: contents discarded; after the acquire semaphore's wait (BLIT stage).
  to_blit[1].srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  to_blit[1].dstStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  to_blit[1].dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_blit[1].oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  to_blit[1].newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  to_blit[1].image = swap_image;
  VkDependencyInfo dep{};
  dep.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
  dep.imageMemoryBarrierCount = 2;
  dep.pImageMemoryBarriers = to_blit;
  vkCmdPipelineBarrier2(cmd, &dep);
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {static_cast<std::int32_t>(extent.width),
                        static_cast<std::int32_t>(extent.height), 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.dstOffsets[1] = blit.srcOffsets[1];
  vkCmdBlitImage(cmd, s.target.color_image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, swap_image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
  VkImageMemoryBarrier2 after_blit[2] = {to_blit[0], to_blit[1]};
  // The scene colour back to its finished state (the target's layout protocol).
  after_blit[0].srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  after_blit[0].srcAccessMask = VK_ACCESS_2_NONE;
  after_blit[0].dstStageMask = kReadStages;
  after_blit[0].dstAccessMask = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT;
  after_blit[0].oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  after_blit[0].newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  // The swapchain image: the blit's writes, then the UI pass loads and draws.
  after_blit[1].srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  after_blit[1].srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  after_blit[1].dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  after_blit[1].dstAccessMask =
      VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  after_blit[1].oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  after_blit[1].newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  dep.pImageMemoryBarriers = after_blit;
  vkCmdPipelineBarrier2(cmd, &dep);

  VkRenderPassBeginInfo rpb{};
  rpb.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  rpb.renderPass = ui_pass_;
  rpb.framebuffer = swapchain_.framebuffer(image);
  rpb.renderArea = {{0, 0}, extent};
  vkCmdBeginRenderPass(cmd, &rpb, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);

  // Window screenshots: the presented image, UI included, copied into the slot's buffer.
  const bool capture =
      swapchain_.can_capture() &&
      std::any_of(shots.begin(), shots.end(), [](const Shot& shot) { return shot.window; });
  VkImageMemoryBarrier2 to_present = after_blit[1];
  to_present.srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  to_present.srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  to_present.dstStageMask = VK_PIPELINE_STAGE_2_NONE; // the present waits on the semaphore
  to_present.dstAccessMask = VK_ACCESS_2_NONE;
  to_present.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  to_present.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  if (capture) {
    const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * 4;
    if (s.capture_size < size) {
      if (s.capture != VK_NULL_HANDLE) {
        vkDestroyBuffer(host_.device, s.capture, nullptr); // the slot's last frame is done
        vkFreeMemory(host_.device, s.capture_memory, nullptr);
        s.capture = VK_NULL_HANDLE;
      }
      VkBufferCreateInfo bci{};
      bci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
      bci.size = size;
      bci.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
      VIEWER_VK(vkCreateBuffer(host_.device, &bci, nullptr, &s.capture), "capture buffer");
      VkMemoryRequirements req{};
      vkGetBufferMemoryRequirements(host_.device, s.capture, &req);
      std::uint32_t type = 0;
      SNELL_ASSIGN_OR_RETURN(
          type, host_.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                          VK_MEMORY_PROPERTY_HOST_COHERENT_BIT));
      VkMemoryAllocateInfo mai{};
      mai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
      mai.allocationSize = req.size;
      mai.memoryTypeIndex = type;
      VIEWER_VK(vkAllocateMemory(host_.device, &mai, nullptr, &s.capture_memory), "capture memory");
      VIEWER_VK(vkBindBufferMemory(host_.device, s.capture, s.capture_memory, 0), "capture memory");
      VIEWER_VK(vkMapMemory(host_.device, s.capture_memory, 0, VK_WHOLE_SIZE, 0, &s.capture_mapped),
                "capture memory");
      s.capture_size = size;
    }
    VkImageMemoryBarrier2 to_copy = to_present;
    to_copy.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    to_copy.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
    to_copy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &to_copy;
    vkCmdPipelineBarrier2(cmd, &dep);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, swap_image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, s.capture, 1,
                           &region);
    // The copy must reach the host before the fence: a buffer barrier to HOST reads.
    VkBufferMemoryBarrier2 to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2;
    to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    to_host.srcQueueFamilyIndex = to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.buffer = s.capture;
    to_host.size = VK_WHOLE_SIZE;
    to_present.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    to_present.srcAccessMask = VK_ACCESS_2_NONE;
    to_present.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    dep.bufferMemoryBarrierCount = 1;
    dep.pBufferMemoryBarriers = &to_host;
    dep.pImageMemoryBarriers = &to_present;
    vkCmdPipelineBarrier2(cmd, &dep);
    s.capture_extent = extent;
    s.capture_format = swapchain_.format();
  } else {
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &to_present;
    vkCmdPipelineBarrier2(cmd, &dep);
  }
  s.timer.end(cmd); // ui
  VIEWER_VK(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  if (g_imgui_vk_error != VK_SUCCESS) {
    return vk_failure("Dear ImGui's Vulkan backend", g_imgui_vk_error);
  }
  if (!scene_drawn) {
    return scene_drawn.error();
  }
  return {};
}

} // namespace
} // namespace snell::viewer

namespace snell::cli {

int run_view(const RenderOptions& options) {
  using namespace snell::viewer;
  // The script first: a bad line is an argument error (exit 2) before any window opens.
  std::vector<ScriptAction> script;
  if (!options.script.empty()) {
    auto loaded = load_script(options.script);
    if (!loaded) {
      std::fprintf(stderr, "snell: %s\n", loaded.error().message.c_str());
      return 2;
    }
    script = std::move(*loaded);
    // Its `set` lines against the schemas, as --set is checked.
    EffectRegistry registry;
    if (auto r = register_builtin_effects(registry); !r) {
      std::fprintf(stderr, "snell: %s\n", r.error().message.c_str());
      return 1;
    }
    for (const ScriptAction& a : script) {
      if (a.kind != ScriptAction::Kind::set && a.kind != ScriptAction::Kind::add) {
        continue;
      }
      const std::string name = split_instance(a.effect).first;
      const ParamSchema* schema = registry.schema(name);
      const std::string where = options.script + ":" + std::to_string(a.line) + ": ";
      if (schema == nullptr) {
        std::fprintf(stderr, "snell: %sunknown effect '%s'\n", where.c_str(), name.c_str());
        return 2;
      }
      if (a.kind == ScriptAction::Kind::set) {
        const ParamSpec* spec = schema->find(a.key);
        if (spec == nullptr) {
          std::fprintf(stderr, "snell: %s%s has no parameter '%s'; valid: %s\n", where.c_str(),
                       name.c_str(), a.key.c_str(), schema->key_list().c_str());
          return 2;
        }
        if (auto v = text_to_value(*schema, *spec, a.value); !v) {
          std::fprintf(stderr, "snell: %s%s\n", where.c_str(), v.error().message.c_str());
          return 2;
        }
      }
    }
  }

  ValidationLog log; // outlives the instance: the layer reports leaks at its destruction
  int code = 1;
  {
    VulkanHost host;
    std::unique_ptr<Session> session;
    {
      SessionHooks hooks;
      hooks.frame_renderer = false;
      hooks.frames_in_flight = kFramesInFlight;
      hooks.make_context = [&]() -> Result<Context> {
        // The arguments and the scene are fine: open the window and adopt its device.
        HostOptions ho;
        ho.width = options.width;
        ho.height = options.height;
        ho.title = "snell view - " + options.scene;
        ho.validation = options.validation || [] {
          const char* v = std::getenv("SNELL_VALIDATION");
          return v != nullptr && (std::strcmp(v, "1") == 0 || std::strcmp(v, "true") == 0 ||
                                  std::strcmp(v, "on") == 0);
        }();
        ho.device = options.device;
        SNELL_TRY(host.init(ho, log));
        AdoptInfo adopt;
        adopt.instance = host.instance;
        adopt.physical_device = host.physical_device;
        adopt.device = host.device;
        adopt.queue = host.queue;
        adopt.queue_family = host.queue_family;
        adopt.enabled_features = host.enabled_features();
        return Context::adopt(adopt);
      };
      int exit_code = 1;
      auto opened = open_session(options, exit_code, hooks);
      if (!opened) {
        std::fprintf(stderr, "snell: %s\n", opened.error().message.c_str());
        return exit_code;
      }
      session = std::move(*opened);
    }
    {
      Viewer viewer(host, *session, options, std::move(script));
      if (auto r = viewer.init(); !r) {
        std::fprintf(stderr, "snell view: %s\n", r.error().message.c_str());
        code = 1;
      } else {
        code = viewer.run();
      }
    }
    session.reset(); // effects, renderer and Snell's context before the host's device
  }
  const std::lock_guard<std::mutex> lock(log.mutex);
  for (const std::string& m : log.messages) {
    std::fprintf(stderr, "%s\n", m.c_str());
  }
  if (log.performance > 0) {
    std::fprintf(stderr, "snell view: %u validation performance warning(s) (reported only)\n",
                 log.performance.load());
  }
  if (log.failures() > 0) {
    std::fprintf(stderr, "snell view: %u validation error(s), %u warning(s)\n", log.errors.load(),
                 log.warnings.load());
    return 1;
  }
  return code;
}

} // namespace snell::cli

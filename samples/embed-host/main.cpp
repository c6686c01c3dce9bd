// `snell-embed-host`: a host application that owns its Vulkan instance, device, queue, images,
// command buffer and scene, and embeds Snell's water effect into its own frame. It uses none of
// the runtime's context helpers, render targets or frame orchestration. docs/embedding.md walks
// through it.
//
//   snell-embed-host --out FILE.png [--size WxH] [--frames N] [--validation] [--check]
#include "host_scene.hpp"
#include "host_vulkan.hpp"

#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/math.hpp>
#include <snell/readback.hpp>
#include <snell/snapshot.hpp>

// Sanitizer builds only: lets LeakSanitizer attribute the Vulkan driver's own leaks.
#include "../../tests/sanitizers/pin_vulkan_libraries.hpp"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

constexpr const char* kUsage =
    "usage: snell-embed-host --out FILE.png [--size WxH] [--frames N] [--validation] [--check]\n"
    "  --out FILE.png  where to write the last frame (required)\n"
    "  --size WxH      output size in pixels, each 1..16384 (default 640x360)\n"
    "  --frames N      frames to render, time advancing 1/60 s each (default 1)\n"
    "  --validation    Vulkan validation layer; any error fails (also SNELL_VALIDATION=1)\n"
    "  --check         verify that the water changes a pixel on its surface and not the sky\n"
    "                  (renders the last frame again without the effect; exit 3 on failure)\n"
    "Environment: SNELL_DEVICE=lavapipe|gpu|<name substring> picks the device.\n";

struct Options {
  std::string out;
  std::uint32_t width = 640;
  std::uint32_t height = 360;
  std::uint32_t frames = 1;
  bool validation = false;
  bool check = false;
  bool help = false;
};

bool parse_uint(std::string_view text, std::uint32_t& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && !text.empty();
}

/// Parses the command line; returns the one-line error, or nothing.
std::optional<std::string> parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const auto value = [&]() -> std::optional<std::string_view> {
      if (i + 1 >= argc) {
        return std::nullopt;
      }
      return std::string_view(argv[++i]);
    };
    if (arg == "--help" || arg == "-h") {
      o.help = true;
    } else if (arg == "--validation") {
      o.validation = true;
    } else if (arg == "--check") {
      o.check = true;
    } else if (arg == "--out") {
      const auto v = value();
      if (!v || v->empty()) {
        return "--out needs a file name";
      }
      o.out = std::string(*v);
    } else if (arg == "--size") {
      const auto v = value();
      const std::size_t x = v ? v->find('x') : std::string_view::npos;
      if (x == std::string_view::npos || !parse_uint(v->substr(0, x), o.width) ||
          !parse_uint(v->substr(x + 1), o.height) || o.width < 1 || o.width > 16384 ||
          o.height < 1 || o.height > 16384) {
        return "--size expects WxH with each in 1..16384, got '" +
               std::string(v ? *v : std::string_view()) + "'";
      }
    } else if (arg == "--frames") {
      const auto v = value();
      if (!v || !parse_uint(*v, o.frames) || o.frames < 1 || o.frames > 100000) {
        return "--frames expects an integer in 1..100000, got '" +
               std::string(v ? *v : std::string_view()) + "'";
      }
    } else {
      return "unknown argument '" + std::string(arg) + "' (see --help)";
    }
  }
  if (!o.help && o.out.empty()) {
    return "--out FILE.png is required";
  }
  return std::nullopt;
}

bool env_flag(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr &&
         (std::strcmp(v, "1") == 0 || std::strcmp(v, "true") == 0 || std::strcmp(v, "on") == 0);
}

/// Begins the host's main rendering on its own images: `clear` clears colour and depth (the
/// opaque phase), otherwise both are loaded (the surfaces phase, after the snapshot).
void begin_main_rendering(VkCommandBuffer cmd, const embed::HostFrame& frame, bool clear) {
  VkRenderingAttachmentInfo color{};
  color.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
  color.imageView = frame.color_view;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  std::memcpy(color.clearValue.color.float32, embed::HostScene::kSkyClear, sizeof(float) * 4);
  VkRenderingAttachmentInfo depth{};
  depth.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
  depth.imageView = frame.depth_view;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE; // the snapshot and the surfaces read it
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{};
  rendering.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
  rendering.renderArea = {{0, 0}, frame.extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
  // Standard, positive-height viewport: the projection is y-flipped (docs/conventions.md).
  const VkViewport viewport{0.0f, 0.0f, float(frame.extent.width), float(frame.extent.height),
                            0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, frame.extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

/// Records one frame into the host's command buffer in Snell's frame phases: the effect's
/// offscreen passes (outside any rendering), the host's opaque scene on its own images, the
/// scene snapshot (one call), the effect's surface over the loaded colour and depth, then a
/// copy of the colour image into the readback buffer. Snell errors are returned.
snell::Result<void> record_frame(embed::HostFrame& frame, embed::HostScene& scene,
                                 snell::SceneSnapshot& snapshot, snell::Effect* effect,
                                 const snell::FrameInfo& info) {
  const VkCommandBuffer cmd = frame.cmd;
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  embed::vk_check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");

  // 1. The effect's passes: they render the host's scene into the effect's own targets (which
  //    they begin and end themselves) and leave them in SHADER_READ_ONLY_OPTIMAL.
  snell::Result<void> result;
  if (effect != nullptr) {
    result = effect->record_passes(cmd, info, scene);
  }

  // 2. The host's own attachments: UNDEFINED (contents discarded) -> attachment layouts, after
  //    the previous frame's copy read the colour and its depth tests used the depth.
  VkImageMemoryBarrier2 to_attachment[2]{};
  for (auto& b : to_attachment) {
    b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  }
  to_attachment[0].srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  to_attachment[0].dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  to_attachment[0].dstAccessMask =
      VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  to_attachment[0].newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  to_attachment[0].image = frame.color;
  to_attachment[0].subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  const VkPipelineStageFlags2 tests =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  to_attachment[1].srcStageMask = tests;
  to_attachment[1].srcAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  to_attachment[1].dstStageMask = tests;
  to_attachment[1].dstAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                   VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  to_attachment[1].newLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  to_attachment[1].image = frame.depth;
  to_attachment[1].subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
  VkDependencyInfo dep{};
  dep.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
  dep.imageMemoryBarrierCount = 2;
  dep.pImageMemoryBarriers = to_attachment;
  vkCmdPipelineBarrier2(cmd, &dep);

  // 3. Opaque: the host's scene on its own attachments (sky-coloured clear).
  begin_main_rendering(cmd, frame, true);
  if (auto r = scene.draw_scene(cmd, info.main_view); !r && result) {
    result = r;
  }
  vkCmdEndRendering(cmd);

  // 4. Snapshot: one call copies colour (with mips) and depth for every effect that reads it.
  if (effect != nullptr && effect->wants_snapshot() && result) {
    snell::SnapshotSource source;
    source.color = frame.color;
    source.color_format = embed::HostFrame::kColorFormat;
    source.color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    source.depth = frame.depth;
    source.depth_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    source.extent = frame.extent;
    source.view_proj = info.main_view.proj * info.main_view.view;
    source.mips = effect->wants_snapshot_mips(); // water reads level 0 only
    result = snapshot.record(cmd, source, info.frame_index);
  }

  // 5. Surfaces: the water over the loaded colour and depth.
  begin_main_rendering(cmd, frame, false);
  if (effect != nullptr && result) {
    result = effect->record_draw(cmd, info); // same formats as EffectCreateInfo
  }
  vkCmdEndRendering(cmd);

  // 4. Colour -> readback buffer -> host.
  VkImageMemoryBarrier2 to_copy{};
  to_copy.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
  to_copy.srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  to_copy.srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  to_copy.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  to_copy.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
  to_copy.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  to_copy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  to_copy.srcQueueFamilyIndex = to_copy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_copy.image = frame.color;
  to_copy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &to_copy;
  vkCmdPipelineBarrier2(cmd, &dep);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {frame.extent.width, frame.extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, frame.color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, frame.readback, 1,
                         &region);
  VkBufferMemoryBarrier2 to_host{};
  to_host.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2;
  to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  to_host.srcQueueFamilyIndex = to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_host.buffer = frame.readback;
  to_host.size = VK_WHOLE_SIZE;
  dep.imageMemoryBarrierCount = 0;
  dep.bufferMemoryBarrierCount = 1;
  dep.pBufferMemoryBarriers = &to_host;
  vkCmdPipelineBarrier2(cmd, &dep);
  embed::vk_check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  return result;
}

/// Prints a Snell error and returns exit code 1.
int snell_failure(const char* what, const snell::Error& error) {
  std::fprintf(stderr, "snell-embed-host: %s: %s\n", what, error.message.c_str());
  return 1;
}

struct Probe {
  int x = 0, y = 0;
  int difference = 0; ///< Largest |with - without| over R, G, B.
  std::uint8_t with[3]{}, without[3]{};
};

Probe probe(const std::vector<std::uint8_t>& with, const std::vector<std::uint8_t>& without,
            std::uint32_t width, int x, int y) {
  Probe p;
  p.x = x;
  p.y = y;
  const std::size_t i = (std::size_t(y) * width + std::size_t(x)) * 4;
  for (int c = 0; c < 3; ++c) {
    p.with[c] = with[i + c];
    p.without[c] = without[i + c];
    p.difference = std::max(p.difference, std::abs(int(with[i + c]) - int(without[i + c])));
  }
  return p;
}

void print_probe(const char* name, const Probe& p, const char* expectation) {
  std::printf("check: %s pixel (%d, %d): with water (%d, %d, %d), without (%d, %d, %d), "
              "difference %d (%s)\n",
              name, p.x, p.y, p.with[0], p.with[1], p.with[2], p.without[0], p.without[1],
              p.without[2], p.difference, expectation);
}

int run(const Options& o, embed::ValidationLog& log) {
  // Declaration order is destruction order reversed: the effect goes first, then the host's
  // frame and scene, then Snell's context, and the host's device last.
  embed::HostDevice device;
  const char* device_env = std::getenv("SNELL_DEVICE");
  device.init({o.validation, device_env != nullptr ? device_env : ""}, log);

  // --- Snell adopts the host's objects (and destroys none of them). ---------------------------
  snell::AdoptInfo adopt;
  adopt.instance = device.instance;
  adopt.physical_device = device.physical_device;
  adopt.device = device.device;
  adopt.queue = device.queue;
  adopt.queue_family = device.queue_family;
  auto context = snell::Context::adopt(adopt);
  if (!context) {
    return snell_failure("Context::adopt", context.error());
  }

  // --- The host's scene and frame (raw Vulkan). -----------------------------------------------
  const embed::PoolWater water;
  embed::HostScene scene;
  scene.init(device, water);
  embed::HostFrame frame;
  frame.init(device, {o.width, o.height});
  // One scene snapshot for all effects of a frame (this host waits for each frame: 1 in flight).
  auto snapshot =
      snell::SceneSnapshot::create(*context, snell::SnapshotDesc{.frames_in_flight = 1});
  if (!snapshot) {
    return snell_failure("SceneSnapshot::create", snapshot.error());
  }

  // --- The water effect, created by name through the host's registry. -------------------------
  snell::EffectRegistry registry;
  if (auto r = snell::register_builtin_effects(registry); !r) {
    return snell_failure("register_builtin_effects", r.error());
  }
  snell::EffectCreateInfo create_info;
  create_info.context = &*context;
  create_info.color_format = embed::HostFrame::kColorFormat; // the host's main rendering
  create_info.depth_format = embed::HostFrame::kDepthFormat;
  create_info.frames_in_flight = 1; // this host waits for each frame before the next
  create_info.scene = nullptr;      // no snell::Scene: parameters come from set_param
  auto created = registry.create("water", create_info);
  if (!created) {
    return snell_failure("create water", created.error());
  }
  std::unique_ptr<snell::Effect> effect = std::move(*created);
  // Its water rectangle is the host's pool opening (the schema lists every parameter).
  for (const auto& [key, value] : std::vector<std::pair<std::string, snell::ParamValue>>{
           {"height", water.height}, {"center", water.center}, {"size", water.size}}) {
    if (auto r = effect->set_param(key, value); !r) {
      return snell_failure("set_param", r.error());
    }
  }

  // --- The camera: Snell's Y convention (flipped projection, standard viewport, depth [0,1]).
  const glm::vec3 eye{0.0f, 3.6f, 8.0f};
  const glm::vec3 target{0.0f, -0.2f, -2.0f};
  snell::FrameInfo info;
  info.main_view.view = snell::look_at(eye, target, {0.0f, 1.0f, 0.0f});
  info.main_view.proj =
      snell::flip_clip_y(snell::perspective(glm::radians(50.0f), float(o.width) / float(o.height),
                                            0.1f, 200.0f, snell::DepthRange::zero_to_one));
  info.main_view.eye = eye;
  info.main_view.layer_mask = snell::layer::main;
  info.main_view.flip_front_face = false; // det(view) = +1 and y flipped: nothing mirrored
  info.main_view.extent = frame.extent;
  info.main_view.color_format = embed::HostFrame::kColorFormat;
  info.main_view.depth_format = embed::HostFrame::kDepthFormat;
  info.light = scene.light;
  info.timer = nullptr;
  info.snapshot = &*snapshot; // this host records a snapshot when an effect wants one

  auto render = [&](bool with_effect) -> int {
    ++info.frame_index;
    if (with_effect) {
      // Creates or resizes its targets; replaced ones are destroyed frames_in_flight later.
      if (auto r = effect->update(info); !r) {
        return snell_failure("water update", r.error());
      }
    }
    auto recorded =
        record_frame(frame, scene, *snapshot, with_effect ? effect.get() : nullptr, info);
    frame.submit_and_wait(); // the command buffer is complete even when a Snell call failed
    if (!recorded) {
      return snell_failure("record_frame", recorded.error());
    }
    return 0;
  };
  for (std::uint32_t i = 0; i < o.frames; ++i) {
    info.time = float(i) / 60.0f;
    info.main_view.time = info.time;
    if (int rc = render(true); rc != 0) {
      return rc;
    }
  }
  const std::vector<std::uint8_t> with_water = frame.pixels();
  if (auto r =
          snell::write_png(o.out, snell::Image{"embed-host", o.width, o.height, with_water, true});
      !r) {
    return snell_failure("write_png", r.error());
  }
  std::printf("snell-embed-host: %ux%u, %u frame(s) on %s -> %s\n", o.width, o.height, o.frames,
              device.device_name.c_str(), o.out.c_str());
  if (!o.check) {
    return 0;
  }

  // --- --check: the same frame without the effect; the water must show where it projects. ---
  if (int rc = render(false); rc != 0) {
    return rc;
  }
  const std::vector<std::uint8_t> without = frame.pixels();
  const glm::vec4 clip = info.main_view.proj * info.main_view.view *
                         glm::vec4(water.center.x, water.height, water.center.y, 1.0f);
  const glm::vec2 uv = snell::project_to_uv(clip, snell::ClipConvention::vulkan);
  if (!(clip.w > 0.0f) || !(uv.x >= 0.0f && uv.x < 1.0f && uv.y >= 0.0f && uv.y < 1.0f)) {
    std::printf("check: FAILED: the water centre projects outside the image (uv %.3f, %.3f)\n",
                uv.x, uv.y);
    return 3;
  }
  const Probe surface =
      probe(with_water, without, o.width, int(uv.x * float(o.width)), int(uv.y * float(o.height)));
  const Probe sky = probe(with_water, without, o.width, int(o.width / 2), 0); // top row centre
  constexpr int kMinWaterDifference = 16; // 8-bit sRGB steps; the water changes far more
  print_probe("water centre", surface, "must be >= 16");
  print_probe("sky", sky, "must be 0");
  if (surface.difference < kMinWaterDifference || sky.difference != 0) {
    std::printf("check: FAILED\n");
    return 3;
  }
  std::printf("check: passed\n");
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  Options options;
  if (auto error = parse(argc, argv, options)) {
    std::fprintf(stderr, "snell-embed-host: %s\n", error->c_str());
    return 2;
  }
  if (options.help) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  options.validation = options.validation || env_flag("SNELL_VALIDATION");
  embed::ValidationLog log; // outlives the instance: the layer reports leaks at its destruction
  int code = 1;
  try {
    code = run(options, log);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell-embed-host: %s\n", e.what());
    code = 1;
  }
  if (log.errors > 0) {
    std::fprintf(stderr, "snell-embed-host: %u validation error(s):\n", log.errors.load());
    for (const std::string& m : log.messages) {
      std::fprintf(stderr, "  %s\n", m.c_str());
    }
    return 1;
  }
  return code;
}

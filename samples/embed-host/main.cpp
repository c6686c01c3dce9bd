// `snell-embed-host`: a host application that owns its Vulkan instance, device, queue, images,
// command buffer and scene, and embeds Snell's water effect into its own frame, with a
// dynamic_cubemap probe whose published cube the host samples in its own chrome material
// (snell/probe.glsl). It uses none of the runtime's context helpers, render targets or frame
// orchestration. docs/embedding.md walks through it.
//
//   snell-embed-host --out FILE.png [--size WxH] [--frames N] [--validation] [--check]
#include "host_scene.hpp"
#include "host_vulkan.hpp"

#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/math.hpp>
#include <snell/probe_directory.hpp>
#include <snell/readback.hpp>
#include <snell/snapshot.hpp>

// Sanitizer builds only: lets LeakSanitizer attribute the Vulkan driver's own leaks.
#include "../../tests/sanitizers/pin_vulkan_libraries.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
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
    "  --check         verify that the water changes a pixel on its surface and not the sky,\n"
    "                  and that the chrome ball shows what the probe's capture predicts\n"
    "                  (renders the last frame again without the effects; exit 3 on failure)\n"
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

/// The Snell effects of one frame (nullptr: left out of this frame, as --check's second render
/// leaves both out).
struct FrameEffects {
  /// dynamic_cubemap: its passes capture the scene around the chrome ball and publish the cube
  /// in `probes`; its record_draw is never called: the host draws the ball itself.
  snell::Effect* probe = nullptr;
  snell::Effect* water = nullptr; ///< Passes and surface.
  const snell::ProbeDirectory* probes = nullptr;
};

/// Records one frame into the host's command buffer in Snell's frame phases: the effects'
/// offscreen passes (outside any rendering; the probe first, then the host's chrome material is
/// pointed at its cube, then the water), the host's opaque scene on its own images, the scene
/// snapshot (one call), the water's surface over the loaded colour and depth, then a copy of the
/// colour image into the readback buffer. Snell errors are returned.
snell::Result<void> record_frame(embed::HostFrame& frame, embed::HostScene& scene,
                                 snell::SceneSnapshot& snapshot, const FrameEffects& effects,
                                 const snell::FrameInfo& info) {
  const VkCommandBuffer cmd = frame.cmd;
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  embed::vk_check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");

  // 1. The effects' passes: they render the host's scene into the effects' own targets (which
  //    they begin and end themselves) and leave them in SHADER_READ_ONLY_OPTIMAL.
  //    a. The probe: six passes of the scene around the chrome ball (which has no `captured`
  //       bit, so it is not in them), then it publishes its cube in the probe directory.
  snell::Result<void> result;
  if (effects.probe != nullptr) {
    result = effects.probe->record_passes(cmd, info, scene);
  }
  //    b. The host's chrome material takes the cube published this frame: its descriptor set
  //       is rewritten if the cube changed, before anything in this command buffer binds it.
  //       Without a probe (or when its passes failed) the ball is drawn flat.
  const snell::ProbeView* probe = nullptr;
  if (effects.probe != nullptr && effects.probes != nullptr && result) {
    probe = effects.probes->nearest(scene.chrome_ball().center);
  }
  scene.use_probe(probe, info.frame_index);
  //    c. The water: its reflection pass draws the chrome ball too, shaded from that cube.
  if (effects.water != nullptr && result) {
    result = effects.water->record_passes(cmd, info, scene);
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
  if (effects.water != nullptr && effects.water->wants_snapshot() && result) {
    snell::SnapshotSource source;
    source.color = frame.color;
    source.color_format = embed::HostFrame::kColorFormat;
    source.color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    source.depth = frame.depth;
    source.depth_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    source.extent = frame.extent;
    source.view_proj = info.main_view.proj * info.main_view.view;
    source.mips = effects.water->wants_snapshot_mips(); // water reads level 0 only
    result = snapshot.record(cmd, source, info.frame_index);
  }

  // 5. Surfaces: the water over the loaded colour and depth. Not the probe's record_draw: it
  //    would draw the effect's own sphere, and the host's chrome ball is that sphere.
  begin_main_rendering(cmd, frame, false);
  if (effects.water != nullptr && result) {
    result = effects.water->record_draw(cmd, info); // same formats as EffectCreateInfo
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

/// One pixel of two renders: with the effects and without them.
struct PixelPair {
  int x = 0, y = 0;
  int difference = 0; ///< Largest |with - without| over R, G, B.
  std::uint8_t with[3]{}, without[3]{};
};

PixelPair compare_pixel(const std::vector<std::uint8_t>& with,
                        const std::vector<std::uint8_t>& without, std::uint32_t width, int x,
                        int y) {
  PixelPair p;
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

void print_pixel(const char* name, const PixelPair& p, const char* expectation) {
  std::printf("check: %s pixel (%d, %d): with effects (%d, %d, %d), without (%d, %d, %d), "
              "difference %d (%s)\n",
              name, p.x, p.y, p.with[0], p.with[1], p.with[2], p.without[0], p.without[1],
              p.without[2], p.difference, expectation);
}

/// The 8-bit sRGB encoding of a linear value, as the host's R8G8B8A8_SRGB target stores it.
int to_srgb8(float linear) {
  const float v = std::clamp(linear, 0.0f, 1.0f);
  const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return int(std::lround(s * 255.0f));
}

/// What the host's scene shows from `origin` along the unit `dir` in a view with `layer_mask`:
/// the nearest box object, shaded as shaders/host_scene.frag shades it, or the sky
/// (host_common.glsl's host_sky). The CPU twin of a probe's capture, for --check.
struct Seen {
  std::string what;
  glm::vec3 color{0.0f}; ///< Linear RGB.
};
Seen trace_scene(const embed::HostScene& scene, glm::vec3 origin, glm::vec3 dir,
                 std::uint32_t layer_mask) {
  Seen seen;
  float nearest = INFINITY;
  for (const embed::HostScene::Object& o : scene.objects()) {
    if (o.chrome || (o.layers & layer_mask) == 0) {
      continue;
    }
    // Slab test: entry distance and the axis entered through.
    float t_in = -INFINITY, t_out = INFINITY;
    int axis = 0;
    for (int a = 0; a < 3 && t_in <= t_out; ++a) {
      if (dir[a] == 0.0f) { // parallel to this slab: inside it or a miss
        t_out = origin[a] >= o.lo[a] && origin[a] <= o.hi[a] ? t_out : -INFINITY;
        continue;
      }
      const float t0 = (o.lo[a] - origin[a]) / dir[a];
      const float t1 = (o.hi[a] - origin[a]) / dir[a];
      if (std::min(t0, t1) > t_in) {
        t_in = std::min(t0, t1);
        axis = a;
      }
      t_out = std::min(t_out, std::max(t0, t1));
    }
    if (t_in > 0.0f && t_in <= t_out && t_in < nearest) {
      nearest = t_in;
      glm::vec3 n(0.0f);
      n[axis] = dir[axis] > 0.0f ? -1.0f : 1.0f;
      const glm::vec3 hit = origin + t_in * dir;
      const glm::ivec3 cell = glm::ivec3(glm::floor(hit - 0.01f * n));
      const float tile = ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0f : 1.0f - o.color.a;
      const snell::DirectionalLight& l = scene.light;
      const float diffuse = std::max(glm::dot(n, -glm::normalize(l.direction)), 0.0f);
      seen.what = o.name;
      seen.color = glm::vec3(o.color) * tile * (l.ambient + l.color * l.intensity * diffuse);
    }
  }
  if (nearest == INFINITY) {
    const glm::vec3 horizon{0.62f, 0.74f, 0.90f}, zenith{0.16f, 0.34f, 0.72f},
        ground{0.30f, 0.28f, 0.25f};
    seen.what = "the sky";
    seen.color = dir.y >= 0.0f ? glm::mix(horizon, zenith, std::sqrt(dir.y))
                               : glm::mix(horizon, ground, std::sqrt(-dir.y));
  }
  return seen;
}

int run(const Options& o, embed::ValidationLog& log) {
  // Declaration order is destruction order reversed: the effects go first, then the probe
  // directory they publish in, the host's frame and scene, then Snell's context, and the host's
  // device last.
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
  constexpr std::uint32_t kFramesInFlight = 1; // this host waits for each frame before the next
  const embed::PoolWater water;
  embed::HostScene scene;
  scene.init(device, water, kFramesInFlight);
  embed::HostFrame frame;
  frame.init(device, {o.width, o.height});
  // One scene snapshot for all effects of a frame.
  auto snapshot = snell::SceneSnapshot::create(
      *context, snell::SnapshotDesc{.frames_in_flight = kFramesInFlight});
  if (!snapshot) {
    return snell_failure("SceneSnapshot::create", snapshot.error());
  }
  // Where probes publish their cubes (after their record_passes); the host's chrome material
  // looks its probe up here. Must outlive the effects.
  snell::ProbeDirectory probes;

  // --- The effects, created by name through the host's registry. ------------------------------
  snell::EffectRegistry registry;
  if (auto r = snell::register_builtin_effects(registry); !r) {
    return snell_failure("register_builtin_effects", r.error());
  }
  snell::EffectCreateInfo create_info;
  create_info.context = &*context;
  create_info.color_format = embed::HostFrame::kColorFormat; // the host's main rendering
  create_info.depth_format = embed::HostFrame::kDepthFormat;
  create_info.frames_in_flight = kFramesInFlight;
  create_info.scene = nullptr; // no snell::Scene: parameters come from set_param
  create_info.probes = &probes;
  using Params = std::vector<std::pair<std::string, snell::ParamValue>>;
  auto make = [&](const char* name,
                  const Params& params) -> snell::Result<std::unique_ptr<snell::Effect>> {
    auto created = registry.create(name, create_info);
    if (!created) {
      return created.error();
    }
    for (const auto& [key, value] : params) { // the schema lists every parameter
      if (auto r = (*created)->set_param(key, value); !r) {
        return r.error();
      }
    }
    return std::move(*created);
  };
  // The water rectangle is the host's pool opening.
  auto water_effect =
      make("water", {{"height", water.height}, {"center", water.center}, {"size", water.size}});
  if (!water_effect) {
    return snell_failure("water", water_effect.error());
  }
  // The probe: captured at the chrome ball's centre. The effect would also draw its own sphere
  // of `radius` at `center` in record_draw; with the ball's centre and radius that sphere *is*
  // the host's ball, so the host skips the probe's record_draw and draws the ball itself with
  // its chrome material (dynamic_cubemap has no capture-only option; docs/embedding.md).
  // capture = six_pass: the host's draw_scene draws one view at a time and refuses multiview
  // views (view_mask != 0), so the six faces must come in six passes. (On a CPU device the
  // effect captures six passes anyway; on a GPU multiview is its default.)
  // face_size 128: the ball covers about 60 x 60 pixels at 640x360.
  const embed::ChromeBall& ball = scene.chrome_ball();
  auto probe_effect = make("dynamic_cubemap", {{"center", ball.center},
                                               {"radius", ball.radius},
                                               {"capture", std::string("six_pass")},
                                               {"face_size", 128}});
  if (!probe_effect) {
    return snell_failure("dynamic_cubemap", probe_effect.error());
  }
  const FrameEffects effects{probe_effect->get(), water_effect->get(), &probes};

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

  auto render = [&](const FrameEffects& fx) -> int {
    ++info.frame_index;
    // Phase 1 for every effect of the frame: creates or resizes targets; replaced ones are
    // destroyed frames_in_flight later.
    for (snell::Effect* e : {fx.probe, fx.water}) {
      if (e != nullptr) {
        if (auto r = e->update(info); !r) {
          return snell_failure("update", r.error());
        }
      }
    }
    auto recorded = record_frame(frame, scene, *snapshot, fx, info);
    frame.submit_and_wait(); // the command buffer is complete even when a Snell call failed
    if (!recorded) {
      return snell_failure("record_frame", recorded.error());
    }
    return 0;
  };
  for (std::uint32_t i = 0; i < o.frames; ++i) {
    info.time = float(i) / 60.0f;
    info.main_view.time = info.time;
    if (int rc = render(effects); rc != 0) {
      return rc;
    }
  }
  const std::vector<std::uint8_t> with_effects = frame.pixels();
  if (auto r = snell::write_png(o.out,
                                snell::Image{"embed-host", o.width, o.height, with_effects, true});
      !r) {
    return snell_failure("write_png", r.error());
  }
  std::printf("snell-embed-host: %ux%u, %u frame(s) on %s -> %s\n", o.width, o.height, o.frames,
              device.device_name.c_str(), o.out.c_str());
  if (!o.check) {
    return 0;
  }

  // --- --check: the same frame without the effects (no water; the ball drawn flat). -----------
  if (int rc = render(FrameEffects{}); rc != 0) {
    return rc;
  }
  const std::vector<std::uint8_t> without = frame.pixels();
  const glm::mat4 view_proj = info.main_view.proj * info.main_view.view;
  // Where a world point lands: uv (0..1, y down) or nothing when outside the image.
  auto pixel_of = [&](glm::vec3 p, const char* what) -> std::optional<glm::ivec2> {
    const glm::vec4 clip = view_proj * glm::vec4(p, 1.0f);
    const glm::vec2 uv = snell::project_to_uv(clip, snell::ClipConvention::vulkan);
    if (!(clip.w > 0.0f) || !(uv.x >= 0.0f && uv.x < 1.0f && uv.y >= 0.0f && uv.y < 1.0f)) {
      std::printf("check: FAILED: the %s projects outside the image (uv %.3f, %.3f)\n", what, uv.x,
                  uv.y);
      return std::nullopt;
    }
    return glm::ivec2(int(uv.x * float(o.width)), int(uv.y * float(o.height)));
  };

  // The water: its centre's pixel changes, the sky's does not.
  const auto water_pixel =
      pixel_of(glm::vec3(water.center.x, water.height, water.center.y), "water centre");
  if (!water_pixel) {
    return 3;
  }
  const PixelPair surface =
      compare_pixel(with_effects, without, o.width, water_pixel->x, water_pixel->y);
  const PixelPair sky = compare_pixel(with_effects, without, o.width, int(o.width / 2), 0);
  constexpr int kMinWaterDifference = 16; // 8-bit sRGB steps; the water changes far more
  print_pixel("water centre", surface, "must be >= 16");
  print_pixel("sky", sky, "must be 0");
  bool passed = surface.difference >= kMinWaterDifference && sky.difference == 0;

  // The chrome ball: at the point facing the eye the mirror reflects straight back, so the
  // pixel shows what the probe's capture sees from the ball's centre toward the camera and
  // beyond: the back wall. Predicted on the CPU from the pixel's own ray: the reflected
  // direction at the sphere, traced through the host's scene from the capture centre (the
  // probe treats the capture as infinitely far), times Schlick's Fresnel of the metal.
  const glm::vec3 toward_eye = glm::normalize(eye - ball.center);
  const auto ball_pixel = pixel_of(ball.center + ball.radius * toward_eye, "chrome ball");
  if (!ball_pixel) {
    return 3;
  }
  const glm::mat4 inverse = glm::inverse(view_proj);
  const glm::vec2 ndc{(float(ball_pixel->x) + 0.5f) / float(o.width) * 2.0f - 1.0f,
                      (float(ball_pixel->y) + 0.5f) / float(o.height) * 2.0f - 1.0f};
  const glm::vec4 near_point = inverse * glm::vec4(ndc, 0.0f, 1.0f);
  const glm::vec4 far_point = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 ray =
      glm::normalize(glm::vec3(far_point) / far_point.w - glm::vec3(near_point) / near_point.w);
  const glm::vec3 oc = eye - ball.center;
  const float b = glm::dot(oc, ray);
  const float disc = b * b - (glm::dot(oc, oc) - ball.radius * ball.radius);
  const glm::vec3 hit = eye + (-b - std::sqrt(std::max(disc, 0.0f))) * ray;
  const glm::vec3 normal = glm::normalize(hit - ball.center);
  const Seen seen = trace_scene(scene, ball.center, glm::reflect(ray, normal),
                                static_cast<std::uint32_t>(snell::layer::captured));
  const float cos_theta = std::clamp(glm::dot(normal, -ray), 0.0f, 1.0f);
  const glm::vec3 fresnel = ball.f0 + (1.0f - ball.f0) * std::pow(1.0f - cos_theta, 5.0f);
  const glm::vec3 expected_linear = fresnel * seen.color;
  const int expected[3] = {to_srgb8(expected_linear.r), to_srgb8(expected_linear.g),
                           to_srgb8(expected_linear.b)};
  const PixelPair chrome =
      compare_pixel(with_effects, without, o.width, ball_pixel->x, ball_pixel->y);
  int error = 0;
  for (int c = 0; c < 3; ++c) {
    error = std::max(error, std::abs(int(chrome.with[c]) - expected[c]));
  }
  // 4 steps: sRGB rounding, the RGBA16F capture and the tessellated sphere's normals.
  constexpr int kMaxChromeError = 4;
  print_pixel("chrome ball", chrome, "must be >= 16: the flat ball without the probe");
  std::printf("check: chrome ball pixel (%d, %d) reflects %s: predicted (%d, %d, %d), "
              "rendered (%d, %d, %d), error %d (must be <= %d)\n",
              chrome.x, chrome.y, seen.what.c_str(), expected[0], expected[1], expected[2],
              chrome.with[0], chrome.with[1], chrome.with[2], error, kMaxChromeError);
  constexpr int kMinChromeDifference = 16; // the probe's colours against a flat grey
  passed = passed && chrome.difference >= kMinChromeDifference && error <= kMaxChromeError &&
           seen.what == "back wall";
  if (!passed) {
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

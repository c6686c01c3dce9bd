#include "commands.hpp"

#include <snell/builtin_scenes.hpp>
#include <snell/frame.hpp>
#include <snell/readback.hpp>
#include <snell/scene_renderer.hpp>

#include <glm/trigonometric.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace snell::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
  if (v.empty()) {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

const char* type_name(VkPhysicalDeviceType t) {
  switch (t) {
  case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
    return "discrete GPU";
  case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
    return "integrated GPU";
  case VK_PHYSICAL_DEVICE_TYPE_CPU:
    return "CPU";
  default:
    return "other";
  }
}

Result<Scene> load_scene(const std::string& name) {
  const std::filesystem::path path(name);
  const std::string ext = path.extension().string();
  if (ext == ".gltf" || ext == ".glb") {
    return load_gltf(path);
  }
  return make_builtin_scene(name);
}

/// The camera: the scene's first camera, else one framing the scene's bounds; then overrides.
CameraDesc choose_camera(const Scene& scene, const RenderOptions& o) {
  CameraDesc cam;
  if (!scene.cameras.empty()) {
    cam = scene.cameras.front();
  } else {
    const auto [lo, hi] = scene.bounds();
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 0.1f);
    cam.target = centre;
    cam.eye = centre + glm::normalize(glm::vec3(0.6f, 0.45f, 1.0f)) * radius * 2.4f;
    cam.z_near = radius * 0.01f;
    cam.z_far = radius * 20.0f;
  }
  if (o.eye) {
    cam.eye = *o.eye;
  }
  if (o.target) {
    cam.target = *o.target;
  }
  if (o.fov_degrees) {
    cam.yfov = glm::radians(*o.fov_degrees);
  }
  if (o.z_near) {
    cam.z_near = *o.z_near;
  }
  if (o.z_far) {
    cam.z_far = *o.z_far;
  }
  return cam;
}

int report_validation(const Context& ctx) {
  if (ctx.validation_enabled() && ctx.validation_error_count() > 0) {
    for (const std::string& m : ctx.validation_messages()) {
      std::fprintf(stderr, "%s\n", m.c_str());
    }
    std::fprintf(stderr, "snell: %u validation error(s)\n", ctx.validation_error_count());
    return 1;
  }
  return 0;
}

} // namespace

int run_info() {
  auto devices = Context::enumerate_devices();
  if (!devices) {
    std::fprintf(stderr, "snell: %s\n", devices.error().message.c_str());
    return 1;
  }
  std::printf("Vulkan devices:\n");
  for (const DeviceInfo& d : *devices) {
    std::printf("  %s (%s), Vulkan %u.%u, %s%s\n", d.name.c_str(), type_name(d.type),
                VK_API_VERSION_MAJOR(d.api_version), VK_API_VERSION_MINOR(d.api_version),
                d.driver.c_str(), d.suitable ? "" : (" -- unsuitable: lacks " + d.missing).c_str());
  }
  auto ctx = Context::create();
  if (!ctx) {
    std::fprintf(stderr, "snell: %s\n", ctx.error().message.c_str());
    return 1;
  }
  std::printf("chosen: %s\n", ctx->device_info().name.c_str());
  return 0;
}

int run_render(const RenderOptions& o) {
  const auto start = Clock::now();
  auto scene = load_scene(o.scene);
  if (!scene) {
    std::fprintf(stderr, "snell: %s\n", scene.error().message.c_str());
    return scene.error().code == ErrorCode::unknown_name ? 2 : 1;
  }
  ContextDesc cd;
  cd.validation = o.validation;
  cd.device = o.device;
  auto ctx = Context::create(cd);
  if (!ctx) {
    std::fprintf(stderr, "snell: %s\n", ctx.error().message.c_str());
    return 1;
  }
  auto renderer = SceneRenderer::create(*ctx, *scene);
  if (!renderer) {
    std::fprintf(stderr, "snell: %s\n", renderer.error().message.c_str());
    return 1;
  }
  auto frame = FrameRenderer::create(
      *ctx, FrameDesc{o.width, o.height, ColorFormat::rgba8_srgb, o.debug_targets});
  if (!frame) {
    std::fprintf(stderr, "snell: %s\n", frame.error().message.c_str());
    return 1;
  }
  const CameraDesc camera = choose_camera(*scene, o);
  std::vector<double> cpu_ms, gpu_ms;
  double startup_ms = 0.0;
  for (std::uint32_t i = 0; i < o.frames; ++i) {
    const float t = o.time + static_cast<float>(i) / 60.0f;
    auto stats = frame->render(*renderer, camera, t);
    if (!stats) {
      std::fprintf(stderr, "snell: frame %u: %s\n", i, stats.error().message.c_str());
      return 1;
    }
    if (!renderer->last_error().empty()) {
      std::fprintf(stderr, "snell: %s\n", renderer->last_error().c_str());
      return 1;
    }
    if (i == 0) {
      // Start-up: context, scene upload, pipelines (created on the first draw).
      startup_ms = ms_since(start);
    }
    if (i > 0 || o.frames == 1) {
      cpu_ms.push_back(stats->cpu_ms);
      gpu_ms.push_back(stats->gpu_ms);
    }
  }
  if (!o.out.empty()) {
    auto image = frame->read_color();
    if (!image) {
      std::fprintf(stderr, "snell: %s\n", image.error().message.c_str());
      return 1;
    }
    if (auto r = write_png(o.out, *image); !r) {
      std::fprintf(stderr, "snell: %s\n", r.error().message.c_str());
      return 1;
    }
  }
  std::printf("scene %s, %ux%u on %s\n", o.scene.c_str(), o.width, o.height,
              ctx->device_info().name.c_str());
  std::printf("start-up (context, upload, pipelines, first frame): %.1f ms\n", startup_ms);
  std::printf("frames timed: %zu, median frame: %.2f ms CPU wall, %.2f ms GPU\n", cpu_ms.size(),
              median(cpu_ms), median(gpu_ms));
  std::printf("peak resident memory: %.1f MiB\n", peak_rss_mib());
  if (!o.out.empty()) {
    std::printf("wrote %s\n", o.out.c_str());
  }
  return report_validation(*ctx);
}

} // namespace snell::cli

#include "commands.hpp"

#include "progress.hpp"
#include "session.hpp"

#include <snell/output_file.hpp>
#include <snell/readback.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

namespace snell::cli {
namespace {

using Clock = std::chrono::steady_clock;

/// The CLI's PNG compression level (PngOptions::compression_level): stb_image_write's fastest.
/// Measured (docs/cli.md) against its default 8: 15 to 25 % less encoding time for 2 to 3 %
/// larger files (3840x2160 and 16384x16384).
constexpr int kPngCompressionLevel = 5;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// Adds frame `frame`'s pass times to `out` (name -> one value per frame): passes of the same
/// name in one frame (several probes' captures) are summed, since the frame pays for all.
void add_frame_passes(const std::vector<PassTime>& frame_passes, std::uint32_t frame,
                      std::map<std::string, std::vector<double>>& out) {
  for (const PassTime& p : frame_passes) {
    std::vector<double>& times = out[p.name];
    if (times.size() == frame + 1) {
      times.back() += p.ms;
    } else {
      times.resize(frame, 0.0); // frames without this pass cost it nothing
      times.push_back(p.ms);
    }
  }
}

/// Pads each pass to `frames` values with 0 (frames that did not draw it: a sliced or budgeted
/// capture), so its median is per frame, not per occurrence.
void pad_absent_passes(std::uint32_t frames, std::map<std::string, std::vector<double>>& passes) {
  for (auto& [name, times] : passes) {
    times.resize(frames, 0.0);
  }
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

/// What is kept of a session's context once the session is closed (before PNG encoding, so
/// that a 16K image is not encoded while the GPU objects still hold their memory).
struct ContextReport {
  std::string device;
  bool validation = false;
  std::uint32_t errors = 0;
  std::vector<std::string> messages;

  explicit ContextReport(const Context& ctx)
      : device(ctx.device_info().name), validation(ctx.validation_enabled()),
        errors(ctx.validation_error_count()), messages(ctx.validation_messages()) {}

  /// Prints validation errors; 1 when there were any.
  int report() const {
    if (validation && errors > 0) {
      for (const std::string& m : messages) {
        std::fprintf(stderr, "%s\n", m.c_str());
      }
      std::fprintf(stderr, "snell: %u validation error(s)\n", errors);
      return 1;
    }
    return 0;
  }
};

std::string size_text(std::uint32_t w, std::uint32_t h) {
  return std::to_string(w) + "x" + std::to_string(h);
}

int failed(const Error& e, int code) {
  std::fprintf(stderr, "snell: %s\n", e.message.c_str());
  return code;
}

/// `e` with the command-line flag it concerns in front ("--out: /x.png: is a folder...").
Error flagged(const char* flag, const Error& e) {
  return Error{e.code, std::string(flag) + ": " + e.message, e.vk_result};
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
    }
    if (static_cast<unsigned char>(c) >= 0x20) {
      out += c;
    }
  }
  return out;
}

} // namespace

int run_info() {
  auto devices = Context::enumerate_devices();
  if (!devices) {
    return failed(devices.error(), 1);
  }
  std::printf("Vulkan devices:\n");
  for (const DeviceInfo& d : *devices) {
    std::printf("  %s (%s), Vulkan %u.%u, %s%s\n", d.name.c_str(), type_name(d.type),
                VK_API_VERSION_MAJOR(d.api_version), VK_API_VERSION_MINOR(d.api_version),
                d.driver.c_str(), d.suitable ? "" : (" -- unsuitable: lacks " + d.missing).c_str());
  }
  auto ctx = Context::create();
  if (!ctx) {
    return failed(ctx.error(), 1);
  }
  std::printf("chosen: %s\n", ctx->device_info().name.c_str());
  return 0;
}

int run_list() {
  EffectRegistry registry;
  if (auto r = register_builtin_effects(registry); !r) {
    return failed(r.error(), 1);
  }
  for (const std::string& name : registry.names()) {
    const ParamSchema* schema = registry.schema(name);
    std::printf("%s: %s\n", name.c_str(), schema->doc.c_str());
    for (const ParamSpec& p : schema->params) {
      std::string range;
      if (p.type == ParamType::enumeration) {
        for (const std::string& c : p.choices) {
          range += (range.empty() ? "" : "|");
          range += c;
        }
      } else if (p.type != ParamType::boolean && p.type != ParamType::texture &&
                 p.type != ParamType::string) {
        range = '[';
        range += to_string(ParamValue{p.min});
        range += ", ";
        range += to_string(ParamValue{p.max});
        range += ']';
      }
      std::printf("  %-20s %-6s default %-18s %-26s %-4s %s\n", p.name.c_str(),
                  std::string(to_string(p.type)).c_str(), to_string(p.default_value).c_str(),
                  range.c_str(), p.unit.c_str(), p.doc.c_str());
    }
  }
  return 0;
}

int run_render(const RenderOptions& o) {
  const auto start = Clock::now();
  // The output is checked before any work: a folder, or a folder that does not exist, is
  // refused now rather than after a long render.
  if (!o.out.empty()) {
    if (auto r = check_output_path(o.out); !r) {
      return failed(flagged("--out", r.error()), 1);
    }
  }
  ProgressLine progress(ProgressLine::stderr_is_terminal());
  const auto stop_and_fail = [&progress](const Error& e, int code) {
    progress.stop();
    return failed(e, code);
  };
  progress.set("starting (scene, Vulkan device, uploads)");
  int code = 1;
  auto session = open_session(o, code);
  if (!session) {
    return stop_and_fail(session.error(), code);
  }
  std::vector<double> cpu_ms, gpu_ms;
  double startup_ms = 0.0;
  for (std::uint32_t i = 0; i < o.frames; ++i) {
    progress.set(i == 0 ? "first frame (pipelines)" : "frame", i + 1, o.frames);
    const float t = o.time + static_cast<float>(i) / 60.0f;
    auto stats = (*session)->render(t, true);
    if (!stats) {
      return stop_and_fail(stats.error(), 1);
    }
    if (!stats->effect_errors.empty()) {
      return stop_and_fail(stats->effect_errors.front(), 1);
    }
    if (i == 0) {
      startup_ms = ms_since(start); // context, upload, pipelines (created on the first draw)
    }
    if (i > 0 || o.frames == 1) {
      cpu_ms.push_back(stats->cpu_ms);
      gpu_ms.push_back(stats->gpu_ms);
    }
  }
  std::optional<Image> image;
  if (!o.out.empty()) {
    progress.set("reading the image back");
    auto read = (*session)->frame->read_color();
    if (!read) {
      return stop_and_fail(read.error(), 1);
    }
    image = std::move(*read);
  }
  const ContextReport context(*(*session)->ctx);
  session->reset();
  std::size_t png_bytes = 0;
  double encode_ms = 0.0;
  if (image) {
    progress.set("encoding the " + size_text(o.width, o.height) + " PNG");
    const auto encode_start = Clock::now();
    auto png = encode_png(*image, PngOptions{.compression_level = kPngCompressionLevel});
    if (!png) {
      return stop_and_fail(Error{png.error().code, "--out: " + o.out + ": " + png.error().message},
                           1);
    }
    encode_ms = ms_since(encode_start);
    image.reset();
    progress.set("writing " + o.out);
    if (auto r = write_file(o.out, png->data(), png->size()); !r) {
      return stop_and_fail(flagged("--out", r.error()), 1);
    }
    png_bytes = png->size();
  }
  progress.stop();
  std::printf("scene %s, %s on %s\n", o.scene.c_str(), size_text(o.width, o.height).c_str(),
              context.device.c_str());
  std::printf("start-up (context, upload, pipelines, first frame): %.1f ms\n", startup_ms);
  std::printf("frames timed: %zu, median frame: %.2f ms CPU wall, %.2f ms GPU\n", cpu_ms.size(),
              median(cpu_ms), median(gpu_ms));
  std::printf("peak resident memory: %.1f MiB\n", peak_rss_mib());
  if (!o.out.empty()) {
    std::printf("wrote %s (%zu bytes; PNG encoding %.0f ms, compression level %d)\n", o.out.c_str(),
                png_bytes, encode_ms, kPngCompressionLevel);
  }
  return context.report();
}

int run_bench(const RenderOptions& o) {
  if (!o.json.empty()) {
    if (auto r = check_output_path(o.json); !r) {
      return failed(flagged("--json", r.error()), 1);
    }
  }
  ProgressLine progress(ProgressLine::stderr_is_terminal());
  const auto stop_and_fail = [&progress](const Error& e, int code) {
    progress.stop();
    return failed(e, code);
  };
  progress.set("starting (scene, Vulkan device, uploads)");
  int code = 1;
  auto session = open_session(o, code);
  if (!session) {
    return stop_and_fail(session.error(), code);
  }
  Session& s = **session;
  // Warm-up: pipelines and targets are created on first use and must not be timed.
  std::uint64_t warm = 0;
  for (const bool with : {false, true, false, true}) {
    progress.set("warm-up frame", ++warm, 4);
    if (auto r = s.render(o.time, with); !r) {
      return stop_and_fail(r.error(), 1);
    }
  }
  // Interleaved plain/effect frames, so drift (thermal, other load) hits both alike.
  std::vector<double> plain_gpu, effect_gpu, plain_cpu, effect_cpu;
  std::map<std::string, std::vector<double>> passes, plain_passes;
  for (std::uint32_t i = 0; i < o.frames; ++i) {
    progress.set("timed frame pair (plain, effects)", i + 1, o.frames);
    const float t = o.time + static_cast<float>(i) / 60.0f;
    auto plain = s.render(t, false);
    auto effect = s.render(t, true);
    if (!plain || !effect) {
      return stop_and_fail(!plain ? plain.error() : effect.error(), 1);
    }
    plain_gpu.push_back(plain->gpu_ms);
    plain_cpu.push_back(plain->cpu_ms);
    effect_gpu.push_back(effect->gpu_ms);
    effect_cpu.push_back(effect->cpu_ms);
    add_frame_passes(effect->passes, i, passes);
    add_frame_passes(plain->passes, i, plain_passes);
  }
  pad_absent_passes(o.frames, passes);
  pad_absent_passes(o.frames, plain_passes);
  const double plain_ms = median(plain_gpu);
  const double effect_ms = median(effect_gpu);
  const double ratio = plain_ms > 0.0 ? effect_ms / plain_ms : 0.0;
  std::string effects;
  for (const std::string& e : o.effects) {
    effects += (effects.empty() ? "" : ",");
    effects += e;
  }
  if (!o.json.empty()) {
    progress.set("writing " + o.json);
    std::ostringstream json;
    json << "{\n  \"scene\": \"" << json_escape(o.scene) << "\",\n  \"effects\": \""
         << json_escape(effects) << "\",\n  \"width\": " << o.width
         << ",\n  \"height\": " << o.height << ",\n  \"frames\": " << o.frames
         << ",\n  \"device\": \"" << json_escape(s.ctx->device_info().name)
         << "\",\n  \"plain_ms\": " << plain_ms << ",\n  \"effect_ms\": " << effect_ms
         << ",\n  \"ratio\": " << ratio << ",\n  \"plain_cpu_ms\": " << median(plain_cpu)
         << ",\n  \"effect_cpu_ms\": " << median(effect_cpu) << ",\n  \"passes\": {";
    bool first = true;
    for (const auto& [name, times] : passes) {
      json << (first ? "\n" : ",\n") << "    \"" << json_escape(name) << "\": " << median(times);
      first = false;
    }
    json << "\n  },\n  \"plain_passes\": {";
    first = true;
    for (const auto& [name, times] : plain_passes) {
      json << (first ? "\n" : ",\n") << "    \"" << json_escape(name) << "\": " << median(times);
      first = false;
    }
    json << "\n  }\n}\n";
    if (auto r = write_file(o.json, json.str()); !r) {
      return stop_and_fail(flagged("--json", r.error()), 1);
    }
  }
  progress.stop();
  std::printf("bench %s + [%s], %ux%u, %u frames each, on %s\n", o.scene.c_str(), effects.c_str(),
              o.width, o.height, o.frames, s.ctx->device_info().name.c_str());
  std::printf("plain  %.3f ms GPU (%.3f ms CPU wall)\n", plain_ms, median(plain_cpu));
  std::printf("effect %.3f ms GPU (%.3f ms CPU wall)\n", effect_ms, median(effect_cpu));
  std::printf("ratio  %.3f\n", ratio);
  for (const auto& [name, times] : passes) {
    std::printf("  pass %-24s %.3f ms\n", name.c_str(), median(times));
  }
  for (const auto& [name, times] : plain_passes) {
    std::printf("  plain pass %-18s %.3f ms\n", name.c_str(), median(times));
  }
  if (!o.json.empty()) {
    std::printf("wrote %s\n", o.json.c_str());
  }
  return ContextReport(*s.ctx).report();
}

} // namespace snell::cli

#include "cli_args.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace snell::cli {
namespace {

Result<float> parse_float(const std::string& text, const std::string& what) {
  errno = 0;
  char* end = nullptr;
  const float v = std::strtof(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) {
    return fail(ErrorCode::invalid_argument, what + ": '" + text + "' is not a finite number");
  }
  return v;
}

Result<std::uint32_t> parse_uint(const std::string& text, const std::string& what, std::uint32_t lo,
                                 std::uint32_t hi) {
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || v < lo || v > hi) {
    return fail(ErrorCode::invalid_argument, what + ": '" + text + "' is not an integer in " +
                                                 std::to_string(lo) + ".." + std::to_string(hi));
  }
  return static_cast<std::uint32_t>(v);
}

/// A float as the user would write it (shortest form: 0.1, 5, 1e+06).
std::string number_text(float v) {
  std::ostringstream ss;
  ss << v;
  return ss.str();
}

} // namespace

std::pair<std::string, std::uint32_t> split_instance(const std::string& effect) {
  const auto at = effect.find('@');
  if (at == std::string::npos) {
    return {effect, 0u};
  }
  auto k = parse_uint(effect.substr(at + 1), "instance", 1, 100000);
  return {effect.substr(0, at), k ? *k : 0u};
}

Result<glm::vec3> parse_vec3(const std::string& text, const std::string& what) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, ',');) {
    parts.push_back(part);
  }
  if (parts.size() != 3) {
    return fail(ErrorCode::invalid_argument,
                what + ": '" + text + "' must be three comma-separated numbers x,y,z");
  }
  glm::vec3 v(0.0f);
  for (int i = 0; i < 3; ++i) {
    auto f = parse_float(parts[static_cast<std::size_t>(i)], what);
    if (!f) {
      return f.error();
    }
    v[i] = *f;
  }
  return v;
}

std::string help_text() {
  return R"(snell - reflection and refraction effects for Vulkan, rendered headlessly

usage:
  snell render [options]     render a scene (with effects) to PNG
  snell bench [options]      time plain frames against frames with the effects (GPU timestamps)
  snell view [options]       open a window: fly around the scene, tune the effects live
  snell list                 list the effects and their parameters (name, type, default, range)
  snell info                 list the Vulkan devices and the one chosen
  snell --help               this text

render options:
  --scene NAME|FILE   built-in scene (pool, window, spheres, room, mirror) or a .gltf/.glb file
                      [pool]
  --size WxH          output size in pixels, each 1..16384 [1280x720]
  --out FILE.png      output PNG (rows top first, world up is image up)
  --eye X,Y,Z         camera position [the scene's default camera]
  --target X,Y,Z      point looked at [the scene's default camera]
  --fov DEG           vertical field of view in degrees, (0,180) [scene camera or 45]
  --near N --far F    clip distances, 0 < N < F [scene camera or 0.1, 200]
  --time SECONDS      scene time (animation), finite [0]
  --frames N          render N frames (time advances 1/60 s each) and report start-up
                      separately from the median frame time, 1..100000 [1]
  --debug-targets     composite thumbnails of intermediate targets into the corners
  --device NAME       lavapipe, gpu, or a device-name substring [SNELL_DEVICE or best]
  --validation        enable the Khronos validation layer (also SNELL_VALIDATION=1)
  --effect NAME       add an effect (repeatable; see `snell list`), e.g. --effect water
  --set E.KEY=VALUE   set a parameter of effect E (repeatable); vectors as x,y or x,y,z,
                      e.g. --set water.wave_height=0 --set water.center=0,0; E@K sets only
                      the K-th --effect E, e.g. --set dynamic_cubemap@2.surface=glass
  --capture-budget N  cube faces all probes (dynamic_cubemap) together capture a frame,
                      stalest and nearest first, 0..10000 [none: each probe on its own]

bench options (as render, plus):
  --frames N          frames of each kind (plain, with effects), >= 3 [60]
  --json FILE         write the results as JSON: plain_ms, effect_ms, ratio, passes, device

view options (as render, without --out and --json, plus):
  --size WxH          initial window size [1280x720]
  --frames N          quit after N frames [run until the window is closed]
  --debug-targets     start with the debug-target thumbnails shown (F3 toggles)
  --present MODE      fifo (vsync) or mailbox [fifo]
  --script FILE       timed actions: camera moves, parameter sets, screenshots, quit;
                      time then advances 1/60 s a frame (see docs/viewer.md)

Output files are written whole or not at all (an existing file is kept on failure).
On a terminal, work longer than about 2 s shows a progress line on stderr.
Exit codes: 0 success, 1 failure (rendering, or a file that cannot be read or
written), 2 bad arguments.
)";
}

Result<Command> parse(const std::vector<std::string>& args) {
  Command cmd;
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    cmd.name = "help";
    return cmd;
  }
  cmd.name = args[0];
  if (cmd.name == "info" || cmd.name == "list") {
    if (args.size() > 1) {
      return fail(ErrorCode::invalid_argument,
                  cmd.name + ": unexpected argument '" + args[1] + "'");
    }
    return cmd;
  }
  if (cmd.name != "render" && cmd.name != "bench" && cmd.name != "view") {
    return fail(ErrorCode::invalid_argument,
                "unknown command '" + cmd.name +
                    "' (commands: render, bench, view, list, info; see --help)");
  }
  if (cmd.name == "bench") {
    cmd.render.frames = 60;
  }
  if (cmd.name == "view") {
    cmd.render.frames = 0; // until the window is closed
  }
  RenderOptions& o = cmd.render;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      cmd.name = "help";
      return cmd;
    }
    if (a == "--debug-targets") {
      o.debug_targets = true;
      continue;
    }
    if (a == "--validation") {
      o.validation = true;
      continue;
    }
    if (i + 1 >= args.size()) {
      return fail(ErrorCode::invalid_argument, a + ": missing value (see --help)");
    }
    const std::string& v = args[++i];
    Result<void> ok;
    if (a == "--scene") {
      o.scene = v;
    } else if (a == "--out" && cmd.name != "view") {
      o.out = v;
    } else if (a == "--script" && cmd.name == "view") {
      o.script = v;
    } else if (a == "--present" && cmd.name == "view") {
      if (v != "fifo" && v != "mailbox") {
        return fail(ErrorCode::invalid_argument, "--present: '" + v + "' must be fifo or mailbox");
      }
      o.present = v;
    } else if (a == "--device") {
      o.device = v;
    } else if (a == "--effect") {
      o.effects.push_back(v);
    } else if (a == "--json" && cmd.name == "bench") {
      o.json = v;
    } else if (a == "--set") {
      const auto dot = v.find('.');
      const auto eq = v.find('=');
      if (dot == std::string::npos || eq == std::string::npos || dot == 0 || eq < dot + 2) {
        return fail(ErrorCode::invalid_argument,
                    "--set: '" + v + "' must be EFFECT.KEY=VALUE, e.g. water.wave_height=0.5");
      }
      o.sets.push_back({v.substr(0, dot), v.substr(dot + 1, eq - dot - 1), v.substr(eq + 1)});
    } else if (a == "--capture-budget") {
      auto n = parse_uint(v, a, 0, 10000);
      if (!n) {
        return n.error();
      }
      o.capture_budget = *n;
    } else if (a == "--size") {
      const auto x = v.find('x');
      if (x == std::string::npos) {
        return fail(ErrorCode::invalid_argument, "--size: '" + v + "' must be WxH, e.g. 1280x720");
      }
      auto w = parse_uint(v.substr(0, x), "--size width", 1, 16384);
      auto h = parse_uint(v.substr(x + 1), "--size height", 1, 16384);
      if (!w || !h) {
        return !w ? w.error() : h.error();
      }
      o.width = *w;
      o.height = *h;
    } else if (a == "--eye" || a == "--target") {
      auto p = parse_vec3(v, a);
      if (!p) {
        return p.error();
      }
      (a == "--eye" ? o.eye : o.target) = *p;
    } else if (a == "--fov") {
      auto f = parse_float(v, a);
      if (!f || !(*f > 0.0f && *f < 180.0f)) {
        return f ? fail(ErrorCode::invalid_argument, "--fov: " + v + " is outside (0, 180) degrees")
                 : f.error();
      }
      o.fov_degrees = *f;
    } else if (a == "--near" || a == "--far") {
      auto f = parse_float(v, a);
      if (!f || !(*f > 0.0f)) {
        return f ? fail(ErrorCode::invalid_argument, a + ": " + v + " must be > 0") : f.error();
      }
      (a == "--near" ? o.z_near : o.z_far) = *f;
    } else if (a == "--time") {
      auto f = parse_float(v, a);
      if (!f) {
        return f.error();
      }
      o.time = *f;
    } else if (a == "--frames") {
      auto n = parse_uint(v, a, 1, 100000);
      if (!n) {
        return n.error();
      }
      o.frames = *n;
    } else if (a == "--json") {
      return fail(ErrorCode::invalid_argument,
                  "--json is an option of snell bench, not of snell render (see --help)");
    } else {
      return fail(ErrorCode::invalid_argument,
                  cmd.name + ": unknown option '" + a + "' (see --help)");
    }
  }
  if (o.z_near && o.z_far && !(*o.z_near < *o.z_far)) {
    return fail(ErrorCode::invalid_argument, "--near " + number_text(*o.z_near) +
                                                 " must be smaller than --far " +
                                                 number_text(*o.z_far));
  }
  if (o.eye && o.target && *o.eye == *o.target) {
    return fail(ErrorCode::invalid_argument,
                "--eye and --target are both " + number_text(o.eye->x) + "," +
                    number_text(o.eye->y) + "," + number_text(o.eye->z) +
                    "; the camera needs a direction (they must differ)");
  }
  if (cmd.name == "render" && o.out.empty() && o.frames == 1) {
    return fail(ErrorCode::invalid_argument, "render: --out FILE.png is required");
  }
  if (cmd.name == "bench" && o.frames < 3) {
    return fail(ErrorCode::invalid_argument,
                "bench: --frames " + std::to_string(o.frames) + " is too few; give 3..100000");
  }
  for (const auto& set : o.sets) {
    const auto [name, instance] = split_instance(set[0]);
    const auto count = std::count(o.effects.begin(), o.effects.end(), name);
    if (count == 0) {
      return fail(ErrorCode::invalid_argument, "--set " + set[0] + "." + set[1] + ": effect '" +
                                                   name + "' is not enabled (add --effect " + name +
                                                   ")");
    }
    if (set[0] != name && (instance < 1 || instance > count)) {
      return fail(ErrorCode::invalid_argument,
                  "--set " + set[0] + "." + set[1] + ": instance '" + set[0].substr(name.size()) +
                      "' must be @1..@" + std::to_string(count) + " (--effect " + name +
                      " is given " + std::to_string(count) + " time(s))");
    }
  }
  return cmd;
}

} // namespace snell::cli

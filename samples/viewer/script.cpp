#include "script.hpp"

#include "cli_args.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace snell::viewer {
namespace {

using Kind = ScriptAction::Kind;

struct Verb {
  const char* name;
  Kind kind;
  int min_args;
  int max_args;
};

constexpr Verb kVerbs[] = {
    {"set", Kind::set, 1, 1},
    {"add", Kind::add, 1, 1},
    {"remove", Kind::remove, 1, 1},
    {"camera", Kind::camera, 2, 2},
    {"orbit", Kind::orbit, 2, 2},
    {"pan", Kind::pan, 2, 2},
    {"zoom", Kind::zoom, 1, 1},
    {"fly", Kind::fly, 3, 3},
    {"reset-camera", Kind::reset_camera, 0, 0},
    {"screenshot", Kind::screenshot, 1, 2},
    {"debug-targets", Kind::debug_targets, 1, 1},
    {"panel", Kind::panel, 1, 1},
    {"resize", Kind::resize, 1, 1},
    {"minimize", Kind::minimize, 0, 0},
    {"restore", Kind::restore, 0, 0},
    {"quit", Kind::quit, 0, 0},
};

std::string verb_list() {
  std::string out;
  for (const Verb& v : kVerbs) {
    out += out.empty() ? "" : ", ";
    out += v.name;
  }
  return out;
}

bool parse_number(const std::string& text, double& out) {
  errno = 0;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && errno != ERANGE &&
         std::isfinite(out);
}

bool parse_dimension(const std::string& text, std::uint32_t& out) {
  double v = 0.0;
  if (!parse_number(text, v) || v < 1.0 || v > 16384.0 || v != std::floor(v)) {
    return false;
  }
  out = static_cast<std::uint32_t>(v);
  return true;
}

} // namespace

Result<std::vector<ScriptAction>> parse_script(std::string_view text, const std::string& name) {
  std::vector<ScriptAction> actions;
  std::istringstream in{std::string(text)};
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string::npos) {
      line.erase(hash);
    }
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) {
      w.push_back(word);
    }
    if (w.empty()) {
      continue;
    }
    const std::string where = name + ":" + std::to_string(line_number) + ": ";
    auto error = [&](const std::string& what) {
      return fail(ErrorCode::invalid_argument, where + what);
    };
    ScriptAction a;
    a.line = line_number;
    if (!parse_number(w[0], a.time) || a.time < 0.0) {
      return error("'" + w[0] +
                   "' is not a time in seconds (>= 0); lines are '<seconds> <action>'");
    }
    if (w.size() < 2) {
      return error("an action must follow the time (" + verb_list() + ")");
    }
    const Verb* verb = nullptr;
    for (const Verb& v : kVerbs) {
      if (w[1] == v.name) {
        verb = &v;
      }
    }
    if (verb == nullptr) {
      return error("unknown action '" + w[1] + "' (actions: " + verb_list() + ")");
    }
    const int args = static_cast<int>(w.size()) - 2;
    if (args < verb->min_args || args > verb->max_args) {
      return error(std::string(verb->name) + " takes " + std::to_string(verb->min_args) +
                   (verb->max_args != verb->min_args ? " to " + std::to_string(verb->max_args)
                                                     : std::string()) +
                   " argument(s), got " + std::to_string(args));
    }
    a.kind = verb->kind;
    auto numbers = [&](int count) -> Result<void> {
      for (int i = 0; i < count; ++i) {
        double v = 0.0;
        if (!parse_number(w[static_cast<std::size_t>(2 + i)], v)) {
          return error(std::string(verb->name) + ": '" + w[static_cast<std::size_t>(2 + i)] +
                       "' is not a finite number");
        }
        a.a[i] = static_cast<float>(v);
      }
      return {};
    };
    switch (a.kind) {
    case Kind::set: {
      const std::string& v = w[2];
      const auto dot = v.find('.');
      const auto eq = v.find('=');
      if (dot == std::string::npos || eq == std::string::npos || dot == 0 || eq < dot + 2) {
        return error("set: '" + v + "' must be EFFECT.KEY=VALUE, e.g. water.wave_height=0.5");
      }
      a.effect = v.substr(0, dot);
      a.key = v.substr(dot + 1, eq - dot - 1);
      a.value = v.substr(eq + 1);
      break;
    }
    case Kind::add:
    case Kind::remove:
      a.effect = w[2];
      if (a.effect.find('@') != std::string::npos &&
          (a.kind == Kind::add || cli::split_instance(a.effect).second == 0)) {
        return error(std::string(verb->name) + ": '" + a.effect + "' must be " +
                     (a.kind == Kind::add ? "an effect name" : "EFFECT or EFFECT@K (K >= 1)"));
      }
      break;
    case Kind::camera: {
      auto eye = cli::parse_vec3(w[2], "camera eye");
      auto target = cli::parse_vec3(w[3], "camera target");
      if (!eye || !target) {
        return error((!eye ? eye.error() : target.error()).message);
      }
      if (*eye == *target) {
        return error("camera: the eye and the target must differ");
      }
      a.a = *eye;
      a.b = *target;
      break;
    }
    case Kind::orbit:
    case Kind::pan:
      SNELL_TRY(numbers(2));
      break;
    case Kind::zoom:
      SNELL_TRY(numbers(1));
      break;
    case Kind::fly:
      SNELL_TRY(numbers(3));
      break;
    case Kind::screenshot:
      a.path = w[2];
      if (w.size() == 4) {
        if (w[3] != "window" && w[3] != "scene") {
          return error("screenshot: '" + w[3] + "' must be window or scene");
        }
        a.window = w[3] == "window";
      }
      break;
    case Kind::debug_targets:
    case Kind::panel:
      if (w[2] != "on" && w[2] != "off") {
        return error(std::string(verb->name) + ": '" + w[2] + "' must be on or off");
      }
      a.on = w[2] == "on";
      break;
    case Kind::resize: {
      const auto x = w[2].find('x');
      if (x == std::string::npos || !parse_dimension(w[2].substr(0, x), a.width) ||
          !parse_dimension(w[2].substr(x + 1), a.height)) {
        return error("resize: '" + w[2] + "' must be WxH, each 1..16384");
      }
      break;
    }
    case Kind::reset_camera:
    case Kind::minimize:
    case Kind::restore:
    case Kind::quit:
      break;
    }
    actions.push_back(std::move(a));
  }
  std::stable_sort(actions.begin(), actions.end(),
                   [](const ScriptAction& x, const ScriptAction& y) { return x.time < y.time; });
  return actions;
}

Result<std::vector<ScriptAction>> load_script(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    return fail(ErrorCode::file_not_found, "--script: cannot open '" + path.string() + "'");
  }
  std::ostringstream text;
  text << file.rdbuf();
  return parse_script(text.str(), path.string());
}

std::vector<ScriptAction> ScriptPlayer::due(double now) {
  std::vector<ScriptAction> out;
  // A nanosecond of slack: "0.1" and the clock's 6 / 60 need not be the same double.
  while (next_ < actions_.size() && actions_[next_].time <= now + 1e-9) {
    out.push_back(actions_[next_++]);
  }
  return out;
}

} // namespace snell::viewer

// `snell view --script FILE`: timed actions for reproducible captures. One action a line,
// "<seconds> <action> [arguments]"; '#' starts a comment. Under a script the viewer's clock
// advances exactly 1/60 s a frame (also while minimised), so "1.5 screenshot a.png" is the
// frame at scene time 1.5 s on any machine. docs/viewer.md lists the actions.
#pragma once

#include <snell/result.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace snell::viewer {

/// One action of a script.
struct ScriptAction {
  enum class Kind : std::uint8_t {
    set,           ///< set EFFECT[@K].KEY=VALUE (through the panel's code path)
    add,           ///< add EFFECT (a new instance from the registry)
    remove,        ///< remove EFFECT[@K] (the K-th instance, default the last)
    camera,        ///< camera EYE TARGET (x,y,z each)
    orbit,         ///< orbit YAW PITCH (degrees)
    pan,           ///< pan DX DY (fractions of the view height)
    zoom,          ///< zoom STEPS (wheel notches; positive moves closer)
    fly,           ///< fly RIGHT UP FORWARD (world units)
    reset_camera,  ///< reset-camera
    screenshot,    ///< screenshot FILE.png [window|scene] (default window)
    debug_targets, ///< debug-targets on|off
    panel,         ///< panel on|off (the whole user interface)
    resize,        ///< resize WxH (the window, screen coordinates)
    minimize,      ///< minimize (iconify the window)
    restore,       ///< restore (from minimised)
    quit,          ///< quit
  };
  double time = 0.0; ///< Script seconds at which it runs.
  int line = 0;      ///< 1-based line in the file (for messages).
  Kind kind = Kind::quit;
  std::string effect; ///< set/add/remove: "EFFECT" or "EFFECT@K".
  std::string key;    ///< set: the parameter.
  std::string value;  ///< set: the value's text (as --set takes it).
  glm::vec3 a{0.0f};  ///< camera: eye; orbit/pan/fly/zoom: the numbers in order.
  glm::vec3 b{0.0f};  ///< camera: target.
  std::string path;   ///< screenshot: the PNG file.
  bool window = true; ///< screenshot: the whole window (true) or the scene view only.
  bool on = true;     ///< debug-targets / panel.
  std::uint32_t width = 0, height = 0; ///< resize.
};

/// Parses a script's text; `name` prefixes error messages ("name:LINE: ..."). Actions come back
/// sorted by time (stable: lines of the same time run in file order). Errors: invalid_argument
/// naming the line and what is wrong.
[[nodiscard]] Result<std::vector<ScriptAction>> parse_script(std::string_view text,
                                                             const std::string& name);
/// Reads and parses a script file. Errors: file_not_found, and parse_script's.
[[nodiscard]] Result<std::vector<ScriptAction>> load_script(const std::filesystem::path& path);

/// Plays a parsed script against a clock: due() returns the actions whose time has come.
class ScriptPlayer {
public:
  explicit ScriptPlayer(std::vector<ScriptAction> actions = {}) : actions_(std::move(actions)) {}
  /// The actions with time <= `now` not returned before, in order.
  [[nodiscard]] std::vector<ScriptAction> due(double now);
  /// True when every action has been returned.
  [[nodiscard]] bool finished() const { return next_ >= actions_.size(); }
  [[nodiscard]] bool empty() const { return actions_.empty(); }
  [[nodiscard]] const std::vector<ScriptAction>& actions() const { return actions_; }

private:
  std::vector<ScriptAction> actions_;
  std::size_t next_ = 0;
};

} // namespace snell::viewer

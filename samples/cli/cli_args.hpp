// Command-line parsing of the `snell` tool: every bad argument is one clear line (exit code 2).
#pragma once

#include <snell/result.hpp>

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace snell::cli {

/// Options of `snell render` (and of `bench` and `view`, which take the same ones plus a few).
struct RenderOptions {
  std::string scene = "pool"; ///< Built-in name or a .gltf/.glb path.
  std::uint32_t width = 1280; ///< --size WxH.
  std::uint32_t height = 720;
  std::string out;                      ///< --out file.png (required unless --frames only).
  std::optional<glm::vec3> eye, target; ///< --eye x,y,z --target x,y,z.
  std::optional<float> fov_degrees;     ///< --fov DEG (vertical).
  std::optional<float> z_near, z_far;   ///< --near N --far F.
  float time = 0.0f;                    ///< --time SECONDS.
  std::uint32_t frames = 1;             ///< --frames N (time advances by 1/60 s a frame).
  bool debug_targets = false;           ///< --debug-targets.
  std::string device;                   ///< --device lavapipe|gpu|NAME.
  bool validation = false;              ///< --validation.
  std::vector<std::string> effects;     ///< --effect NAME (repeatable), in order.
  /// --set EFFECT[@K].KEY=VALUE (repeatable): (effect, key, value text), checked against the
  /// schema; "EFFECT@K" sets only the K-th (1-based) --effect EFFECT, plain "EFFECT" every one.
  std::vector<std::array<std::string, 3>> sets;
  /// --capture-budget N: cube faces all probes together capture a frame (CaptureBudget).
  std::optional<std::uint32_t> capture_budget;
  std::string json; ///< bench: --json FILE.
  /// view: --script FILE, timed actions (docs/viewer.md). "" for none.
  std::string script;
  /// view: --present fifo|mailbox (VK_PRESENT_MODE_*_KHR). Default fifo.
  std::string present = "fifo";
};

/// A parsed command line.
struct Command {
  std::string name; ///< "render", "bench", "view", "list", "info", "help".
  RenderOptions render;
};

/// Parses argv (without the program name). Errors are one line, naming the argument.
[[nodiscard]] Result<Command> parse(const std::vector<std::string>& args);

/// The --help text.
[[nodiscard]] std::string help_text();

/// Splits "EFFECT@K" of --set into the effect name and K (0 when there is no "@K").
[[nodiscard]] std::pair<std::string, std::uint32_t> split_instance(const std::string& effect);
/// Parses "x,y,z" (finite numbers) for `what`.
[[nodiscard]] Result<glm::vec3> parse_vec3(const std::string& text, const std::string& what);

} // namespace snell::cli

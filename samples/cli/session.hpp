// The state one `snell render` / `snell bench` / `snell view` run builds: scene, context,
// renderer, effects.
#pragma once

#include "cli_args.hpp"

#include <snell/capture_budget.hpp>
#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/probe_directory.hpp>
#include <snell/scene_renderer.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace snell::cli {

struct Session {
  Scene scene;
  EffectRegistry registry;
  std::optional<Context> ctx;
  std::optional<SceneRenderer> renderer;
  std::optional<FrameRenderer> frame;
  std::optional<CaptureBudget> budget; ///< --capture-budget, shared by the probes.
  ProbeDirectory probes;               ///< Probes published for the other effects.
  std::vector<std::unique_ptr<Effect>> effects;
  CameraDesc camera;
  /// What the effects were created with (`snell view` creates more with it at run time).
  EffectCreateInfo effect_info;

  /// Renders one frame at `time`, with the effects when `with_effects`.
  Result<FrameStats> render(float time, bool with_effects);
};

/// How a host other than `render` / `bench` builds its session (`snell view`).
struct SessionHooks {
  /// Makes the context once the arguments and the scene are checked (`view` opens its window
  /// and adopts its own device here). Default: Context::create from --device and --validation.
  std::function<Result<Context>()> make_context;
  /// Create Session::frame (an owned target of --size, waited for each frame). Default true.
  bool frame_renderer = true;
  /// EffectCreateInfo::frames_in_flight of the effects. Default 2.
  std::uint32_t frames_in_flight = 2;
};

/// Builds a session. `exit_code` is 2 for argument errors (unknown scene, effect, parameter or
/// bad value: checked before any GPU work) and 1 for failures.
Result<std::unique_ptr<Session>> open_session(const RenderOptions& options, int& exit_code,
                                              const SessionHooks& hooks = {});

} // namespace snell::cli

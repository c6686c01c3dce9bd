// The state one `snell render` / `snell bench` run builds: scene, context, renderer, effects.
#pragma once

#include "cli_args.hpp"

#include <snell/capture_budget.hpp>
#include <snell/effect.hpp>
#include <snell/frame.hpp>
#include <snell/probe_directory.hpp>
#include <snell/scene_renderer.hpp>

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

  /// Renders one frame at `time`, with the effects when `with_effects`.
  Result<FrameStats> render(float time, bool with_effects);
};

/// Builds a session. `exit_code` is 2 for argument errors (unknown scene, effect, parameter or
/// bad value: checked before any GPU work) and 1 for failures.
Result<std::unique_ptr<Session>> open_session(const RenderOptions& options, int& exit_code);

} // namespace snell::cli

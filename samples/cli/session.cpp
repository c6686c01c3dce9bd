#include "session.hpp"

#include <snell/builtin_scenes.hpp>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <filesystem>

namespace snell::cli {
namespace {

/// "pool, window, spheres".
std::string builtin_list() {
  std::string known;
  for (std::string_view n : builtin_scene_names()) {
    known += (known.empty() ? "" : ", ") + std::string(n);
  }
  return known;
}

Result<Scene> load_scene(const std::string& name) {
  const std::filesystem::path path(name);
  const std::string ext = path.extension().string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) {
    return fail(ErrorCode::file_not_found, "--scene " + name +
                                               ": is a folder; expected a built-in scene (" +
                                               builtin_list() + ") or a .gltf/.glb file");
  }
  if (ext == ".gltf" || ext == ".glb") {
    return load_gltf(path);
  }
  if (std::filesystem::exists(status)) {
    return fail(ErrorCode::unknown_name, "--scene " + name +
                                             ": not a .gltf or .glb file, nor a built-in scene (" +
                                             builtin_list() + ")");
  }
  auto scene = make_builtin_scene(name);
  if (!scene) {
    return fail(scene.error().code, "--scene: " + scene.error().message + "; or a .gltf/.glb file");
  }
  return scene;
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

} // namespace

Result<std::unique_ptr<Session>> open_session(const RenderOptions& o, int& exit_code,
                                              const SessionHooks& hooks) {
  auto s = std::make_unique<Session>();
  exit_code = 2;
  if (auto r = register_builtin_effects(s->registry); !r) {
    exit_code = 1;
    return r.error();
  }
  // Arguments first (no GPU work): effect names and every --set against the schemas.
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, ParamValue>>>> plan;
  for (const std::string& name : o.effects) {
    const ParamSchema* schema = s->registry.schema(name);
    if (schema == nullptr) {
      std::string known;
      for (const std::string& n : s->registry.names()) {
        if (!known.empty()) {
          known += ", ";
        }
        known += n;
      }
      return fail(ErrorCode::unknown_name,
                  "--effect: unknown effect '" + name + "'; registered effects: " + known);
    }
    plan.push_back({name, {}});
    const auto instance = static_cast<std::uint32_t>(
        std::count_if(plan.begin(), plan.end(), [&](const auto& e) { return e.first == name; }));
    for (const auto& set : o.sets) {
      // "name" sets every instance, "name@K" only the K-th (K checked by the parser).
      if (set[0] != name && set[0] != name + "@" + std::to_string(instance)) {
        continue;
      }
      const ParamSpec* spec = schema->find(set[1]);
      if (spec == nullptr) {
        return fail(ErrorCode::unknown_name,
                    "--set " + name + "." + set[1] +
                        ": unknown parameter; valid: " + schema->key_list());
      }
      auto value = parse_param(*schema, *spec, set[2]);
      if (!value) {
        return fail(ErrorCode::invalid_argument, "--set: " + value.error().message);
      }
      plan.back().second.push_back({set[1], *value});
    }
  }
  auto scene = load_scene(o.scene);
  if (!scene) {
    exit_code = scene.error().code == ErrorCode::unknown_name ? 2 : 1;
    return scene.error();
  }
  s->scene = std::move(*scene);
  exit_code = 1;
  ContextDesc cd;
  cd.validation = o.validation;
  cd.device = o.device;
  auto ctx = hooks.make_context ? hooks.make_context() : Context::create(cd);
  if (!ctx) {
    return ctx.error();
  }
  s->ctx.emplace(std::move(*ctx));
  auto renderer = SceneRenderer::create(*s->ctx, s->scene);
  if (!renderer) {
    return renderer.error();
  }
  s->renderer.emplace(std::move(*renderer));
  if (hooks.frame_renderer) {
    auto frame = FrameRenderer::create(*s->ctx, FrameDesc{.width = o.width,
                                                          .height = o.height,
                                                          .color = ColorFormat::rgba8_srgb,
                                                          .debug_targets = o.debug_targets});
    if (!frame) {
      return frame.error();
    }
    s->frame.emplace(std::move(*frame));
  }
  EffectCreateInfo& info = s->effect_info;
  info.context = &*s->ctx;
  info.color_format = to_vk_format(ColorFormat::rgba8_srgb); // the frame's output format
  info.depth_format = VK_FORMAT_D32_SFLOAT;
  info.frames_in_flight = hooks.frames_in_flight;
  info.scene = &s->scene;
  info.probes = &s->probes;
  if (o.capture_budget) {
    s->budget.emplace(*o.capture_budget);
    info.capture_budget = &*s->budget;
  }
  for (const auto& [name, values] : plan) {
    auto effect = s->registry.create(name, info);
    if (!effect) {
      return effect.error();
    }
    for (const auto& [key, value] : values) {
      if (auto r = (*effect)->set_param(key, value); !r) {
        exit_code = 2;
        return r.error();
      }
    }
    s->effects.push_back(std::move(*effect));
  }
  s->camera = choose_camera(s->scene, o);
  return s;
}

Result<FrameStats> Session::render(float time, bool with_effects) {
  if (!with_effects || effects.empty()) {
    return frame->render(*renderer, camera, time);
  }
  std::vector<Effect*> list;
  for (auto& e : effects) {
    list.push_back(e.get());
  }
  return frame->render(*renderer, camera, time, list, scene.light);
}

} // namespace snell::cli

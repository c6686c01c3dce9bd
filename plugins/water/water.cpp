// The water effect: a reflection pass (and, without a scene snapshot, a refraction pass) into
// its own targets, then the surface inside the host's main rendering. Everything that is not
// water's own logic (targets, rings, descriptors, pipelines, views, clipping, timing, deferred
// destruction) comes from the plugin toolkit (snell/plugin.hpp).
#include "water_internal.hpp"

#include <snell/builtin_scenes.hpp>
#include <snell/math.hpp>
#include <snell/plugin.hpp>

#include "snell_water_shaders.hpp"

#include <glm/matrix.hpp>

#include <cmath>
#include <vector>

namespace snell {
namespace {

/// std140 mirror of plugins/water/shaders/water_common.glsl.
struct WaterBlock {
  glm::mat4 view_proj;
  glm::mat4 refraction_inv_vp;
  glm::vec4 eye, plane, rect, wave, wind, water_color, absorption, light_dir, light_color, fresnel,
      extent, side;
};

enum Binding : std::uint32_t { kUniforms, kReflection, kRefraction, kRefractionDepth, kNormals };

class Water final : public WaterEffect {
public:
  Result<void> init(const EffectCreateInfo& info) {
    ctx_ = info.context;
    frames_in_flight_ = info.frames_in_flight;
    release_ = DeferredRelease(info.frames_in_flight);
    if (info.scene != nullptr) {
      if (const Anchor* a = info.scene->find_anchor("water")) {
        params_.value().height = a->position.y;
        params_.value().center = glm::vec2(a->position.x, a->position.z);
        params_.value().size = glm::max(glm::vec2(a->size.x, a->size.z), glm::vec2(0.01f));
      }
    }
    SNELL_ASSIGN_OR_RETURN(normal_map_, load_normal_map(""));
    // Binding 0 the WaterBlock, 1..4 reflection, refraction, refraction depth, normal map.
    SNELL_TRY(create_surface_bindings(*ctx_,
                                      {.block_size = sizeof(WaterBlock),
                                       .images = 4,
                                       .frames_in_flight = frames_in_flight_,
                                       .label = "water surface"},
                                      ubo_, sets_));
    sets_.set_image(kNormals, normal_map_.view(), ctx_->sampler(StandardSampler::linear_repeat));
    SNELL_ASSIGN_OR_RETURN(
        pipeline_,
        Pipeline::create(
            *ctx_, surface_pipeline_desc(info, "water surface pipeline", water::shaders::water_vert,
                                         water::shaders::water_frag, {sets_.layout()})));
    // The rectangle: the unit quad, placed by the vertex shader from the uniform block.
    SNELL_ASSIGN_OR_RETURN(surface_, Surfaces::shape(*ctx_, Shape::quad));
    return {};
  }

  std::string_view type() const override { return "water"; }

  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    return params_.set(
        key, value, [this](const WaterParams& next) { return apply_normal_map(next.normal_map); });
  }
  Result<ParamValue> get_param(std::string_view key) const override { return params_.get(key); }
  Result<void> set_params(const WaterParams& params) override {
    return params_.set_all(
        params, [this](const WaterParams& next) { return apply_normal_map(next.normal_map); });
  }
  const WaterParams& params() const override { return params_.value(); }
  Span<const DebugTarget> debug_targets() const override { return debug_; }
  bool wants_snapshot() const override {
    return params_.value().refraction_source == WaterRefractionSource::snapshot;
  }
  VkRect2D snapshot_region() const override { return snapshot_region_; }

  Result<void> update(const FrameInfo& info) override {
    frame_ = info.frame_index;
    release_.collect(frame_);
    use_snapshot_ = wants_snapshot() && info.snapshot != nullptr;
    reflection_.set_scale(params_.value().resolution_scale);
    refraction_.set_scale(params_.value().resolution_scale);
    const VkExtent2D e = info.main_view.extent;
    auto made = reflection_.fit(*ctx_, e, frame_, release_);
    if (!made) {
      return made.error();
    }
    bool changed = *made;
    if (!use_snapshot_) {
      auto made_f = refraction_.fit(*ctx_, e, frame_, release_);
      if (!made_f) {
        return made_f.error();
      }
      changed = changed || *made_f;
    }
    if (changed || debug_.empty() || use_snapshot_ != debug_has_snapshot_) {
      debug_.clear();
      reflection_.append_debug_targets(debug_, "water.reflection");
      debug_.pop_back(); // the reflection's depth is of no interest
      if (!use_snapshot_) {
        refraction_.append_debug_targets(debug_, "water.refraction");
      }
      debug_has_snapshot_ = use_snapshot_;
    }
    compute_views(info.main_view);
    // The surface samples the snapshot where the water projects, plus the ripple margin.
    snapshot_region_ = sampled_rect(info.main_view, info.main_view.extent);
    return {};
  }

  Result<void> record_passes(VkCommandBuffer cmd, const FrameInfo& info,
                             SceneSource& scene) override {
    // Both passes only render the screen rectangle the surface can sample (the water's
    // projected bounds plus the largest ripple offset): on lavapipe this skips most of the fill.
    ScenePass pass;
    pass.name = "water.reflection";
    pass.view = reflection_view_;
    pass.scissor = sampled_rect(info.main_view, reflection_.extent());
    if (auto r = record_scene_pass(cmd, scene, reflection_.target(), pass, info.timer); !r) {
      return r;
    }
    if (!use_snapshot_) {
      pass.name = "water.refraction";
      pass.view = refraction_view_;
      return record_scene_pass(cmd, scene, refraction_.target(), pass, info.timer);
    }
    return {};
  }

  Result<void> record_draw(VkCommandBuffer cmd, const FrameInfo& info) override {
    const WaterParams& p = params_.value();
    WaterBlock b{};
    b.view_proj = info.main_view.proj * info.main_view.view;
    const VkSampler clamp = ctx_->sampler(StandardSampler::linear_clamp);
    const VkSampler nearest = ctx_->sampler(StandardSampler::nearest_clamp);
    sets_.set_image(kReflection, reflection_.target().color_view(), clamp);
    if (use_snapshot_) {
      b.refraction_inv_vp = glm::inverse(info.snapshot->view_proj());
      sets_.set_image(kRefraction, info.snapshot->color_view(), clamp);
      sets_.set_image(kRefractionDepth, info.snapshot->depth_view(), nearest);
    } else {
      b.refraction_inv_vp = glm::inverse(refraction_view_.proj * refraction_view_.view);
      sets_.set_image(kRefraction, refraction_.target().color_view(), clamp);
      sets_.set_image(kRefractionDepth, refraction_.target().depth_view(), nearest);
    }
    b.eye = glm::vec4(info.main_view.eye, 1.0f);
    b.plane = glm::vec4(0.0f, 1.0f, 0.0f, -p.height);
    b.rect = glm::vec4(p.center, p.size);
    glm::vec2 wind =
        glm::length(p.wind_direction) > 1e-6f ? glm::normalize(p.wind_direction) : glm::vec2(0.0f);
    wind *= p.wind_force;
    // The second layer drifts 37 degrees off the wind at 0.7 of its speed, so the two layers
    // never move in lock-step (that would show the tiling) while both go downwind.
    const glm::vec2 wind2 =
        0.7f * glm::vec2(wind.x * 0.8f - wind.y * 0.6f, wind.x * 0.6f + wind.y * 0.8f);
    b.wave = glm::vec4(1.0f / p.wave_length, p.wave_height, p.distortion, info.time);
    b.wind = glm::vec4(wind, wind2);
    b.water_color = glm::vec4(p.water_color, p.color_blend);
    b.absorption = glm::vec4(p.absorption, p.shore_softness);
    b.light_dir = glm::vec4(glm::normalize(info.light.direction), p.specular_intensity);
    b.light_color = glm::vec4(info.light.color * info.light.intensity, p.specular_power);
    b.fresnel = glm::vec4(static_cast<float>(p.fresnel), 1.0f / p.ior, f0_from_ior(1.0f, p.ior),
                          static_cast<float>(p.debug_view));
    const VkExtent2D e = info.main_view.extent;
    b.extent =
        glm::vec4(float(e.width), float(e.height), 1.0f / float(e.width), 1.0f / float(e.height));
    b.side = glm::vec4(underwater_ ? -1.0f : 1.0f, p.ior, p.reflectance, 0.0f);
    auto offset = ubo_.push(frame_, b);
    if (!offset) {
      return offset.error();
    }
    pipeline_.bind(cmd);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
    sets_.bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout(), frame_, &*offset, 1);
    surface_.draw(cmd, 0);
    return {};
  }

private:
  /// The procedural ripples for "", else the file (linear data, mips).
  Result<Texture2D> load_normal_map(const std::string& file) const {
    if (!file.empty()) {
      auto tex = Texture2D::load(*ctx_, file, false, true);
      if (!tex) {
        return fail(tex.error().code, "water.normal_map: " + tex.error().message);
      }
      return tex;
    }
    auto normals = make_noise_normal_map(256, 1.0f, 7u);
    if (!normals) {
      return normals.error();
    }
    normals->name = "water ripples";
    return Texture2D::create(*ctx_, *normals, true);
  }

  /// Loads a new normal map when the path changed; the old one stays on error, and is
  /// destroyed past the frames in flight when replaced.
  Result<void> apply_normal_map(const std::string& file) {
    if (file == params_.value().normal_map && normal_map_.view() != VK_NULL_HANDLE) {
      return {};
    }
    auto tex = load_normal_map(file);
    if (!tex) {
      return tex.error();
    }
    release_.retire(frame_, std::move(normal_map_));
    normal_map_ = std::move(*tex);
    sets_.set_image(kNormals, normal_map_.view(), ctx_->sampler(StandardSampler::linear_repeat));
    return {};
  }

  void compute_views(const SceneView& main) {
    const WaterParams& p = params_.value();
    // Reflection: mirrored camera; refraction: the main camera. Seen from above the water the
    // reflection keeps y >= height - clip_offset and the refraction y <= height + clip_offset;
    // from below (underwater_) the sides swap: the surface reflects the underwater scene (total
    // internal reflection) and refracts the world above. The layer masks name the side an
    // object is seen on (reflection_layers: above the water, refraction_layers: below).
    const Plane mirror{{0.0f, 1.0f, 0.0f}, -p.height};
    const Plane keep_above{{0.0f, 1.0f, 0.0f}, -(p.height - p.clip_offset)};
    const Plane keep_below{{0.0f, -1.0f, 0.0f}, p.height + p.clip_offset};
    underwater_ = signed_distance(mirror, main.eye) < 0.0f;
    const auto above_layers = static_cast<std::uint32_t>(p.reflection_layers);
    const auto below_layers = static_cast<std::uint32_t>(p.refraction_layers);
    const PlaneClip clip =
        p.clip_mode == WaterClipMode::oblique ? PlaneClip::oblique : PlaneClip::clip_distance;
    SceneView r = mirrored_view(main, mirror);
    r.layer_mask = underwater_ ? below_layers : above_layers;
    clip_view(r, underwater_ ? keep_below : keep_above, clip);
    aim_at(r, reflection_.target());
    reflection_view_ = r;
    if (!use_snapshot_) {
      SceneView f = main;
      f.layer_mask = underwater_ ? above_layers : below_layers;
      clip_view(f, underwater_ ? keep_above : keep_below, clip);
      aim_at(f, refraction_.target());
      refraction_view_ = f;
    }
  }

  /// The rectangle of a target of `extent` covering the main view's screen area that the
  /// surface samples: the water's projected bounds widened by the largest lookup offset
  /// (|slope| <= 2 sqrt(2) wave_height, times distortion, in uv) and two texels for the
  /// bilinear and gather footprints.
  [[nodiscard]] VkRect2D sampled_rect(const SceneView& main, VkExtent2D extent) const {
    const WaterParams& p = params_.value();
    const glm::vec2 half = 0.5f * p.size;
    const Aabb water{{p.center.x - half.x, p.height, p.center.y - half.y},
                     {p.center.x + half.x, p.height, p.center.y + half.y}};
    const glm::vec2 size(static_cast<float>(extent.width), static_cast<float>(extent.height));
    const glm::vec2 margin = 2.83f * p.wave_height * p.distortion * size + 2.0f;
    return screen_rect(main.proj * main.view, water, extent, margin);
  }

  const Context* ctx_ = nullptr;
  std::uint32_t frames_in_flight_ = 2;
  VkRect2D snapshot_region_{}; ///< Main-view pixels the surface samples (this frame).
  DeferredRelease release_;
  ParamStore<WaterParams> params_{detail::water_table(), WaterParams{}};
  bool underwater_ = false;   ///< The eye is below the plane (this frame).
  bool use_snapshot_ = false; ///< Refraction from FrameInfo::snapshot this frame.
  bool debug_has_snapshot_ = false;
  std::uint64_t frame_ = 0;
  SceneView reflection_view_, refraction_view_;
  ScaledTarget reflection_{{.scale = 0.5f, .label = "water reflection"}};
  ScaledTarget refraction_{{.scale = 0.5f, .label = "water refraction"}};
  Texture2D normal_map_;
  UniformRing ubo_;
  DescriptorSets sets_;
  Pipeline pipeline_;
  Surfaces surface_;
  std::vector<DebugTarget> debug_;
};

} // namespace

Result<std::unique_ptr<WaterEffect>> create_water(const EffectCreateInfo& info) {
  SNELL_TRY(check_create_info(info, "water"));
  auto water = std::make_unique<Water>();
  if (auto r = water->init(info); !r) {
    return r.error();
  }
  return std::unique_ptr<WaterEffect>(std::move(water));
}

Result<void> register_water(EffectRegistry& registry) {
  return registry.add("water", effect_factory(create_water), water_schema());
}

} // namespace snell

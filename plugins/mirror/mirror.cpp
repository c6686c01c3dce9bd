// The planar mirror: per frame, the host's scene from the mirrored camera into a scaled target
// (scissored to the mirror on screen, clipped 1 mm in front of the plane), then the mirror's
// surface inside the host's main rendering. Everything but the mirror's own shading comes from
// the plugin toolkit (scene passes, scaled targets, surfaces, descriptors, parameters).
#include "mirror_internal.hpp"

#include <snell/math.hpp>
#include <snell/plugin.hpp>

#include "snell_mirror_shaders.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace snell {
namespace {

/// std140 mirror of MirrorBlock in plugins/mirror/shaders/mirror_common.glsl.
struct MirrorBlock {
  glm::mat4 view_proj, model, inv_reflection;
  glm::vec4 plane, eye, extent, tint, base_color, back_color, distortion;
};

enum Binding : std::uint32_t { kUniforms, kReflection, kReflectionDepth, kNormalMap };

/// The reflection pass keeps what stands at least this far in front of the plane, m: the
/// mirror's own mesh (on the plane) never shows in its reflection.
constexpr float kClipOffset = 1e-3f;

/// A flat tangent-space normal (0, 0, 1): the normal map when none is given.
Image flat_normal_image() {
  Image image;
  image.name = "mirror flat normal";
  image.width = 1;
  image.height = 1;
  image.rgba8 = {128, 128, 255, 255};
  image.srgb = false;
  return image;
}

class Mirror final : public MirrorEffect {
public:
  Result<void> init(const EffectCreateInfo& info) {
    ctx_ = info.context;
    scene_ = info.scene;
    release_ = DeferredRelease(info.frames_in_flight);
    if (scene_ != nullptr) {
      if (const Anchor* a = scene_->find_anchor("mirror")) {
        params_.value().center = a->position;
        if (a->object >= 0 && static_cast<std::size_t>(a->object) < scene_->objects.size()) {
          params_.value().node = scene_->objects[static_cast<std::size_t>(a->object)].name;
        }
      }
    }
    SNELL_TRY(apply(params_.value(), true));
    SNELL_TRY(create_surface_bindings(*ctx_,
                                      {.block_size = sizeof(MirrorBlock),
                                       .images = 3,
                                       .frames_in_flight = info.frames_in_flight,
                                       .label = "mirror surface"},
                                      ubo_, sets_));
    sets_.set_image(kNormalMap, normal_map_.view(), ctx_->sampler(StandardSampler::linear_repeat));
    GraphicsPipelineDesc desc =
        surface_pipeline_desc(info, "mirror surface pipeline", mirror::shaders::mirror_vert,
                              mirror::shaders::mirror_frag, {sets_.layout()});
    // The mirror is opaque: it writes depth, so a surface drawn after it (another mirror, a
    // glass pane) that lies behind it stays hidden.
    desc.state.depth_write = true;
    variants_ = PipelineVariants(std::move(desc));
    return {};
  }

  std::string_view type() const override { return "mirror"; }
  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    return params_.set(key, value, [this](const MirrorParams& next) { return apply(next, false); });
  }
  Result<ParamValue> get_param(std::string_view key) const override { return params_.get(key); }
  Result<void> set_params(const MirrorParams& params) override {
    return params_.set_all(params, [this](const MirrorParams& next) { return apply(next, false); });
  }
  const MirrorParams& params() const override { return params_.value(); }
  Span<const DebugTarget> debug_targets() const override { return debug_; }
  glm::vec4 plane() const override { return plane_; }
  /// The node's mesh: covered by the mirror in the main view, still seen by other mirrors.
  Span<const int> replaced_objects() const override { return surface_.objects(); }

  MirrorHostView host_view() const override {
    MirrorHostView v;
    v.color = reflection_.target().color_view();
    v.sampler = ctx_->sampler(StandardSampler::linear_clamp);
    v.texture_matrix =
        clip_to_uv(ClipConvention::vulkan) * reflection_view_.proj * reflection_view_.view;
    v.plane = plane_;
    v.mip_levels = reflection_.target().mip_levels();
    v.drawn = !behind_;
    return v;
  }

  Result<void> update(const FrameInfo& info) override {
    frame_ = info.frame_index;
    release_.collect(frame_);
    time_ = info.time;
    const MirrorParams& p = params_.value();
    reflection_.set_scale(p.resolution_scale);
    reflection_.set_mips(p.roughness > 0.0f); // a sharp mirror reads level 0 only
    bool made = false;
    SNELL_ASSIGN_OR_RETURN(made, reflection_.fit(*ctx_, info.main_view.extent, frame_, release_));
    if (made || debug_.empty()) {
      debug_.clear();
      reflection_.append_debug_targets(debug_, "mirror.reflection");
    }
    const SceneView& main = info.main_view;
    place(p, main.eye);
    const Plane mirror = plane_from_vec4(plane_);
    // Behind the mirror (or on it): nothing to reflect, the surface shows its back.
    behind_ = !(signed_distance(mirror, main.eye) > kClipOffset);
    if (!behind_) {
      SceneView r = mirrored_view(main, mirror);
      r.layer_mask = static_cast<std::uint32_t>(p.reflection_layers);
      const Plane keep{mirror.normal, mirror.d - kClipOffset};
      clip_view(r, keep,
                p.clip == MirrorClip::oblique ? PlaneClip::oblique : PlaneClip::clip_distance);
      aim_at(r, reflection_.target());
      reflection_view_ = r;
      // Only the mirror's pixels are drawn (plus the distortion's reach and the filter's).
      const glm::vec2 size(static_cast<float>(reflection_.extent().width),
                           static_cast<float>(reflection_.extent().height));
      const float reach = normal_map_given_ ? p.distortion : 0.0f;
      // A rough mirror's blur reads the target around each pixel, up to the widest lobe (what
      // is infinitely far: 2 roughness^2 of tan(angle), shaders/snell/mirror.glsl), from mip
      // texels up to twice that wide (trilinear: the next level too): that much more is drawn,
      // so its mips hold the scene there and not an old clear.
      const float focal = std::abs(r.proj[1][1]) * 0.5f * size.y;
      const float blur = 4.0f * p.roughness * p.roughness * focal;
      scissor_ = screen_rect(main.proj * main.view, world_bounds_, reflection_.extent(),
                             reach * size + blur + 2.0f);
    }
    return pick_variant(p);
  }

  Result<void> record_passes(VkCommandBuffer cmd, const FrameInfo& info,
                             SceneSource& scene) override {
    if (behind_) {
      return {};
    }
    ScenePass pass;
    pass.name = "mirror.reflection";
    pass.view = reflection_view_;
    pass.scissor = scissor_;
    return record_scene_pass(cmd, scene, reflection_.target(), pass, info.timer);
  }

  Result<void> record_draw(VkCommandBuffer cmd, const FrameInfo& info) override {
    const MirrorParams& p = params_.value();
    const SceneView& main = info.main_view;
    MirrorBlock b{};
    b.view_proj = main.proj * main.view;
    b.inv_reflection = glm::inverse(reflection_view_.proj * reflection_view_.view);
    b.plane = plane_;
    b.eye = glm::vec4(main.eye, behind_ ? 1.0f : 0.0f);
    const RenderTarget& target = reflection_.target();
    // Pixels per unit of tan(angle) in the reflection target: its height x proj[1][1] / 2.
    const float focal =
        std::abs(reflection_view_.proj[1][1]) * 0.5f * static_cast<float>(target.height());
    b.extent = glm::vec4(1.0f / static_cast<float>(main.extent.width),
                         1.0f / static_cast<float>(main.extent.height), focal,
                         static_cast<float>(target.mip_levels()));
    b.tint = glm::vec4(p.tint, p.roughness);
    b.base_color = glm::vec4(p.base_color, p.ior);
    b.back_color = glm::vec4(p.back_color, p.fade_distance);
    b.distortion = glm::vec4(p.distortion, p.normal_tiles, 0.0f, 0.0f);
    sets_.set_image(kReflection, target.color_view(), ctx_->sampler(StandardSampler::linear_clamp));
    sets_.set_image(kReflectionDepth, target.depth_view(),
                    ctx_->sampler(StandardSampler::nearest_clamp));
    pipeline_->bind(cmd);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE); // both sides: the back shows back_color
    vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
    for (std::size_t i = 0; i < surface_.size(); ++i) {
      b.model = model_;
      std::uint32_t offset = 0;
      SNELL_ASSIGN_OR_RETURN(offset, ubo_.push(frame_, b));
      sets_.bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->layout(), frame_, &offset, 1);
      surface_.draw(cmd, i);
    }
    return {};
  }

private:
  /// Checks `next` and takes what changed: the node's mesh and plane (or the rectangle's
  /// geometry), the normal map. Nothing changes on error. `first`: everything is taken.
  Result<void> apply(const MirrorParams& next, bool first) {
    const MirrorParams& now = params_.value();
    if (first || next.node != now.node) {
      Surfaces surface;
      int object = -1;
      detail::MeshPlane fitted;
      if (next.node.empty()) {
        SNELL_ASSIGN_OR_RETURN(surface, Surfaces::shape(*ctx_, Shape::quad));
      } else {
        SNELL_ASSIGN_OR_RETURN(object, find_object(next.node));
        const Object& o = scene_->objects[static_cast<std::size_t>(object)];
        SNELL_ASSIGN_OR_RETURN(
            fitted, detail::fit_mesh_plane(scene_->meshes[static_cast<std::size_t>(o.mesh)],
                                           next.node, "mirror.node"));
        SNELL_ASSIGN_OR_RETURN(
            surface, Surfaces::from_scene(*ctx_, *scene_,
                                          [&o](const Object& other, const Mesh&, const Material&) {
                                            return &other == &o;
                                          }));
      }
      if (!surface_.empty()) {
        release_.retire(frame_, std::move(surface_));
      }
      surface_ = std::move(surface);
      object_ = object;
      local_ = fitted;
    }
    if (first || next.normal_map != now.normal_map) {
      Texture2D texture;
      if (next.normal_map.empty()) {
        SNELL_ASSIGN_OR_RETURN(texture, Texture2D::create(*ctx_, flat_normal_image(), false));
      } else {
        auto loaded = Texture2D::load(*ctx_, next.normal_map, false, true);
        if (!loaded) {
          return fail(loaded.error().code, "mirror.normal_map: " + loaded.error().message);
        }
        texture = std::move(*loaded);
      }
      if (normal_map_.view() != VK_NULL_HANDLE) {
        release_.retire(frame_, std::move(normal_map_));
      }
      normal_map_ = std::move(texture);
      normal_map_given_ = !next.normal_map.empty();
      if (sets_) {
        sets_.set_image(kNormalMap, normal_map_.view(),
                        ctx_->sampler(StandardSampler::linear_repeat));
      }
    }
    return {};
  }

  /// The index of the scene object called `name`; errors name mirror.node and the value.
  Result<int> find_object(const std::string& name) const {
    if (scene_ != nullptr) {
      for (std::size_t i = 0; i < scene_->objects.size(); ++i) {
        if (scene_->objects[i].name == name && scene_->objects[i].mesh >= 0) {
          return static_cast<int>(i);
        }
      }
    }
    return fail(ErrorCode::invalid_argument,
                "mirror.node: no object with a mesh named '" + name + "' in " +
                    (scene_ != nullptr ? "the scene '" + scene_->name + "'"
                                       : std::string("a host scene (none was given)")));
  }

  /// This frame's plane, model matrix and world bounds: the node's at the frame's time, or the
  /// rectangle's (the unit quad's +Y turned to `normal`, its x to the right, z to -up).
  void place(const MirrorParams& p, glm::vec3 eye) {
    if (object_ >= 0) {
      model_ = scene_->objects[static_cast<std::size_t>(object_)].world_at(time_);
      const Plane world = normalize(transform_plane(plane_from_vec4(local_.plane), model_));
      plane_ = to_vec4(world);
      world_bounds_ = transform_aabb(local_.bounds, model_);
      return;
    }
    // A zero normal faces the eye (as glass's pane does); an up along the normal (or zero)
    // falls back to world +Y, or +Z for a horizontal mirror.
    glm::vec3 n = p.normal;
    if (glm::length(n) < 1e-6f) {
      n = eye - p.center;
      if (glm::length(n) < 1e-6f) {
        n = glm::vec3(0.0f, 0.0f, 1.0f);
      }
    }
    n = glm::normalize(n);
    glm::vec3 up = p.up - glm::dot(p.up, n) * n;
    if (glm::length(up) < 1e-4f) {
      const glm::vec3 world_up = std::abs(n.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
      up = world_up - glm::dot(world_up, n) * n;
    }
    up = glm::normalize(up);
    const glm::vec3 right = glm::cross(up, n);
    model_ = glm::mat4(glm::vec4(right * p.size.x, 0.0f), glm::vec4(n, 0.0f),
                       glm::vec4(-up * p.size.y, 0.0f), glm::vec4(p.center, 1.0f));
    plane_ = to_vec4(plane_from_point_normal(p.center, n));
    world_bounds_ = transform_aabb(Aabb{{-0.5f, 0.0f, -0.5f}, {0.5f, 0.0f, 0.5f}}, model_);
  }

  /// Points pipeline_ at the variant of this frame's features (built the first time).
  Result<void> pick_variant(const MirrorParams& p) {
    SNELL_ASSIGN_OR_RETURN(
        pipeline_, variants_.get(*ctx_, {p.roughness > 0.0f ? 1u : 0u,
                                         p.fresnel == MirrorFresnel::dielectric ? 1u : 0u,
                                         p.fade_distance > 0.0f ? 1u : 0u,
                                         normal_map_given_ && p.distortion > 0.0f ? 1u : 0u}));
    return {};
  }

  const Context* ctx_ = nullptr;
  const Scene* scene_ = nullptr;
  DeferredRelease release_;
  ParamStore<MirrorParams> params_{detail::mirror_table(), MirrorParams{}};
  std::uint64_t frame_ = 0;
  float time_ = 0.0f;
  ScaledTarget reflection_{ScaledTargetDesc{.scale = 0.5f,
                                            .color = ColorFormat::rgba16_float,
                                            .depth = true,
                                            .mips = true,
                                            .label = "mirror reflection"}};
  SceneView reflection_view_{};
  VkRect2D scissor_{};
  bool behind_ = false;                     ///< The eye is behind (or on) the plane this frame.
  Surfaces surface_;                        ///< The node's mesh, or the unit quad.
  int object_ = -1;                         ///< The node's object, or -1 (the rectangle).
  detail::MeshPlane local_{};               ///< The node mesh's plane and bounds in object space.
  glm::mat4 model_{1.0f};                   ///< Mesh to world this frame.
  glm::vec4 plane_{0.0f, 0.0f, 1.0f, 0.0f}; ///< World plane this frame.
  Aabb world_bounds_{};                     ///< The mirror's world bounds this frame.
  Texture2D normal_map_;
  bool normal_map_given_ = false;
  UniformRing ubo_;
  DescriptorSets sets_;
  PipelineVariants variants_; ///< By the shader's constants (roughness, Fresnel, fade, map).
  const Pipeline* pipeline_ = nullptr;
  std::vector<DebugTarget> debug_;
};

} // namespace

Result<std::unique_ptr<MirrorEffect>> create_mirror(const EffectCreateInfo& info) {
  SNELL_TRY(check_create_info(info, "mirror"));
  auto effect = std::make_unique<Mirror>();
  SNELL_TRY(effect->init(info));
  return std::unique_ptr<MirrorEffect>(std::move(effect));
}

Result<void> register_mirror(EffectRegistry& registry) {
  return registry.add("mirror", effect_factory(create_mirror), mirror_schema());
}

} // namespace snell

// The glass and ice effects: a pane and the scene's transmissive objects, drawn inside the host's
// main rendering, seeing what is behind them in the scene snapshot (or in a pass of their own
// when the host gives none). Everything but glass's own optics comes from the plugin toolkit.
#include "glass_internal.hpp"

#include <snell/math.hpp>
#include <snell/plugin.hpp>
#include <snell/probe_directory.hpp>

#include "snell_glass_shaders.hpp"

#include <glm/common.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace snell {
namespace {

constexpr std::size_t kMaxSurfaces = 64; // glass_common.glsl's kMaxSurfaces

/// std140 mirror of GlassSurface in plugins/glass/shaders/glass_common.glsl.
struct SurfaceRecord {
  glm::vec4 center, axis_u, axis_v, normal, tint, attenuation, params;
};

/// std140 mirror of GlassBlock.
struct GlassBlock {
  glm::mat4 view_proj;
  glm::mat4 inv_view_proj;
  glm::vec4 eye, extent, light_dir, light_color, ambient, sky_zenith, sky_horizon, sky_ground, mode;
  glm::vec4 probe_center, probe_box_min, probe_box_max;
  SurfaceRecord surfaces[kMaxSurfaces];
};

/// std140 mirror of GlassDraw: one per draw, from a ring of its own.
struct DrawBlock {
  glm::mat4 model;
  glm::uvec4 index;   ///< surface, count, layers, unused
  SurfaceRecord self; ///< == GlassBlock::surfaces[index.x]
};

enum Binding : std::uint32_t {
  kUniforms,
  kBackground,
  kBackgroundDepth,
  kNormals,
  kColors,
  kDraw,
  kProbeCube
};

/// One surface of this frame: what to draw and its optics.
struct Drawn {
  const Surfaces* set = nullptr; ///< Where the mesh lives (the pane's quad or the scene's).
  std::size_t index = 0;         ///< Its index in `set`.
  glm::mat4 model{1.0f};         ///< Object to world this frame.
  bool cull_back = false; ///< Solid: only the faces toward the eye (the volume does the rest).
  SurfaceRecord record{};
  float distance = 0.0f;     ///< From the eye to its centre (drawn farthest first).
  Aabb bounds{};             ///< World bounds, grown by its thickness.
  std::uint32_t variant = 0; ///< Its pipeline variant (Glass::pipeline_for).
  VkRect2D screen{};         ///< The pixels it may cover or sample (bounds on screen).
};

/// Feature bits of the shader's kFeatures specialization constant (glass_common.glsl).
enum Feature : std::uint32_t {
  kShift = 1u,
  kLayers = 2u,
  kTextured = 4u,
  kRough = 8u,
  kDispersion = 16u,
  kProbe = 32u,
};

/// True when two pixel rectangles share a pixel.
bool overlaps(const VkRect2D& a, const VkRect2D& b) {
  const auto end = [](std::int32_t o, std::uint32_t e) { return std::int64_t{o} + e; };
  return a.offset.x < end(b.offset.x, b.extent.width) &&
         b.offset.x < end(a.offset.x, a.extent.width) &&
         a.offset.y < end(b.offset.y, b.extent.height) &&
         b.offset.y < end(a.offset.y, a.extent.height);
}

/// The features one surface needs alone.
std::uint32_t features_of(const SurfaceRecord& r) {
  std::uint32_t f = 0;
  f |= r.center.w > 0.0f ? kShift : 0u;
  f |= r.params.w > 0.0f ? kTextured : 0u;
  f |= r.normal.w > 0.0f ? kRough : 0u;
  f |= r.params.x > 0.0f ? kDispersion : 0u;
  return f;
}

/// The scale of a world transform along an object-space direction, for thicknesses given "in
/// the mesh's coordinate space" (KHR_materials_volume): the distance between two planes `t`
/// apart along the unit object normal `n` is t / |M^-T n| in world space.
float thickness_scale(const glm::mat4& model, glm::vec3 n) {
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
  const float len = glm::length(normal_matrix * n);
  return len > 1e-12f ? 1.0f / len : 0.0f;
}

class Glass final : public GlassEffect {
public:
  explicit Glass(GlassKind kind)
      : kind_(kind), params_(detail::glass_table(kind),
                             kind == GlassKind::ice ? ice_defaults() : GlassParams{}) {}

  Result<void> init(const EffectCreateInfo& info) {
    ctx_ = info.context;
    scene_ = info.scene;
    frames_in_flight_ = info.frames_in_flight;
    probes_ = info.probes;
    release_ = DeferredRelease(info.frames_in_flight);
    if (scene_ != nullptr) {
      SNELL_TRY(take_scene_objects());
      if (const Anchor* a = scene_->find_anchor("window")) {
        params_.value().center = a->position;
        params_.value().size = glm::max(glm::vec2(a->size.x, a->size.y), glm::vec2(0.01f));
      } else if (!scene_surfaces_.empty()) {
        params_.value().pane = false; // a glTF scene with glass of its own needs no extra pane
      }
    }
    SNELL_ASSIGN_OR_RETURN(normal_map_, load_texture("normal_map", "", false));
    SNELL_ASSIGN_OR_RETURN(color_map_, load_texture("color_texture", "", true));
    SNELL_ASSIGN_OR_RETURN(draws_,
                           UniformRing::create(*ctx_, {.block_size = sizeof(DrawBlock),
                                                       .blocks_per_frame = kMaxSurfaces,
                                                       .frames_in_flight = frames_in_flight_,
                                                       .label = "glass draw uniforms"}));
    // Binding 0 the frame's GlassBlock, 1..4 the images, 5 this draw's DrawBlock.
    SNELL_TRY(create_surface_bindings(
        *ctx_,
        {.block_size = sizeof(GlassBlock),
         .images = 4,
         .extra = {{.binding = kDraw,
                    .type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                    .stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                   {.binding = kProbeCube}},
         .frames_in_flight = frames_in_flight_,
         .label = "glass surfaces"},
        ubo_, sets_));
    sets_.set_buffer(kDraw, draws_.buffer(), 0, draws_.block_size());
    const VkSampler repeat = ctx_->sampler(StandardSampler::linear_repeat);
    sets_.set_image(kNormals, normal_map_.view(), repeat);
    sets_.set_image(kColors, color_map_.view(), repeat);
    // Bound while no probe is: the variants without kProbe never read it.
    SNELL_ASSIGN_OR_RETURN(no_probe_,
                           CubeTarget::create(*ctx_, CubeTargetDesc{
                                                         .size = 1,
                                                         .mips = false,
                                                         .debug_name = "glass no-probe cube",
                                                     }));
    sets_.set_image(kProbeCube, no_probe_.cube_view(),
                    ctx_->sampler(StandardSampler::linear_clamp));
    bound_probe_view_ = no_probe_.cube_view();
    variants_ = PipelineVariants(
        surface_pipeline_desc(info, "glass surface pipeline", glass::shaders::glass_vert,
                              glass::shaders::glass_frag, {sets_.layout()}));
    SNELL_ASSIGN_OR_RETURN(pane_, Surfaces::shape(*ctx_, Shape::quad));
    return {};
  }

  std::string_view type() const override { return kind_ == GlassKind::ice ? "ice" : "glass"; }

  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    return params_.set(key, value,
                       [this](const GlassParams& next) { return apply_textures(next); });
  }
  Result<ParamValue> get_param(std::string_view key) const override { return params_.get(key); }
  Result<void> set_params(const GlassParams& params) override {
    return params_.set_all(params,
                           [this](const GlassParams& next) { return apply_textures(next); });
  }
  const GlassParams& params() const override { return params_.value(); }
  std::size_t surface_count() const override {
    return (params_.value().pane ? 1u : 0u) + scene_surfaces_.size();
  }
  Span<const DebugTarget> debug_targets() const override { return debug_; }
  bool wants_snapshot() const override { return !drawn_.empty(); }
  bool wants_snapshot_mips() const override { return rough_; }
  VkRect2D snapshot_region() const override { return region_; }
  Span<const int> drawn_objects() const override { return scene_surfaces_.objects(); }

  Result<void> update(const FrameInfo& info) override {
    frame_ = info.frame_index;
    release_.collect(frame_);
    use_snapshot_ = info.snapshot != nullptr;
    collect_surfaces(info);
    SNELL_TRY(make_variants());
    if (!use_snapshot_ && !drawn_.empty()) {
      // No snapshot from the host: the effect renders the opaque scene behind itself.
      bool made = false;
      SNELL_ASSIGN_OR_RETURN(made, own_.fit(*ctx_, info.main_view.extent, frame_, release_));
      if (made || debug_.empty()) {
        debug_.clear();
        own_.append_debug_targets(debug_, std::string(type()) + ".background");
      }
    } else if (!debug_.empty()) {
      debug_.clear();
    }
    return {};
  }

  Result<void> record_passes(VkCommandBuffer cmd, const FrameInfo& info,
                             SceneSource& scene) override {
    if (use_snapshot_ || drawn_.empty()) {
      return {};
    }
    ScenePass pass;
    pass.name = kind_ == GlassKind::ice ? "ice.background" : "glass.background";
    pass.view = info.main_view;
    aim_at(pass.view, own_.target());
    pass.scissor = region_;
    return record_scene_pass(cmd, scene, own_.target(), pass, info.timer);
  }

  Result<void> record_draw(VkCommandBuffer cmd, const FrameInfo& info) override {
    if (drawn_.empty()) {
      return {};
    }
    const SceneView& main = info.main_view;
    auto block = std::make_unique<GlassBlock>();
    GlassBlock& b = *block;
    b.view_proj = main.proj * main.view;
    const VkSampler clamp = ctx_->sampler(StandardSampler::linear_clamp);
    const VkSampler nearest = ctx_->sampler(StandardSampler::nearest_clamp);
    std::uint32_t levels = 1;
    VkExtent2D bg_extent = main.extent;
    if (use_snapshot_) {
      b.inv_view_proj = glm::inverse(info.snapshot->view_proj());
      sets_.set_image(kBackground, info.snapshot->color_view(), clamp);
      sets_.set_image(kBackgroundDepth, info.snapshot->depth_view(), nearest);
      levels = rough_ ? info.snapshot->mip_levels() : 1u;
      bg_extent = info.snapshot->extent();
    } else {
      b.inv_view_proj = glm::inverse(b.view_proj); // the pass used the main view's matrices
      sets_.set_image(kBackground, own_.target().color_view(), clamp);
      sets_.set_image(kBackgroundDepth, own_.target().depth_view(), nearest);
      levels = own_.target().mip_levels();
    }
    const GlassParams& p = params_.value();
    b.eye = glm::vec4(main.eye, 0.0f);
    const VkExtent2D e = main.extent;
    b.extent =
        glm::vec4(float(e.width), float(e.height), 1.0f / float(e.width), 1.0f / float(e.height));
    b.light_dir = glm::vec4(glm::normalize(info.light.direction), p.specular_intensity);
    b.light_color = glm::vec4(info.light.color * info.light.intensity, p.specular_power);
    b.ambient = glm::vec4(info.light.ambient, static_cast<float>(levels - 1));
    const Sky sky = scene_ != nullptr ? scene_->sky : Sky{};
    b.sky_zenith = glm::vec4(sky.zenith, 0.0f);
    b.sky_horizon = glm::vec4(sky.horizon, 0.0f);
    b.sky_ground = glm::vec4(sky.ground, 0.0f);
    const float size_log2 =
        std::log2(static_cast<float>(std::max(bg_extent.width, bg_extent.height)));
    b.mode = glm::vec4(0.0f, 0.0f, 0.0f, size_log2);
    for (std::size_t i = 0; i < drawn_.size(); ++i) {
      b.surfaces[i] = drawn_[i].record;
    }
    // The probe nearest to the surfaces (published this frame in phase 2), if any.
    const ProbeView* probe = nullptr;
    if (probes_ != nullptr) {
      glm::vec3 middle(0.0f);
      for (const Drawn& d : drawn_) {
        middle += glm::vec3(d.record.center) / static_cast<float>(drawn_.size());
      }
      probe = probes_->nearest(middle);
    }
    const VkImageView probe_view = probe != nullptr ? probe->cube : no_probe_.cube_view();
    if (probe_view != bound_probe_view_) { // re-pointed only when it changes
      sets_.set_image(kProbeCube, probe_view, probe != nullptr ? probe->sampler : clamp);
      bound_probe_view_ = probe_view;
    }
    if (probe != nullptr) {
      if (std::any_of(drawn_.begin(), drawn_.end(),
                      [](const Drawn& d) { return d.record.normal.w > 0.0f; })) {
        probes_->want_levels(probe); // a rough surface reads the probe's blurred levels
      }
      b.probe_center = glm::vec4(probe->center, static_cast<float>(probe->mip_levels));
      b.probe_box_min = glm::vec4(probe->box_min, probe->box_projection ? 1.0f : 0.0f);
      b.probe_box_max = glm::vec4(probe->box_max, 0.0f);
    }
    std::uint32_t offset = 0;
    SNELL_ASSIGN_OR_RETURN(offset, ubo_.push(frame_, b));
    // Farthest first: a nearer surface is drawn over a farther one, and sees it by tracing.
    std::vector<std::size_t> order(drawn_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) {
      return drawn_[a].distance > drawn_[c].distance;
    });
    // Alone, nothing can stand behind a surface: one layer.
    const auto layers = drawn_.size() > 1 ? static_cast<std::uint32_t>(p.max_layers) : 1u;
    const Pipeline* bound = nullptr;
    for (const std::size_t i : order) {
      const Drawn& d = drawn_[i];
      const DrawBlock draw{d.model,
                           glm::uvec4(static_cast<std::uint32_t>(i),
                                      static_cast<std::uint32_t>(drawn_.size()), layers, 0u),
                           d.record};
      const Pipeline* variant = nullptr;
      SNELL_ASSIGN_OR_RETURN(variant, pipeline_for(d.variant | (probe != nullptr ? kProbe : 0u)));
      const Pipeline& pipeline = *variant;
      if (&pipeline != bound) {
        pipeline.bind(cmd);
        bound = &pipeline;
      }
      std::uint32_t offsets[2] = {offset, 0}; // dynamic offsets in binding order: 0, then 5
      SNELL_ASSIGN_OR_RETURN(offsets[1], draws_.push(frame_, draw));
      sets_.bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), frame_, offsets, 2);
      vkCmdSetCullMode(cmd, d.cull_back ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
      // A mirroring transform turns the winding around.
      const bool mirrored = glm::determinant(glm::mat3(d.model)) < 0.0f;
      vkCmdSetFrontFace(cmd, mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
      d.set->draw(cmd, d.index);
    }
    return {};
  }

private:
  /// Picks each surface's pipeline variant (its features; with layers, everything the surfaces
  /// behind it may need; the debug view and Fresnel mode) and builds the ones not built yet.
  /// A few variants exist in practice; each is built once (a shader compile on lavapipe).
  Result<void> make_variants() {
    const bool layered = drawn_.size() > 1 && params_.value().max_layers > 1;
    const std::uint32_t modes = static_cast<std::uint32_t>(params_.value().debug_view) << 8 |
                                static_cast<std::uint32_t>(params_.value().fresnel) << 12;
    for (Drawn& d : drawn_) {
      std::uint32_t features = features_of(d.record);
      // Tracing only where a flat surface may stand behind this one on screen, and only with
      // what those surfaces need (dispersion applies at the first surface alone).
      for (const Drawn& other : drawn_) {
        if (layered && &other != &d && other.record.axis_u.w > 0.5f &&
            overlaps(d.screen, other.screen)) {
          features |= kLayers | (features_of(other.record) & ~std::uint32_t{kDispersion});
        }
      }
      d.variant = features | modes;
      SNELL_TRY(pipeline_for(d.variant));
    }
    return {};
  }

  /// The pipeline of `variant` (features | debug view << 8 | fresnel << 12), built the first
  /// time it is asked for. kProbe is added in record_draw, once the probes have published.
  Result<const Pipeline*> pipeline_for(std::uint32_t variant) {
    return variants_.get(
        *ctx_, {variant & 0xFFu, variant >> 8 & 0xFu, (variant >> 12 & 0xFu) == 0 ? 1u : 0u});
  }

  /// Uploads the scene's transmissive objects (transmission > 0) once.
  Result<void> take_scene_objects() {
    auto taken =
        Surfaces::from_scene(*ctx_, *scene_, [](const Object&, const Mesh&, const Material& m) {
          return m.transmission > 0.0f;
        });
    if (!taken) {
      return taken.error();
    }
    if (taken->size() + 1 > kMaxSurfaces) {
      return fail(ErrorCode::invalid_argument,
                  std::string(type()) + ": the scene has " + std::to_string(taken->size()) +
                      " transmissive objects; one effect draws at most " +
                      std::to_string(kMaxSurfaces - 1));
    }
    scene_surfaces_ = std::move(*taken);
    return {};
  }

  /// This frame's surfaces: their transforms, optics and the slab each is to tracing.
  void collect_surfaces(const FrameInfo& info) {
    drawn_.clear();
    rough_ = false;
    const glm::vec3 eye = info.main_view.eye;
    if (params_.value().pane) {
      drawn_.push_back(pane_surface(eye));
    }
    for (std::size_t i = 0; i < scene_surfaces_.size(); ++i) {
      drawn_.push_back(object_surface(scene_surfaces_[i], i, info.time, eye));
    }
    // The snapshot pixels the surfaces sample: their bounds (grown by their thickness, which
    // bounds the lateral shift) on screen, plus the normal-map offset and the blur footprint.
    region_ = {};
    const glm::mat4 vp = info.main_view.proj * info.main_view.view;
    const VkExtent2D extent = info.main_view.extent;
    const glm::vec2 size(static_cast<float>(extent.width), static_cast<float>(extent.height));
    for (Drawn& d : drawn_) {
      const float roughness = d.record.normal.w;
      rough_ = rough_ || roughness > 0.0f;
      // A lookup at level L reads texels of levels L and L + 1, up to 1.5 texels of the
      // coarser one away: two texels of level ceil(L) cover it.
      const float level = roughness * std::log2(std::max(size.x, size.y));
      const float blur = roughness > 0.0f ? 2.0f * std::exp2(std::ceil(level)) : 0.0f;
      const glm::vec2 margin = d.record.params.y * size + blur + 2.0f;
      d.screen = screen_rect(vp, d.bounds, extent, margin);
      region_ = rect_union(region_, d.screen);
    }
    if (drawn_.empty()) {
      region_ = VkRect2D{{0, 0}, {1, 1}};
    }
  }

  /// The pane: the unit quad on the slab's face toward the eye.
  Drawn pane_surface(glm::vec3 eye) const {
    const GlassParams& p = params_.value();
    const glm::vec3 toward_eye = eye - p.center;
    const glm::vec3 facing = glm::dot(p.normal, p.normal) > 1e-12f ? p.normal : toward_eye;
    const glm::vec3 n =
        glm::dot(facing, facing) > 1e-12f ? glm::normalize(facing) : glm::vec3(0.0f, 0.0f, 1.0f);
    // Its height runs along world up projected into the plane (world -Z when it faces up/down).
    glm::vec3 up = glm::vec3(0.0f, 1.0f, 0.0f) - n * n.y;
    if (glm::dot(up, up) < 1e-6f) {
      up = glm::vec3(0.0f, 0.0f, -1.0f) - n * -n.z;
    }
    up = glm::normalize(up);
    const glm::vec3 right = glm::normalize(glm::cross(up, n));
    const glm::vec3 half_u = right * (0.5f * p.size.x);
    const glm::vec3 half_v = up * (0.5f * p.size.y);
    const float side = glm::dot(eye - p.center, n) >= 0.0f ? 1.0f : -1.0f;
    const glm::vec3 face = p.center + side * n * (0.5f * p.thickness);
    Drawn d;
    d.set = &pane_;
    d.index = 0;
    // Quad x -> width, y -> the face's normal, z -> down the pane (its v grows downward).
    d.model = glm::mat4(glm::vec4(2.0f * half_u, 0.0f), glm::vec4(side * n, 0.0f),
                        glm::vec4(-2.0f * half_v, 0.0f), glm::vec4(face, 1.0f));
    d.cull_back = false;
    d.record.center = glm::vec4(p.center, p.thickness);
    d.record.axis_u = glm::vec4(half_u, 1.0f);
    d.record.axis_v = glm::vec4(half_v, p.ior);
    d.record.normal = glm::vec4(n, p.roughness);
    d.record.tint = glm::vec4(p.tint, 1.0f);
    d.record.attenuation = glm::vec4(p.attenuation_color, p.attenuation_distance);
    // Texture tiles 0 tells the shader to sample no texture: neither would change anything.
    const bool textured = p.refraction_scale > 0.0f || p.color_blend > 0.0f;
    d.record.params = glm::vec4(p.dispersion, p.refraction_scale, p.color_blend,
                                textured ? p.texture_scale : 0.0f);
    d.distance = glm::distance(eye, p.center);
    const glm::vec3 reach = glm::abs(half_u) + glm::abs(half_v) + glm::abs(n) * 0.5f * p.thickness +
                            glm::vec3(p.thickness);
    d.bounds = Aabb{p.center - reach, p.center + reach};
    return d;
  }

  /// A scene object: its mesh, its material's optics; a slab to tracing when it is flat (its
  /// thinnest side at most a quarter of the next).
  Drawn object_surface(const Surface& s, std::size_t index, float time, glm::vec3 eye) const {
    const Material& m = s.material;
    Drawn d;
    d.set = &scene_surfaces_;
    d.index = index;
    d.model = s.world;
    if (scene_ != nullptr && s.object >= 0) {
      d.model = scene_->objects[static_cast<std::size_t>(s.object)].world_at(time);
    }
    const glm::vec3 dims = s.bounds_max - s.bounds_min;
    int thin = 0;
    for (int k = 1; k < 3; ++k) {
      if (dims[k] < dims[thin]) {
        thin = k;
      }
    }
    const int a = (thin + 1) % 3, c = (thin + 2) % 3;
    glm::vec3 axis(0.0f);
    axis[thin] = 1.0f;
    const float scale = thickness_scale(d.model, axis);
    const float thickness = m.thickness * scale;
    const bool flat = dims[thin] <= 0.25f * std::min(dims[a], dims[c]);
    const glm::vec3 mid = 0.5f * (s.bounds_min + s.bounds_max);
    glm::vec3 ua(0.0f), vc(0.0f);
    ua[a] = 0.5f * dims[a];
    vc[c] = 0.5f * dims[c];
    const glm::mat3 linear(d.model);
    const glm::vec3 n = glm::normalize(glm::transpose(glm::inverse(linear)) * axis);
    const glm::vec3 center = glm::vec3(d.model * glm::vec4(mid, 1.0f));
    const bool solid = m.thickness > 0.0f;
    d.cull_back = solid && !m.double_sided;
    d.record.center = glm::vec4(center, thickness);
    d.record.axis_u = glm::vec4(linear * ua, flat ? 1.0f : 0.0f);
    d.record.axis_v = glm::vec4(linear * vc, std::max(m.ior, 1.0f));
    d.record.normal = glm::vec4(n, glm::clamp(m.roughness, 0.0f, 1.0f));
    d.record.tint = glm::vec4(glm::vec3(m.base_color), m.transmission);
    const bool attenuates = std::isfinite(m.attenuation_distance) && m.attenuation_distance > 0.0f;
    d.record.attenuation = attenuates ? glm::vec4(m.attenuation_color, m.attenuation_distance)
                                      : glm::vec4(1.0f, 1.0f, 1.0f, 1.0f);
    d.record.params = glm::vec4(m.dispersion, 0.0f, 0.0f, 0.0f);
    d.distance = glm::distance(eye, center);
    Aabb box = transform_aabb(Aabb{s.bounds_min, s.bounds_max}, d.model);
    box.min -= glm::vec3(thickness);
    box.max += glm::vec3(thickness);
    d.bounds = box;
    return d;
  }

  /// The built-in texture of this kind for "", else the file; errors name `<effect>.<key>`.
  Result<Texture2D> load_texture(const char* key, const std::string& file, bool srgb) const {
    if (!file.empty()) {
      auto tex = Texture2D::load(*ctx_, file, srgb, true);
      if (!tex) {
        return fail(tex.error().code, std::string(type()) + "." + key + ": " + tex.error().message);
      }
      return tex;
    }
    auto image = srgb ? detail::builtin_glass_color(kind_, 256)
                      : detail::builtin_glass_normal_map(kind_, 256);
    if (!image) {
      return image.error();
    }
    return Texture2D::create(*ctx_, *image, true);
  }

  /// Loads the textures whose paths changed; on any error nothing changes (both are loaded
  /// before either is swapped in). Replaced ones are destroyed past the frames in flight.
  Result<void> apply_textures(const GlassParams& next) {
    const bool new_normals = next.normal_map != params_.value().normal_map;
    const bool new_colors = next.color_texture != params_.value().color_texture;
    Texture2D normals, colors;
    if (new_normals) {
      SNELL_ASSIGN_OR_RETURN(normals, load_texture("normal_map", next.normal_map, false));
    }
    if (new_colors) {
      SNELL_ASSIGN_OR_RETURN(colors, load_texture("color_texture", next.color_texture, true));
    }
    const VkSampler repeat = ctx_->sampler(StandardSampler::linear_repeat);
    if (new_normals) {
      release_.retire(frame_, std::move(normal_map_));
      normal_map_ = std::move(normals);
      sets_.set_image(kNormals, normal_map_.view(), repeat);
    }
    if (new_colors) {
      release_.retire(frame_, std::move(color_map_));
      color_map_ = std::move(colors);
      sets_.set_image(kColors, color_map_.view(), repeat);
    }
    return {};
  }

  GlassKind kind_;
  const Context* ctx_ = nullptr;
  const Scene* scene_ = nullptr;
  std::uint32_t frames_in_flight_ = 2;
  DeferredRelease release_;
  ParamStore<GlassParams> params_;
  std::uint64_t frame_ = 0;
  bool use_snapshot_ = false;
  bool rough_ = false; ///< Some surface samples blurred levels this frame.
  VkRect2D region_{};  ///< Main-view pixels the surfaces sample (this frame).
  std::vector<Drawn> drawn_;
  ScaledTarget own_{{.scale = 1.0f, .mips = true, .label = "glass background"}};
  Texture2D normal_map_, color_map_;
  UniformRing ubo_;
  UniformRing draws_; ///< One DrawBlock per surface drawn.
  DescriptorSets sets_;
  PipelineVariants variants_; ///< The surface pipeline's variants (Drawn::variant's constants).
  ProbeDirectory* probes_ = nullptr;              ///< The host's probes, if any.
  CubeTarget no_probe_;                           ///< Bound while no probe is published.
  VkImageView bound_probe_view_ = VK_NULL_HANDLE; ///< What kProbeCube points at.
  Surfaces pane_, scene_surfaces_;
  std::vector<DebugTarget> debug_;
};

Result<std::unique_ptr<GlassEffect>> create(GlassKind kind, const EffectCreateInfo& info) {
  const char* name = kind == GlassKind::ice ? "ice" : "glass";
  SNELL_TRY(check_create_info(info, name));
  auto glass = std::make_unique<Glass>(kind);
  SNELL_TRY(glass->init(info));
  return std::unique_ptr<GlassEffect>(std::move(glass));
}

EffectFactory factory(GlassKind kind) {
  return effect_factory([kind](const EffectCreateInfo& info) { return create(kind, info); });
}

} // namespace

Result<std::unique_ptr<GlassEffect>> create_glass(const EffectCreateInfo& info) {
  return create(GlassKind::glass, info);
}

Result<std::unique_ptr<GlassEffect>> create_ice(const EffectCreateInfo& info) {
  return create(GlassKind::ice, info);
}

Result<void> register_glass(EffectRegistry& registry) {
  SNELL_TRY(registry.add("glass", factory(GlassKind::glass), glass_schema()));
  return registry.add("ice", factory(GlassKind::ice), ice_schema());
}

} // namespace snell

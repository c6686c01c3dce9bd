// The water effect: reflection and refraction passes into its own targets, then the surface
// inside the host's main rendering.
#include "water_internal.hpp"

#include <snell/buffer.hpp>
#include <snell/builtin_scenes.hpp>
#include <snell/images.hpp>
#include <snell/math.hpp>
#include <snell/pipeline.hpp>

#include "snell_water_shaders.hpp"

#include <glm/matrix.hpp>

#include <cmath>
#include <cstring>
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

constexpr std::uint32_t kSlots = 3; // uniform slots: frames a host may have in flight

template <class T> T vk_struct(VkStructureType type) {
  T v{};
  v.sType = type;
  return v;
}

#define WATER_VK(call, what)                                                                       \
  do {                                                                                             \
    const VkResult r_ = (call);                                                                    \
    if (r_ != VK_SUCCESS) {                                                                        \
      return fail(ErrorCode::vulkan_error, std::string("water: ") + (what) +                       \
                                               " failed (VkResult " + std::to_string(r_) + ")");   \
    }                                                                                              \
  } while (false)

class Water final : public WaterEffect {
public:
  ~Water() override { destroy(); }

  Result<void> init(const EffectCreateInfo& info) {
    ctx_ = info.context;
    color_format_ = info.color_format;
    depth_format_ = info.depth_format;
    if (info.scene != nullptr) {
      if (const Anchor* a = info.scene->find_anchor("water")) {
        params_.height = a->position.y;
        params_.center = glm::vec2(a->position.x, a->position.z);
        params_.size = glm::max(glm::vec2(a->size.x, a->size.z), glm::vec2(0.01f));
      }
    }
    auto tex = load_normal_map("");
    auto repeat = Sampler::create(*ctx_, SamplerDesc{true, true, AddressMode::repeat, 1.0f});
    auto clamp = Sampler::create(*ctx_, SamplerDesc{true, false, AddressMode::clamp_to_edge, 1.0f});
    auto nearest =
        Sampler::create(*ctx_, SamplerDesc{false, false, AddressMode::clamp_to_edge, 1.0f});
    if (!tex || !repeat || !clamp || !nearest) {
      return !tex      ? tex.error()
             : !repeat ? repeat.error()
             : !clamp  ? clamp.error()
                       : nearest.error();
    }
    normal_map_ = std::move(*tex);
    repeat_ = std::move(*repeat);
    clamp_ = std::move(*clamp);
    nearest_ = std::move(*nearest);
    VkDeviceSize align = 256; // conservative minUniformBufferOffsetAlignment
    stride_ = (sizeof(WaterBlock) + align - 1) / align * align;
    auto ubo =
        Buffer::create(*ctx_, BufferDesc{stride_ * kSlots, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                         MemoryUsage::upload, "water uniforms"});
    if (!ubo) {
      return ubo.error();
    }
    ubo_ = std::move(*ubo);
    return create_pipeline();
  }

  std::string_view type() const override { return "water"; }

  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    WaterParams next = params_;
    if (auto r = detail::apply_water_param(next, key, value); !r) {
      return r;
    }
    if (auto r = apply_normal_map(next.normal_map); !r) {
      return r;
    }
    params_ = next;
    if (key == "preset") {
      preset_ = std::get<std::string>(value);
    }
    return {};
  }
  Result<ParamValue> get_param(std::string_view key) const override {
    if (key == "preset") {
      return ParamValue{preset_}; // the last preset applied
    }
    return detail::read_water_param(params_, key);
  }
  Result<void> set_params(const WaterParams& params) override {
    if (auto r = detail::validate_water_params(params); !r) {
      return r;
    }
    if (auto r = apply_normal_map(params.normal_map); !r) {
      return r;
    }
    params_ = params;
    return {};
  }
  const WaterParams& params() const override { return params_; }
  std::span<const DebugTarget> debug_targets() const override { return debug_; }
  const Error* error() const override { return error_ ? &*error_ : nullptr; }

  void update(const FrameInfo& info) override {
    info_ = info;
    const VkExtent2D e = info.main_view.extent;
    const auto scaled = [&](std::uint32_t v) {
      return std::max(
          1u, static_cast<std::uint32_t>(static_cast<float>(v) * params_.resolution_scale + 0.5f));
    };
    const std::uint32_t w = scaled(e.width), h = scaled(e.height);
    if (!reflection_ || reflection_.width() != w || reflection_.height() != h) {
      if (reflection_) {
        vkDeviceWaitIdle(ctx_->device()); // targets may be in use by a frame in flight
      }
      auto r = RenderTarget::create(*ctx_, RenderTargetDesc{w, h, ColorFormat::rgba16_float, true,
                                                            false, "water reflection"});
      auto f = RenderTarget::create(*ctx_, RenderTargetDesc{w, h, ColorFormat::rgba16_float, true,
                                                            false, "water refraction"});
      if (!r || !f) {
        error_ = !r ? r.error() : f.error();
        return;
      }
      reflection_ = std::move(*r);
      refraction_ = std::move(*f);
      write_descriptors();
      debug_ = {
          DebugTarget{"water.reflection", reflection_.color_view(), false,
                      reflection_.color_image(), w, h, reflection_.vk_color_format()},
          DebugTarget{"water.refraction", refraction_.color_view(), false,
                      refraction_.color_image(), w, h, refraction_.vk_color_format()},
          DebugTarget{"water.refraction_depth", refraction_.depth_view(), true,
                      refraction_.depth_image(), w, h, VK_FORMAT_D32_SFLOAT},
      };
    }
    error_.reset();
    compute_views();
  }

  void record_passes(VkCommandBuffer cmd, SceneSource& scene) override {
    if (error_ || !reflection_) {
      return;
    }
    const float clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    if (info_.timer != nullptr) {
      info_.timer->begin(cmd, "water.reflection");
    }
    // Both passes only render the screen rectangle the surface can sample (the water's
    // projected bounds plus the largest ripple offset): on lavapipe this skips most of the fill.
    const VkRect2D scissor = sampled_rect();
    reflection_.begin_rendering(cmd, clear);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    scene.draw_scene(cmd, reflection_view_);
    reflection_.end_rendering(cmd);
    if (info_.timer != nullptr) {
      info_.timer->end(cmd);
      info_.timer->begin(cmd, "water.refraction");
    }
    refraction_.begin_rendering(cmd, clear);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    scene.draw_scene(cmd, refraction_view_);
    refraction_.end_rendering(cmd);
    if (info_.timer != nullptr) {
      info_.timer->end(cmd);
    }
  }

  void record_draw(VkCommandBuffer cmd, const FrameInfo& info) override {
    if (error_ || !reflection_) {
      return;
    }
    const WaterParams& p = params_;
    WaterBlock b{};
    b.view_proj = info.main_view.proj * info.main_view.view;
    b.refraction_inv_vp = glm::inverse(refraction_view_.proj * refraction_view_.view);
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
    const std::uint32_t slot = slot_;
    slot_ = (slot_ + 1) % kSlots;
    std::memcpy(static_cast<char*>(ubo_.mapped()) + stride_ * slot, &b, sizeof(b));
    const std::uint32_t offset = static_cast<std::uint32_t>(stride_ * slot);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 1, &offset);
    vkCmdDraw(cmd, 4, 1, 0, 0);
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

  /// Loads a new normal map when the path changed; the old one stays on error.
  Result<void> apply_normal_map(const std::string& file) {
    if (file == params_.normal_map && normal_map_.view() != VK_NULL_HANDLE) {
      return {};
    }
    auto tex = load_normal_map(file);
    if (!tex) {
      return tex.error();
    }
    vkDeviceWaitIdle(ctx_->device()); // the old map may be in use by a frame in flight
    normal_map_ = std::move(*tex);
    if (reflection_) {
      write_descriptors();
    }
    return {};
  }

  void compute_views() {
    const WaterParams& p = params_;
    const SceneView& main = info_.main_view;
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
    SceneView r = main;
    r.view = reflect_view(main.view, mirror);
    r.eye = reflect_point(mirror, main.eye);
    r.layer_mask = underwater_ ? below_layers : above_layers;
    r.extent = {reflection_.width(), reflection_.height()};
    r.color_format = reflection_.vk_color_format();
    r.depth_format = VK_FORMAT_D32_SFLOAT;
    r.view_mask = 0;
    SceneView f = main;
    f.layer_mask = underwater_ ? above_layers : below_layers;
    f.extent = r.extent;
    f.color_format = refraction_.vk_color_format();
    f.depth_format = VK_FORMAT_D32_SFLOAT;
    f.view_mask = 0;
    clip(r, underwater_ ? keep_below : keep_above);
    clip(f, underwater_ ? keep_above : keep_below);
    r.flip_front_face = needs_front_face_flip(r.view, r.proj);
    f.flip_front_face = needs_front_face_flip(f.view, f.proj);
    reflection_view_ = r;
    refraction_view_ = f;
  }

  /// The texels of the targets the surface shader can read: the projected water rectangle,
  /// widened by the largest lookup offset (|slope| <= 2 sqrt(2) wave_height, times distortion)
  /// and two texels for the bilinear and gather footprints. The whole target when a corner is
  /// behind the eye (the projection of the rectangle is then unbounded).
  [[nodiscard]] VkRect2D sampled_rect() const {
    const VkRect2D full{{0, 0}, {reflection_.width(), reflection_.height()}};
    const WaterParams& p = params_;
    const glm::mat4 vp = info_.main_view.proj * info_.main_view.view;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int i = 0; i < 4; ++i) {
      const glm::vec2 corner =
          p.center + 0.5f * p.size * glm::vec2(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f);
      const glm::vec4 clip = vp * glm::vec4(corner.x, p.height, corner.y, 1.0f);
      if (!(clip.w > 1e-4f)) {
        return full;
      }
      const glm::vec2 uv = project_to_uv(clip, ClipConvention::vulkan);
      lo = glm::min(lo, uv);
      hi = glm::max(hi, uv);
    }
    const glm::vec2 size(static_cast<float>(full.extent.width),
                         static_cast<float>(full.extent.height));
    const glm::vec2 margin = glm::vec2(2.83f * p.wave_height * p.distortion) + 2.0f / size;
    lo = glm::clamp(lo - margin, glm::vec2(0.0f), glm::vec2(1.0f)) * size;
    hi = glm::clamp(hi + margin, glm::vec2(0.0f), glm::vec2(1.0f)) * size;
    const auto x0 = static_cast<std::int32_t>(std::floor(lo.x));
    const auto y0 = static_cast<std::int32_t>(std::floor(lo.y));
    const auto x1 = static_cast<std::uint32_t>(std::ceil(hi.x));
    const auto y1 = static_cast<std::uint32_t>(std::ceil(hi.y));
    if (x1 <= static_cast<std::uint32_t>(x0) || y1 <= static_cast<std::uint32_t>(y0)) {
      return VkRect2D{{0, 0}, {1, 1}}; // the water is off screen: render (almost) nothing
    }
    return VkRect2D{{x0, y0},
                    {x1 - static_cast<std::uint32_t>(x0), y1 - static_cast<std::uint32_t>(y0)}};
  }

  /// Oblique near plane when possible (the eye strictly on the clipped side), else clip
  /// distance: a camera on or below the plane cannot use an oblique near plane.
  void clip(SceneView& v, const Plane& keep) const {
    v.clip_plane.reset();
    const bool eye_clipped = signed_distance(keep, v.eye) < -1e-4f;
    if (params_.clip_mode == WaterClipMode::oblique && eye_clipped) {
      const glm::vec4 view_plane = to_vec4(transform_plane(keep, v.view));
      v.proj = oblique_projection(v.proj, view_plane, DepthRange::zero_to_one);
    } else {
      v.clip_plane = keep;
    }
  }

  Result<void> create_pipeline() {
    const VkDevice d = ctx_->device();
    VkDescriptorSetLayoutBinding bindings[5];
    bindings[0] = {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1,
                   VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    for (std::uint32_t i = 1; i < 5; ++i) {
      bindings[i] = {i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
                     nullptr};
    }
    auto lci = vk_struct<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    lci.bindingCount = 5;
    lci.pBindings = bindings;
    WATER_VK(vkCreateDescriptorSetLayout(d, &lci, nullptr, &set_layout_), "descriptor layout");
    auto pli = vk_struct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &set_layout_;
    WATER_VK(vkCreatePipelineLayout(d, &pli, nullptr, &layout_), "pipeline layout");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}};
    auto dpci =
        vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    dpci.maxSets = 1;
    dpci.poolSizeCount = 2;
    dpci.pPoolSizes = sizes;
    WATER_VK(vkCreateDescriptorPool(d, &dpci, nullptr, &pool_), "descriptor pool");
    auto ai =
        vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    ai.descriptorPool = pool_;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &set_layout_;
    WATER_VK(vkAllocateDescriptorSets(d, &ai, &set_), "descriptor set");

    auto vert = create_shader_module(d, water::shaders::water_vert, "water.vert");
    auto frag = create_shader_module(d, water::shaders::water_frag, "water.frag");
    Result<VkPipeline> pipeline = fail(ErrorCode::vulkan_error, "water: shader modules");
    if (vert && frag) {
      GraphicsPipelineDesc desc;
      desc.vertex = *vert;
      desc.fragment = *frag;
      desc.layout = layout_;
      desc.color_format = color_format_;
      desc.depth_format = depth_format_;
      desc.vertex_input = false;
      // The surface does not write depth: the scene's depth behind it stays for effects after it.
      desc.depth_write = false;
      desc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
      pipeline = create_graphics_pipeline(d, desc, "water surface pipeline");
    }
    for (auto* m : {&vert, &frag}) {
      if (*m) {
        vkDestroyShaderModule(d, **m, nullptr);
      }
    }
    if (!vert || !frag) {
      return !vert ? vert.error() : frag.error();
    }
    if (!pipeline) {
      return pipeline.error();
    }
    pipeline_ = *pipeline;
    return {};
  }

  void write_descriptors() {
    const VkDescriptorBufferInfo ubo{ubo_.handle(), 0, sizeof(WaterBlock)};
    const VkDescriptorImageInfo images[4] = {
        {clamp_.handle(), reflection_.color_view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {clamp_.handle(), refraction_.color_view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {nearest_.handle(), refraction_.depth_view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {repeat_.handle(), normal_map_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
    };
    VkWriteDescriptorSet writes[2];
    writes[0] = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[0].dstSet = set_;
    writes[0].dstBinding = 0;
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    writes[0].pBufferInfo = &ubo;
    writes[1] = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    writes[1].dstSet = set_;
    writes[1].dstBinding = 1;
    writes[1].descriptorCount = 4;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[1].pImageInfo = images;
    vkUpdateDescriptorSets(ctx_->device(), 2, writes, 0, nullptr);
  }

  void destroy() {
    if (ctx_ == nullptr) {
      return;
    }
    const VkDevice d = ctx_->device();
    vkDeviceWaitIdle(d);
    vkDestroyPipeline(d, pipeline_, nullptr);
    vkDestroyPipelineLayout(d, layout_, nullptr);
    vkDestroyDescriptorPool(d, pool_, nullptr);
    vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
  }

  const Context* ctx_ = nullptr;
  VkFormat color_format_ = VK_FORMAT_UNDEFINED;
  VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
  WaterParams params_;
  std::string preset_ = "default";
  bool underwater_ = false; ///< The eye is below the plane (this frame).
  FrameInfo info_;
  SceneView reflection_view_, refraction_view_;
  RenderTarget reflection_, refraction_;
  Texture2D normal_map_;
  Sampler repeat_, clamp_, nearest_;
  Buffer ubo_;
  VkDeviceSize stride_ = 0;
  std::uint32_t slot_ = 0;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  std::vector<DebugTarget> debug_;
  std::optional<Error> error_;
};

} // namespace

Result<std::unique_ptr<WaterEffect>> create_water(const EffectCreateInfo& info) {
  if (info.context == nullptr) {
    return fail(ErrorCode::invalid_argument, "water: EffectCreateInfo::context is required");
  }
  auto water = std::make_unique<Water>();
  if (auto r = water->init(info); !r) {
    return r.error();
  }
  return std::unique_ptr<WaterEffect>(std::move(water));
}

Result<void> register_water(EffectRegistry& registry) {
  return registry.add(
      "water",
      [](const EffectCreateInfo& info) -> Result<std::unique_ptr<Effect>> {
        auto w = create_water(info);
        if (!w) {
          return w.error();
        }
        return std::unique_ptr<Effect>(std::move(*w));
      },
      water_schema());
}

} // namespace snell

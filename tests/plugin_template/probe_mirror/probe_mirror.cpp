// probe_mirror: the smallest useful plugin. A horizontal mirror quad at `height`: one
// reflection pass of the host's scene (mirrored camera, oblique clipping at the plane), then the
// quad sampling it. Everything but its own shading comes from the plugin toolkit.
#include <snell/math.hpp>
#include <snell/param_table.hpp>
#include <snell/plugin.hpp>

#include "snell_probe_mirror_shaders.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace snell {
namespace {

struct ProbeMirrorParams {
  float height = 0.0f;        ///< The mirror plane y = height, m.
  glm::vec2 size{4.0f, 4.0f}; ///< Extent (x, z) of the quad around the origin, m.
};

const ParamTable<ProbeMirrorParams>& table() {
  using P = ProbeMirrorParams;
  static const ParamTable<P> t =
      ParamTable<P>("probe_mirror", "A minimal planar mirror built from the plugin toolkit.")
          .number("height", &P::height, -100.0f, 100.0f, "m", "Height of the mirror plane")
          .vec2("size", &P::size, 0.01f, 100.0f, "m", "Extent (x, z) of the mirror quad");
  return t;
}

struct Block {
  glm::mat4 view_proj;
  glm::mat4 model;
  glm::vec4 extent;
};

class ProbeMirror final : public Effect {
public:
  Result<void> init(const EffectCreateInfo& info) {
    ctx_ = info.context;
    release_ = DeferredRelease(info.frames_in_flight);
    SNELL_ASSIGN_OR_RETURN(ring_,
                           UniformRing::create(*ctx_, {.block_size = sizeof(Block),
                                                       .frames_in_flight = info.frames_in_flight}));
    const DescriptorBinding uniforms{.binding = 0,
                                     .type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                                     .stages =
                                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT};
    SNELL_ASSIGN_OR_RETURN(
        sets_, DescriptorSets::create(*ctx_, {.bindings = {uniforms, {.binding = 1}},
                                              .frames_in_flight = info.frames_in_flight}));
    sets_.set_buffer(0, ring_.buffer(), 0, ring_.block_size());
    SNELL_ASSIGN_OR_RETURN(quad_, Surfaces::shape(*ctx_, Shape::quad));
    return make_pipeline(info);
  }

  Result<void> make_pipeline(const EffectCreateInfo& info) {
    GraphicsPipelineDesc pd{.label = "probe_mirror surface",
                            .vertex = probe_mirror::shaders::probe_mirror_vert,
                            .fragment = probe_mirror::shaders::probe_mirror_frag,
                            .set_layouts = {sets_.layout()}};
    pd.state.color_formats = {info.color_format};
    pd.state.depth_format = info.depth_format;
    SNELL_ASSIGN_OR_RETURN(pipeline_, Pipeline::create(*ctx_, pd));
    return {};
  }

  std::string_view type() const override { return "probe_mirror"; }
  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    return table().set(params_, key, value);
  }
  Result<ParamValue> get_param(std::string_view key) const override {
    return table().get(params_, key);
  }
  Span<const DebugTarget> debug_targets() const override { return debug_; }

  Result<void> update(const FrameInfo& info) override {
    release_.collect(info.frame_index);
    auto made = target_.fit(*ctx_, info.main_view.extent, info.frame_index, release_);
    if (!made) {
      return made.error();
    }
    debug_.clear();
    target_.append_debug_targets(debug_, "probe_mirror.reflection");
    const Plane plane{{0.0f, 1.0f, 0.0f}, -params_.height};
    view_ = mirrored_view(info.main_view, plane);
    view_.layer_mask = layer::reflected;
    clip_view(view_, plane, PlaneClip::oblique);
    aim_at(view_, target_.target());
    return {};
  }

  Result<void> record_passes(VkCommandBuffer cmd, const FrameInfo& info,
                             SceneSource& scene) override {
    return record_scene_pass(cmd, scene, target_.target(),
                             {.name = "probe_mirror.reflection", .view = view_}, info.timer);
  }

  Result<void> record_draw(VkCommandBuffer cmd, const FrameInfo& info) override {
    const VkExtent2D e = info.main_view.extent;
    Block b;
    b.view_proj = info.main_view.proj * info.main_view.view;
    b.model = glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, params_.height, 0.0f}),
                         {params_.size.x, 1.0f, params_.size.y});
    b.extent = {float(e.width), float(e.height), 1.0f / float(e.width), 1.0f / float(e.height)};
    auto offset = ring_.push(info.frame_index, b);
    if (!offset) {
      return offset.error();
    }
    sets_.set_image(1, target_.target().color_view(), ctx_->sampler(StandardSampler::linear_clamp));
    pipeline_.bind(cmd);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
    vkCmdSetFrontFace(cmd, VK_FRONT_FACE_COUNTER_CLOCKWISE);
    sets_.bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.layout(), info.frame_index, &*offset,
               1);
    quad_.draw(cmd, 0);
    return {};
  }

private:
  const Context* ctx_ = nullptr;
  ProbeMirrorParams params_;
  DeferredRelease release_;
  ScaledTarget target_{{.scale = 1.0f, .label = "probe_mirror reflection"}};
  SceneView view_;
  UniformRing ring_;
  DescriptorSets sets_;
  Pipeline pipeline_;
  Surfaces quad_;
  std::vector<DebugTarget> debug_;
};

} // namespace

Result<void> register_probe_mirror(EffectRegistry& registry) {
  return registry.add(
      "probe_mirror",
      [](const EffectCreateInfo& info) -> Result<std::unique_ptr<Effect>> {
        if (info.context == nullptr) {
          return fail(ErrorCode::invalid_argument, "probe_mirror: no context");
        }
        auto e = std::make_unique<ProbeMirror>();
        if (auto r = e->init(info); !r) {
          return r.error();
        }
        return std::unique_ptr<Effect>(std::move(e));
      },
      table().schema());
}

} // namespace snell

// The dynamic cube map effect: every frame the scene around the probe is captured into a cube
// (toolkit record_cube_capture: multiview or six passes, then mips), and the probe's owner is
// drawn from it inside the host's main rendering.
#include "cubemap_internal.hpp"

#include <snell/plugin.hpp>

#include "snell_dynamic_cubemap_shaders.hpp"

#include <snell/capture_budget.hpp>
#include <snell/math/bounds.hpp>
#include <snell/probe_directory.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vector_relational.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace snell {
namespace {

/// std140 mirror of ProbeBlock in shaders/probe_common.glsl.
struct ProbeBlock {
  glm::mat4 view_proj;
  glm::mat4 model;
  glm::vec4 eye, optics, tint, center, box_min, box_max;
};

class DynamicCubemap final : public DynamicCubemapEffect {
public:
  DynamicCubemap() = default;
  DynamicCubemap(const DynamicCubemap&) = delete;
  DynamicCubemap& operator=(const DynamicCubemap&) = delete;
  ~DynamicCubemap() override {
    if (directory_ != nullptr) {
      directory_->withdraw(this);
    }
  }

  Result<void> init(const EffectCreateInfo& info) {
    ctx_ = info.context;
    scene_ = info.scene;
    release_ = DeferredRelease(info.frames_in_flight);
    budget_ = info.capture_budget;
    directory_ = info.probes;
    if (scene_ != nullptr) {
      if (const Anchor* a = scene_->find_anchor("probe")) {
        params_.value().center = a->position;
        params_.value().radius = std::max(0.5f * a->size.x, 0.01f);
        if (a->object >= 0 && static_cast<std::size_t>(a->object) < scene_->objects.size()) {
          params_.value().node = scene_->objects[static_cast<std::size_t>(a->object)].name;
        }
      }
    }
    SNELL_ASSIGN_OR_RETURN(owner_, take_owner(params_.value().node));
    SNELL_TRY(create_surface_bindings(*ctx_,
                                      {.block_size = sizeof(ProbeBlock),
                                       .images = 1,
                                       .frames_in_flight = info.frames_in_flight,
                                       .label = "dynamic_cubemap surface"},
                                      ubo_, sets_));
    GraphicsPipelineDesc desc = surface_pipeline_desc(
        info, "dynamic_cubemap surface pipeline", dynamic_cubemap::shaders::probe_surface_vert,
        dynamic_cubemap::shaders::probe_surface_frag, {sets_.layout()});
    // The probe's owner is opaque: it writes depth, so surfaces drawn after it (another probe,
    // a glass pane) that lie behind it stay hidden.
    desc.state.depth_write = true;
    variants_ = PipelineVariants(std::move(desc));
    return {};
  }

  std::string_view type() const override { return "dynamic_cubemap"; }
  Result<void> set_param(std::string_view key, const ParamValue& value) override {
    return params_.set(key, value,
                       [this](const DynamicCubemapParams& next) { return apply_node(next); });
  }
  Result<ParamValue> get_param(std::string_view key) const override { return params_.get(key); }
  Result<void> set_params(const DynamicCubemapParams& params) override {
    return params_.set_all(params,
                           [this](const DynamicCubemapParams& next) { return apply_node(next); });
  }
  const DynamicCubemapParams& params() const override { return params_.value(); }
  Span<const DebugTarget> debug_targets() const override { return debug_; }
  Span<const int> drawn_objects() const override { return owner_.objects(); }

  void request_update() override { requested_ = true; }
  std::uint64_t publications() const override { return publications_; }
  std::uint32_t faces_captured() const override { return faces_captured_; }

  Result<void> update(const FrameInfo& info) override {
    frame_ = info.frame_index;
    release_.collect(frame_);
    const DynamicCubemapParams& p = params_.value();
    const auto size = static_cast<std::uint32_t>(p.face_size);
    SNELL_TRY(fit(front_, size));
    // Slices (a policy or a budget may leave a round unfinished) go into a back cube, published
    // whole; without slicing there is none.
    const bool slices = p.refresh == CubemapRefresh::faces_per_frame || budget_ != nullptr;
    if (slices) {
      SNELL_TRY(fit(back_, size));
    } else if (back_ && done_ == 0) {
      release_.retire(frame_, std::move(back_));
      back_ = CubeTarget();
    }
    SNELL_TRY(fit_prefilter(p));
    time_ = info.time;
    SNELL_TRY(pick_variant(p));
    ++frames_;
    wanted_ = wanted_faces(p);
    levels_wanted_ = directory_ != nullptr && directory_->take_levels_wanted(this);
    ticket_.reset();
    if (budget_ != nullptr && wanted_ != 0 && !whole_) {
      const float distance = glm::length(capture_center(info.time) - info.main_view.eye);
      // A requested update declares the cube outdated: as stale as a cube can be.
      const std::uint64_t age = requested_ ? ~std::uint64_t{0} : frames_ - published_frame_;
      ticket_ = budget_->request(frame_, CaptureBudget::Request{wanted_, age, distance});
    }
    return {};
  }

  Result<void> record_passes(VkCommandBuffer cmd, const FrameInfo& info,
                             SceneSource& scene) override {
    std::uint32_t faces = wanted_;
    if (ticket_) {
      faces = budget_->grant(frame_, *ticket_);
    }
    if (faces == 0) {
      return {};
    }
    const DynamicCubemapParams& p = params_.value();
    // The whole cube at once goes straight into the front cube; slices into the back one.
    const bool direct = whole_ || (faces == 0x3Fu && done_ == 0) || !back_;
    const bool publish = direct || (done_ | faces) == 0x3Fu;
    CubeCapture capture;
    capture.name = "dynamic_cubemap.capture";
    capture.center = capture_center(info.time);
    capture.z_near = p.z_near;
    capture.z_far = p.z_far;
    capture.layer_mask = static_cast<std::uint32_t>(p.capture_layers);
    // Lavapipe (Mesa 22.3, the CPU device) draws views 1..5 of the multiview capture wrongly:
    // no sky and a floor filling the -x face, where the same build on an NVIDIA H100 and the
    // six-pass path on lavapipe are right (docs/cubemap.md). On a CPU device it captures the
    // faces one by one; six passes cost the CPU rasteriser no more than six views.
    const bool multiview = p.capture == CubemapCaptureMode::multiview &&
                           ctx_->device_info().type != VK_PHYSICAL_DEVICE_TYPE_CPU;
    capture.mode = multiview ? CubeCaptureMode::multiview : CubeCaptureMode::six_pass;
    capture.time = info.time;
    capture.faces = direct ? 0x3Fu : faces;
    // The mip chain (a blit chain per capture: a fifth of the capture on lavapipe) only when
    // something samples above level 0: this probe's own roughness, the GGX prefilter, a
    // consumer that asked (ProbeDirectory::want_levels), and always the first capture.
    const bool levels = p.prefilter != CubemapPrefilter::none &&
                        (p.roughness > 0.0f || p.prefilter == CubemapPrefilter::ggx ||
                         levels_wanted_ || publications_ == 0);
    capture.mips = publish && levels;
    SNELL_TRY(record_cube_capture(cmd, scene, direct ? front_ : back_, capture, info.timer));
    faces_captured_ = capture.faces;
    if (direct) {
      done_ = 0; // a round in the back cube is superseded by the fresher front
    } else {
      done_ |= faces;
      if (publish) {
        // The back cube is complete (six faces, mips): it becomes the one the surface samples;
        // the old front, sampled by frames still in flight, is overwritten only by later
        // frames' captures, which their barriers order after those reads.
        std::swap(front_, back_);
        point_at_front();
        done_ = 0;
      }
    }
    if (publish && p.prefilter == CubemapPrefilter::ggx) {
      // The published capture, filtered into the cube the surface samples.
      const CubePrefilterBinding& job =
          ggx_bindings_[0].source() == front_.color_image() ? ggx_bindings_[0] : ggx_bindings_[1];
      SNELL_TRY(prefilter_.record(cmd, job, info.timer));
    }
    if (publish) {
      front_levels_ = levels;
      ++publications_;
      published_frame_ = frames_;
      requested_ = false;
      whole_ = false;
      published_center_ = capture.center;
    }
    list_in_directory();
    return {};
  }

  Result<void> record_draw(VkCommandBuffer cmd, const FrameInfo& info) override {
    const DynamicCubemapParams& p = params_.value();
    ProbeBlock b{};
    b.view_proj = info.main_view.proj * info.main_view.view;
    const Surface& owner = owner_[0];
    if (owner.object >= 0 && scene_ != nullptr) {
      b.model = scene_->objects[static_cast<std::size_t>(owner.object)].world_at(time_);
    } else {
      // The unit sphere shape has radius 0.5.
      b.model = glm::scale(glm::translate(glm::mat4(1.0f), p.center), glm::vec3(2.0f * p.radius));
    }
    b.eye = glm::vec4(info.main_view.eye, 1.0f);
    const float levels = static_cast<float>(published_levels());
    b.optics = glm::vec4(p.dispersion, p.ior, p.roughness, levels);
    b.tint = glm::vec4(p.tint, 1.0f);
    b.center = glm::vec4(capture_center(time_), 1.0f);
    b.box_min = glm::vec4(p.box_min, 0.0f);
    b.box_max = glm::vec4(p.box_max, 0.0f);
    std::uint32_t offset = 0;
    SNELL_ASSIGN_OR_RETURN(offset, ubo_.push(frame_, b));
    pipeline_->bind(cmd);
    sets_.bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->layout(), frame_, &offset, 1);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_BACK_BIT);
    const bool mirrored = glm::determinant(glm::mat3(b.model)) < 0.0f;
    vkCmdSetFrontFace(cmd, mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
    for (std::size_t i = 0; i < owner_.size(); ++i) {
      owner_.draw(cmd, i);
    }
    return {};
  }

private:
  /// Publishes the front cube in the host's ProbeDirectory (when given) for other effects and
  /// host materials: its view, the centre it was captured at, the box.
  void list_in_directory() {
    if (directory_ == nullptr || publications_ == 0) {
      return;
    }
    const DynamicCubemapParams& p = params_.value();
    directory_->publish(this, ProbeView{.cube = sampled().cube_view(),
                                        .sampler = ctx_->sampler(StandardSampler::linear_clamp),
                                        .mip_levels = published_levels(),
                                        .center = published_center_,
                                        .box_projection = p.box_projection,
                                        .box_min = p.box_min,
                                        .box_max = p.box_max,
                                        .publications = publications_});
  }

  /// The levels of the published cube that hold the capture: all, or 1 when its chain was not
  /// built (nothing sampled above level 0, or prefilter = none).
  std::uint32_t published_levels() const {
    return front_levels_ && params_.value().prefilter != CubemapPrefilter::none
               ? sampled().mip_levels()
               : 1u;
  }

  /// The cube the surface and the directory sample: the GGX-filtered one, else the capture.
  const CubeTarget& sampled() const {
    return filtered_ && params_.value().prefilter == CubemapPrefilter::ggx ? filtered_ : front_;
  }

  /// With prefilter = ggx: the compute pass (once), the filtered cube of the capture's size
  /// and the bindings of both capture cubes to it (again when a cube is replaced). Turning ggx
  /// off keeps them (cheap to keep, expensive to rebuild), but the surface samples the capture.
  Result<void> fit_prefilter(const DynamicCubemapParams& p) {
    const bool was = sampled_ggx_;
    sampled_ggx_ = p.prefilter == CubemapPrefilter::ggx;
    if (!sampled_ggx_) {
      if (was) {
        point_at_front();
      }
      return {};
    }
    if (!prefilter_) {
      SNELL_ASSIGN_OR_RETURN(prefilter_,
                             CubePrefilter::create(*ctx_, {.name = "dynamic_cubemap.prefilter"}));
    }
    // Bound: the front cube in [0], the back cube (if any) in [1]; they swap on publication, so
    // the binding to record is the one whose source is the front cube then.
    const auto bound = [this](const CubeTarget& cube) {
      return ggx_bindings_[0].source() == cube.color_image() ||
             ggx_bindings_[1].source() == cube.color_image();
    };
    const bool stale = !filtered_ || filtered_.size() != front_.size() || !bound(front_) ||
                       (back_ && !bound(back_)) || (!back_ && ggx_bindings_[1]);
    if (!stale) {
      if (!was) {
        point_at_front();
        whole_ = true; // the filtered cube holds an old capture (or nothing): refresh it
      }
      return {};
    }
    if (!filtered_ || filtered_.size() != front_.size()) {
      CubeTarget made;
      SNELL_ASSIGN_OR_RETURN(
          made, CubeTarget::create(*ctx_, CubeTargetDesc{.size = front_.size(),
                                                         .color = ColorFormat::rgba16_float,
                                                         .mips = true,
                                                         .debug_name = "dynamic_cubemap ggx",
                                                         .storage = true}));
      if (filtered_) {
        release_.retire(frame_, std::move(filtered_));
      }
      filtered_ = std::move(made);
    }
    for (CubePrefilterBinding& b : ggx_bindings_) {
      if (b) {
        release_.retire(frame_, std::move(b));
        b = CubePrefilterBinding();
      }
    }
    SNELL_ASSIGN_OR_RETURN(ggx_bindings_[0], prefilter_.bind(front_, filtered_));
    if (back_) {
      SNELL_ASSIGN_OR_RETURN(ggx_bindings_[1], prefilter_.bind(back_, filtered_));
    }
    whole_ = true; // a new filtered cube: fill it from a full capture this frame
    point_at_front();
    return {};
  }

  /// Points pipeline_ at the surface's shader variant (specialization constants: the surface
  /// mode, box projection, dispersion), built the first time it is used.
  Result<void> pick_variant(const DynamicCubemapParams& p) {
    const bool reflects = p.surface != CubemapSurface::refract;
    const bool refracts = p.surface != CubemapSurface::reflect;
    SNELL_ASSIGN_OR_RETURN(pipeline_,
                           variants_.get(*ctx_, {static_cast<std::uint32_t>(p.surface),
                                                 reflects && p.box_projection ? 1u : 0u,
                                                 refracts && p.dispersion > 0.0f ? 1u : 0u}));
    return {};
  }

  /// The faces the refresh policy wants this frame (a budget may grant fewer): all six the
  /// first time, after a request or a resize (`whole_`), else those of the round in progress
  /// when a refresh is due.
  std::uint32_t wanted_faces(const DynamicCubemapParams& p) {
    // Without a budget a request is served at once; with one it competes as the stalest.
    whole_ = whole_ || publications_ == 0 || (requested_ && budget_ == nullptr);
    faces_captured_ = 0;
    if (whole_) {
      return 0x3Fu;
    }
    const std::uint32_t remaining = 0x3Fu & ~done_;
    bool due = done_ != 0 || requested_;
    switch (p.refresh) {
    case CubemapRefresh::every_frame:
    case CubemapRefresh::faces_per_frame:
      due = true;
      break;
    case CubemapRefresh::every_n:
      due = due || frames_ - published_frame_ >= static_cast<std::uint64_t>(p.refresh_n);
      break;
    case CubemapRefresh::on_demand:
      break;
    }
    if (!due) {
      return 0;
    }
    if (p.refresh != CubemapRefresh::faces_per_frame) {
      return remaining;
    }
    std::uint32_t mask = 0; // the lowest `faces_per_frame` faces still to draw
    int left = p.faces_per_frame;
    for (std::uint32_t f = 0; f < 6 && left > 0; ++f) {
      if ((remaining & (1u << f)) != 0) {
        mask |= 1u << f;
        --left;
      }
    }
    return mask;
  }

  /// Makes `cube` a cube of `size` (retiring the old one); the front one is then recaptured
  /// whole and the descriptors point at it.
  Result<void> fit(CubeTarget& cube, std::uint32_t size) {
    if (cube && cube.size() == size) {
      return {};
    }
    CubeTarget made;
    SNELL_ASSIGN_OR_RETURN(
        made, CubeTarget::create(*ctx_, CubeTargetDesc{.size = size,
                                                       .color = ColorFormat::rgba16_float,
                                                       .mips = true,
                                                       .debug_name = "dynamic_cubemap cube"}));
    if (cube) {
      release_.retire(frame_, std::move(cube));
    }
    cube = std::move(made);
    if (&cube == &front_) {
      whole_ = true;
      done_ = 0;
      point_at_front();
    } else {
      done_ = 0;
    }
    return {};
  }

  /// The surface's descriptor and the debug targets follow the front cube.
  void point_at_front() {
    sets_.set_image(1, sampled().cube_view(), ctx_->sampler(StandardSampler::linear_clamp));
    debug_.clear();
    static const char* const names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (std::uint32_t face = 0; face < 6; ++face) {
      debug_.push_back(DebugTarget{.name = std::string("dynamic_cubemap.face") + names[face],
                                   .kind = DebugKind::cube_face,
                                   .view = front_.face_view(face),
                                   .image = front_.color_image(),
                                   .width = front_.size(),
                                   .height = front_.size(),
                                   .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                   .layer = face});
    }
  }

  /// The owner's meshes: the object called `node`, or for "" the effect's own sphere. Errors
  /// name dynamic_cubemap.node and the value.
  Result<Surfaces> take_owner(const std::string& node) const {
    int object = -1;
    if (!node.empty()) {
      if (scene_ != nullptr) {
        for (std::size_t i = 0; i < scene_->objects.size(); ++i) {
          if (scene_->objects[i].name == node) {
            object = static_cast<int>(i);
            break;
          }
        }
      }
      if (object < 0) {
        return fail(ErrorCode::invalid_argument,
                    "dynamic_cubemap.node: no object named '" + node + "' in " +
                        (scene_ != nullptr ? "the scene '" + scene_->name + "'"
                                           : std::string("a host scene (none was given)")));
      }
    }
    Surfaces owner;
    if (object >= 0 && scene_ != nullptr) {
      const Object* chosen = &scene_->objects[static_cast<std::size_t>(object)];
      SNELL_ASSIGN_OR_RETURN(
          owner, Surfaces::from_scene(*ctx_, *scene_,
                                      [chosen](const Object& o, const Mesh&, const Material&) {
                                        return &o == chosen;
                                      }));
      if (owner.empty() && !node.empty()) {
        return fail(ErrorCode::invalid_argument,
                    "dynamic_cubemap.node: the object '" + node + "' has no mesh");
      }
    }
    if (owner.empty()) { // no anchor object: the effect's own sphere
      SNELL_ASSIGN_OR_RETURN(owner, Surfaces::shape(*ctx_, Shape::sphere));
    }
    return owner;
  }

  /// Checks the box (box_min < box_max when box_projection is on) and replaces the owner when
  /// `next.node` differs (the old meshes retired past the frames in
  /// flight); nothing changes on error.
  Result<void> apply_node(const DynamicCubemapParams& next) {
    if (next.box_projection && !glm::all(glm::lessThan(next.box_min, next.box_max))) {
      return fail(ErrorCode::invalid_argument,
                  "dynamic_cubemap.box_max: (" + std::to_string(next.box_max.x) + ", " +
                      std::to_string(next.box_max.y) + ", " + std::to_string(next.box_max.z) +
                      ") must exceed box_min (" + std::to_string(next.box_min.x) + ", " +
                      std::to_string(next.box_min.y) + ", " + std::to_string(next.box_min.z) +
                      ") on every axis when box_projection is on");
    }
    if (next.node == params_.value().node) {
      return {};
    }
    Surfaces owner;
    SNELL_ASSIGN_OR_RETURN(owner, take_owner(next.node));
    release_.retire(frame_, std::move(owner_));
    owner_ = std::move(owner);
    return {};
  }

  /// Where the capture is taken: the centre of a named owner's world bounds, else `center`.
  glm::vec3 capture_center(float time) const {
    const DynamicCubemapParams& p = params_.value();
    const Surface& owner = owner_[0];
    if (p.node.empty() || owner.object < 0 || scene_ == nullptr) {
      return p.center;
    }
    const glm::mat4 world = scene_->objects[static_cast<std::size_t>(owner.object)].world_at(time);
    const Aabb box = transform_aabb(Aabb{owner.bounds_min, owner.bounds_max}, world);
    return 0.5f * (box.min + box.max);
  }

  const Context* ctx_ = nullptr;
  const Scene* scene_ = nullptr;
  DeferredRelease release_;
  ParamStore<DynamicCubemapParams> params_{detail::cubemap_table(), DynamicCubemapParams{}};
  std::uint64_t frame_ = 0;
  float time_ = 0.0f;
  CubeTarget front_;        ///< The published cube the surface samples.
  CubeTarget back_;         ///< Slices in progress (faces_per_frame or a budget).
  CubeTarget filtered_;     ///< prefilter = ggx: the filtered front cube.
  CubePrefilter prefilter_; ///< The GGX pass (made on first use).
  std::array<CubePrefilterBinding, 2> ggx_bindings_{}; ///< front and back cube -> filtered_.
  bool sampled_ggx_ = false;                           ///< The surface samples filtered_.
  bool levels_wanted_ = false;            ///< A consumer samples the published cube blurred.
  bool front_levels_ = false;             ///< The published cube's mip chain was built.
  CaptureBudget* budget_ = nullptr;       ///< The host's shared face budget, if any.
  ProbeDirectory* directory_ = nullptr;   ///< The host's list of probes, if any.
  glm::vec3 published_center_{0.0f};      ///< Where the front cube was captured.
  std::optional<std::uint32_t> ticket_{}; ///< This frame's budget request.
  std::uint32_t wanted_ = 0;              ///< Faces the policy wants this frame.
  std::uint32_t done_ = 0;                ///< Faces of the back cube's round drawn so far.
  std::uint32_t faces_captured_ = 0;      ///< Faces drawn this frame.
  std::uint64_t frames_ = 0;              ///< Frames updated so far.
  std::uint64_t published_frame_ = 0;     ///< frames_ at the last publication.
  std::uint64_t publications_ = 0;        ///< Complete cubes published.
  bool requested_ = false;                ///< request_update() since the last publication.
  bool whole_ = false; ///< Capture all six faces into the front now (first, resized, ...).
  Surfaces owner_;
  UniformRing ubo_;
  DescriptorSets sets_;
  PipelineVariants variants_;          ///< Surface variants by their constants.
  const Pipeline* pipeline_ = nullptr; ///< This frame's variant.
  std::vector<DebugTarget> debug_;
};

} // namespace

Result<std::unique_ptr<DynamicCubemapEffect>> create_dynamic_cubemap(const EffectCreateInfo& info) {
  SNELL_TRY(check_create_info(info, "dynamic_cubemap"));
  auto effect = std::make_unique<DynamicCubemap>();
  SNELL_TRY(effect->init(info));
  return std::unique_ptr<DynamicCubemapEffect>(std::move(effect));
}

Result<void> register_dynamic_cubemap(EffectRegistry& registry) {
  return registry.add("dynamic_cubemap", effect_factory(create_dynamic_cubemap),
                      dynamic_cubemap_schema());
}

} // namespace snell

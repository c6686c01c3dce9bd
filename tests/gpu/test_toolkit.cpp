// The plugin toolkit: deferred release, uniform ring alignment, descriptor sets per frame,
// targets samplable from creation, one scene snapshot per frame, effects skipped before submit,
// the debug overlay's every thumbnail, and VkResult kept in Error.
#include "water_fixture.hpp"

#include <snell/plugin.hpp>

#include <cstring>
#include <memory>

using namespace snell;

namespace {

void require_ok(const Result<void>& r) {
  REQUIRE_MESSAGE(r.has_value(), r.error().message);
}

/// Counts its live instances (moved-from instances do not count).
struct Tracked {
  std::shared_ptr<int> live;
  explicit Tracked(std::shared_ptr<int> counter) : live(std::move(counter)) { ++*live; }
  Tracked(Tracked&& o) noexcept : live(std::move(o.live)) {}
  Tracked& operator=(Tracked&&) = delete;
  Tracked(const Tracked&) = delete;
  ~Tracked() {
    if (live) {
      --*live;
    }
  }
};

/// An effect whose update fails on demand (for the error model).
class FailingEffect final : public Effect {
public:
  bool fail_update = true;
  int draws = 0;
  std::string_view type() const override { return "failing"; }
  Result<void> set_param(std::string_view, const ParamValue&) override { return {}; }
  Result<ParamValue> get_param(std::string_view) const override { return ParamValue{0.0f}; }
  Result<void> update(const FrameInfo&) override {
    if (fail_update) {
      return vk_error("vkCreateImage", VK_ERROR_OUT_OF_DEVICE_MEMORY, "failing target");
    }
    return {};
  }
  Result<void> record_passes(VkCommandBuffer, const FrameInfo&, SceneSource&) override {
    return {};
  }
  Result<void> record_draw(VkCommandBuffer, const FrameInfo&) override {
    ++draws;
    return {};
  }
  Span<const DebugTarget> debug_targets() const override { return {}; }
};

} // namespace

TEST_CASE("toolkit: DeferredRelease destroys a resource frames_in_flight frames after it retired") {
  auto live = std::make_shared<int>(0);
  DeferredRelease release(2);
  release.retire(5, Tracked(live));
  CHECK(*live == 1);
  release.collect(5);
  release.collect(6); // frame 5 may still execute while frame 6 records
  CHECK(*live == 1);
  CHECK(release.pending() == 1);
  release.collect(7); // the host waited for frame 5 before recording frame 7
  CHECK(*live == 0);
  CHECK(release.pending() == 0);
  release.retire(9, Tracked(live));
  release.release_all();
  CHECK(*live == 0);
}

TEST_CASE("toolkit: Error keeps the VkResult of a failed Vulkan call") {
  const Result<void> r = check_vk(VK_ERROR_DEVICE_LOST, "test call");
  REQUIRE_FALSE(r.has_value());
  CHECK(r.error().code == ErrorCode::vulkan_error);
  CHECK(r.error().vk_result == VK_ERROR_DEVICE_LOST);
  CHECK(r.error().message.find("VK_ERROR_DEVICE_LOST") != std::string::npos);
  CHECK(r.error().message.find("test call") != std::string::npos);
  const Error oom = vk_error("vkAllocateMemory", VK_ERROR_OUT_OF_DEVICE_MEMORY, "a target");
  CHECK(oom.code == ErrorCode::out_of_memory);
  CHECK(oom.vk_result == VK_ERROR_OUT_OF_DEVICE_MEMORY);
  CHECK(check_vk(VK_SUCCESS, "fine").has_value());
  CHECK(fail(ErrorCode::invalid_argument, "x").vk_result == 0);
}

TEST_CASE("toolkit: UniformRing blocks are aligned to the device and distinct per frame") {
  test::GpuFixture gpu;
  const VkDeviceSize align = gpu.ctx().limits().minUniformBufferOffsetAlignment;
  auto ring = UniformRing::create(gpu.ctx(), UniformRingDesc{.block_size = 100,
                                                             .blocks_per_frame = 2,
                                                             .frames_in_flight = 3,
                                                             .label = "test ring"});
  REQUIRE_MESSAGE(ring.has_value(), ring.error().message);
  CHECK(ring->stride() % align == 0);
  CHECK(ring->stride() >= 100);
  CHECK(ring->block_size() == 100);
  std::vector<std::uint32_t> offsets;
  for (std::uint64_t frame = 10; frame < 13; ++frame) {
    for (int i = 0; i < 2; ++i) {
      const float value = static_cast<float>(frame);
      auto offset = ring->push(frame, &value, sizeof(value));
      REQUIRE_MESSAGE(offset.has_value(), offset.error().message);
      CHECK(*offset % align == 0);
      offsets.push_back(*offset);
    }
  }
  std::sort(offsets.begin(), offsets.end());
  CHECK(std::adjacent_find(offsets.begin(), offsets.end()) == offsets.end()); // 6 distinct
  const float value = 0.0f;
  auto third = ring->push(12, &value, sizeof(value));
  REQUIRE_FALSE(third.has_value());
  CHECK(third.error().code == ErrorCode::limit_exceeded);
  std::vector<char> big(200);
  auto too_big = ring->push(13, big.data(), big.size());
  REQUIRE_FALSE(too_big.has_value());
  CHECK(too_big.error().code == ErrorCode::invalid_argument);
  CHECK_FALSE(UniformRing::create(gpu.ctx(), UniformRingDesc{}).has_value()); // block_size 0
  CHECK_FALSE(
      UniformRing::create(gpu.ctx(), UniformRingDesc{.block_size = 16, .frames_in_flight = 0})
          .has_value());
}

TEST_CASE("toolkit: DescriptorSets give each frame in flight its own set, updated lazily") {
  test::GpuFixture gpu;
  CHECK_FALSE(DescriptorSets::create(gpu.ctx(), DescriptorSetDesc{}).has_value());
  auto sets = DescriptorSets::create(
      gpu.ctx(), DescriptorSetDesc{.bindings = {{.binding = 0}}, .frames_in_flight = 2});
  REQUIRE_MESSAGE(sets.has_value(), sets.error().message);
  auto a = RenderTarget::create(gpu.ctx(), RenderTargetDesc{.width = 4, .height = 4});
  REQUIRE(a.has_value());
  sets->set_image(0, a->color_view(), gpu.ctx().sampler(StandardSampler::linear_clamp));
  const VkDescriptorSet s0 = sets->acquire(0);
  const VkDescriptorSet s1 = sets->acquire(1);
  CHECK(s0 != VK_NULL_HANDLE);
  CHECK(s0 != s1);
  CHECK(sets->acquire(2) == s0); // slot 0 again: frame 0 completed before frame 2 records
}

TEST_CASE("toolkit: a new render target is samplable before any pass wrote it") {
  test::GpuFixture gpu;
  auto target = RenderTarget::create(
      gpu.ctx(), RenderTargetDesc{.width = 8, .height = 8, .color = ColorFormat::rgba16_float});
  REQUIRE(target.has_value());
  CHECK(target->depth_format() == VK_FORMAT_D32_SFLOAT);
  DebugTarget t;
  t.view = target->color_view();
  t.image = target->color_image();
  t.width = t.height = 8;
  t.format = target->vk_color_format();
  auto image = read_debug_target(gpu.ctx(), t); // SHADER_READ_ONLY -> transfer: no validation
  REQUIRE_MESSAGE(image.has_value(), image.error().message);
  for (const float v : image->rgba) {
    CHECK(v == 0.0f); // cleared to transparent black
  }
  auto no_depth =
      RenderTarget::create(gpu.ctx(), RenderTargetDesc{.width = 4, .height = 4, .depth = false});
  REQUIRE(no_depth.has_value());
  CHECK(no_depth->depth_format() == VK_FORMAT_UNDEFINED);
}

TEST_CASE("toolkit: one scene snapshot per frame whatever the number of effects") {
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  rig.init(gpu.ctx());
  EffectCreateInfo info;
  info.context = &gpu.ctx();
  info.color_format = rig.frame->target().vk_color_format();
  info.scene = &rig.scene;
  auto second = create_water(info);
  REQUIRE(second.has_value());
  require_ok((*second)->set_param("height", -0.5f));
  Effect* both[] = {rig.water.get(), second->get()};
  for (int frame = 0; frame < 2; ++frame) {
    auto stats = rig.frame->render(*rig.renderer, rig.camera, 0.0f, both, rig.scene.light);
    REQUIRE_MESSAGE(stats.has_value(), stats.error().message);
    CHECK(stats->effect_errors.empty());
    CHECK(stats->snapshot_copies == 1);
    const auto copies = std::count_if(stats->passes.begin(), stats->passes.end(),
                                      [](const PassTime& p) { return p.name == "snapshot"; });
    CHECK(copies == 1);
    const auto refractions =
        std::count_if(stats->passes.begin(), stats->passes.end(),
                      [](const PassTime& p) { return p.name == "water.refraction"; });
    CHECK(refractions == 0); // refraction comes from the snapshot
  }
  // Neither wants it: no copy, each renders its own refraction pass.
  require_ok(rig.water->set_param("refraction_source", std::string("pass")));
  require_ok((*second)->set_param("refraction_source", std::string("pass")));
  auto stats = rig.frame->render(*rig.renderer, rig.camera, 0.0f, both, rig.scene.light);
  REQUIRE(stats.has_value());
  CHECK(stats->snapshot_copies == 0);
  CHECK(std::count_if(stats->passes.begin(), stats->passes.end(),
                      [](const PassTime& p) { return p.name == "water.refraction"; }) == 2);
}

TEST_CASE("toolkit: a failing effect is skipped before submit and reported, the frame renders") {
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  rig.init(gpu.ctx());
  FailingEffect failing;
  Effect* effects[] = {&failing, rig.water.get()};
  auto stats = rig.frame->render(*rig.renderer, rig.camera, 0.0f, effects, rig.scene.light);
  REQUIRE_MESSAGE(stats.has_value(), stats.error().message);
  REQUIRE(stats->effect_errors.size() == 1);
  CHECK(stats->effect_errors[0].message.rfind("failing: ", 0) == 0);
  CHECK(stats->effect_errors[0].vk_result == VK_ERROR_OUT_OF_DEVICE_MEMORY);
  CHECK(failing.draws == 0); // skipped: nothing of it was recorded
  failing.fail_update = false;
  stats = rig.frame->render(*rig.renderer, rig.camera, 0.0f, effects, rig.scene.light);
  REQUIRE(stats.has_value());
  CHECK(stats->effect_errors.empty());
  CHECK(failing.draws == 1);
}

TEST_CASE("toolkit: resizing water's targets between frames needs no device idle") {
  // Targets are replaced through DeferredRelease: validation (synchronization included) stays
  // clean while the scale changes every frame, and the image still shows the water.
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  rig.init(gpu.ctx());
  for (const float scale : {0.5f, 0.25f, 1.0f, 0.5f}) {
    require_ok(rig.water->set_param("resolution_scale", scale));
    (void)rig.render(0.0f);
    const auto targets = rig.water->debug_targets();
    REQUIRE(!targets.empty());
    CHECK(targets[0].width == static_cast<std::uint32_t>(float(rig.width) * scale + 0.5f));
  }
}

TEST_CASE("toolkit: the debug overlay shows every target, more than four included") {
  test::GpuFixture gpu;
  test::WaterRig rig;
  rig.scene = test::water_test_scene();
  rig.scene.sky = Sky{}; // a bright gradient: every thumbnail shows something
  rig.init(gpu.ctx());
  require_ok(rig.water->set_param("refraction_source", std::string("pass")));
  const Image plain = rig.render(0.0f);
  auto frame = FrameRenderer::create(gpu.ctx(), FrameDesc{.width = rig.width,
                                                          .height = rig.height,
                                                          .color = ColorFormat::rgba8_unorm,
                                                          .debug_targets = true});
  REQUIRE(frame.has_value());
  Effect* effects[] = {rig.water.get()};
  auto stats = frame->render(*rig.renderer, rig.camera, 0.0f, effects, rig.scene.light);
  REQUIRE(stats.has_value());
  auto image = frame->read_color();
  REQUIRE(image.has_value());
  // water: reflection, refraction, refraction depth; the frame's depth: 4 thumbnails (corners).
  // With a second water on the snapshot: + its reflection and the snapshot's colour, mip 2 and
  // depth = 8, laid out in a 3 x 3 grid; every cell must differ from the frame without overlay.
  EffectCreateInfo info;
  info.context = &gpu.ctx();
  info.color_format = frame->target().vk_color_format();
  info.scene = &rig.scene;
  auto second = create_water(info);
  REQUIRE(second.has_value());
  Effect* two[] = {rig.water.get(), second->get()};
  stats = frame->render(*rig.renderer, rig.camera, 0.0f, two, rig.scene.light);
  REQUIRE(stats.has_value());
  CHECK(stats->snapshot_copies == 1);
  image = frame->read_color();
  REQUIRE(image.has_value());
  const std::size_t n = 8;
  int differing = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Grid cell i (3 columns): the share of its pixels that differ from the frame without
    // overlay (a thumbnail is a scaled picture of something else, so most of them do).
    const std::uint32_t x0 = static_cast<std::uint32_t>(float(i % 3) / 3.0f * rig.width) + 4;
    const std::uint32_t y0 = static_cast<std::uint32_t>(float(i / 3) / 3.0f * rig.height) + 4;
    const std::uint32_t x1 = x0 + rig.width / 3 - 8, y1 = y0 + rig.height / 3 - 8;
    int changed = 0, total = 0;
    for (std::uint32_t y = y0; y < y1; ++y) {
      for (std::uint32_t x = x0; x < x1; ++x) {
        const std::size_t p = (std::size_t(y) * rig.width + x) * 4;
        int diff = 0;
        for (int c = 0; c < 3; ++c) {
          diff = std::max(diff, std::abs(int(image->rgba8[p + c]) - int(plain.rgba8[p + c])));
        }
        changed += diff > 8 ? 1 : 0;
        ++total;
      }
    }
    CAPTURE(i);
    CAPTURE(changed);
    differing += changed * 10 > total ? 1 : 0;
  }
  test::save_png(*image, "overlay_grid");
  CHECK(differing == static_cast<int>(n));
}

namespace {

/// An effect that claims scene objects (drawn_objects) and draws nothing itself.
class ClaimingEffect final : public Effect {
public:
  std::vector<int> claimed;
  std::string_view type() const override { return "claiming"; }
  Result<void> set_param(std::string_view, const ParamValue&) override { return {}; }
  Result<ParamValue> get_param(std::string_view) const override { return ParamValue{0.0f}; }
  Result<void> update(const FrameInfo&) override { return {}; }
  Result<void> record_passes(VkCommandBuffer, const FrameInfo&, SceneSource&) override {
    return {};
  }
  Result<void> record_draw(VkCommandBuffer, const FrameInfo&) override { return {}; }
  Span<const DebugTarget> debug_targets() const override { return {}; }
  Span<const int> drawn_objects() const override { return claimed; }
};

} // namespace

TEST_CASE("toolkit: Surfaces from scene nodes, host arrays and shapes") {
  test::GpuFixture gpu;
  Scene scene = test::empty_dark_scene();
  const int red = test::add_emissive_material(scene, {1, 0, 0});
  const int glass = test::add_emissive_material(scene, {0, 0, 1});
  scene.materials[static_cast<std::size_t>(glass)].transmission = 1.0f;
  test::add_object(scene, test::make_box_mesh(glm::vec3(0.5f), red), {0, 0, 0});
  const int pane = test::add_object(scene, test::make_quad_mesh({1, 1}, glass), {2, 0, 0});
  auto transmissive =
      Surfaces::from_scene(gpu.ctx(), scene, [](const Object&, const Mesh&, const Material& m) {
        return m.transmission > 0.0f;
      });
  REQUIRE_MESSAGE(transmissive.has_value(), transmissive.error().message);
  REQUIRE(transmissive->size() == 1);
  CHECK((*transmissive)[0].object == pane);
  CHECK((*transmissive)[0].world[3].x == doctest::Approx(2.0f));
  CHECK((*transmissive)[0].material.transmission == 1.0f);
  REQUIRE(transmissive->objects().size() == 1);
  CHECK(transmissive->objects()[0] == pane);
  auto all = Surfaces::from_scene(gpu.ctx(), scene);
  REQUIRE(all.has_value());
  CHECK(all->size() == 2);

  const Vertex tri[3] = {};
  const std::uint32_t good[3] = {0, 1, 2};
  const std::uint32_t bad[3] = {0, 1, 3};
  CHECK(Surfaces::from_arrays(gpu.ctx(), tri, good).has_value());
  auto refused = Surfaces::from_arrays(gpu.ctx(), tri, bad);
  REQUIRE_FALSE(refused.has_value());
  CHECK(refused.error().message.find("index 3") != std::string::npos);
  CHECK_FALSE(Surfaces::from_arrays(gpu.ctx(), Span<const Vertex>(), good).has_value());
  for (const Shape s : {Shape::quad, Shape::box, Shape::sphere}) {
    auto shape = Surfaces::shape(gpu.ctx(), s);
    REQUIRE(shape.has_value());
    CHECK((*shape)[0].bounds_max.x == doctest::Approx(0.5f));
    CHECK((*shape)[0].bounds_min.x == doctest::Approx(-0.5f));
  }
}

TEST_CASE("toolkit: the scene renderer leaves out the objects an effect draws itself") {
  test::GpuFixture gpu;
  Scene scene = test::empty_dark_scene();
  const int marker = test::add_object(
      scene, test::make_box_mesh(glm::vec3(0.5f), test::add_emissive_material(scene, {1, 0, 0})),
      {0, 0, 0});
  auto renderer = SceneRenderer::create(gpu.ctx(), scene);
  REQUIRE(renderer.has_value());
  auto frame = FrameRenderer::create(
      gpu.ctx(), FrameDesc{.width = 64, .height = 64, .color = ColorFormat::rgba8_unorm});
  REQUIRE(frame.has_value());
  CameraDesc camera;
  camera.eye = {0, 0, 4};
  ClaimingEffect claiming;
  Effect* effects[] = {&claiming};
  const auto red_pixels = [&] {
    auto image = frame->read_color();
    REQUIRE(image.has_value());
    return test::find_color(*image, {1, 0, 0}).count;
  };
  REQUIRE(frame->render(*renderer, camera, 0.0f, effects).has_value());
  CHECK(red_pixels() > 50);
  claiming.claimed = {marker};
  REQUIRE(frame->render(*renderer, camera, 0.0f, effects).has_value());
  CHECK(red_pixels() == 0);
  claiming.claimed.clear(); // released again: drawn by the scene renderer
  REQUIRE(frame->render(*renderer, camera, 0.0f, effects).has_value());
  CHECK(red_pixels() > 50);
}

TEST_CASE("toolkit: a snapshot region copies only its pixels and keeps the rest") {
  test::GpuFixture gpu;
  constexpr std::uint32_t w = 64, h = 32;
  auto source = RenderTarget::create(
      gpu.ctx(), RenderTargetDesc{.width = w, .height = h, .color = ColorFormat::rgba8_unorm});
  REQUIRE(source.has_value());
  auto snapshot = SceneSnapshot::create(gpu.ctx(), SnapshotDesc{.mips = false});
  REQUIRE(snapshot.has_value());
  std::uint64_t frame = 0;
  // Fills the source with `color`, then snapshots `region` of it.
  const auto copy = [&](glm::vec4 color, VkRect2D region) {
    const float clear[4] = {color.r, color.g, color.b, color.a};
    Result<void> recorded;
    require_ok(gpu.ctx().submit_and_wait([&](VkCommandBuffer cmd) {
      source->begin_rendering(cmd, clear);
      source->end_rendering(cmd);
      SnapshotSource src;
      src.color = source->color_image();
      src.color_format = source->vk_color_format();
      src.color_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      src.depth = source->depth_image();
      src.depth_layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
      src.extent = {w, h};
      src.mips = false;
      src.region = region;
      recorded = snapshot->record(cmd, src, ++frame);
    }));
    require_ok(recorded);
    auto image = read_debug_target(gpu.ctx(), snapshot->debug_targets().at(0));
    REQUIRE_MESSAGE(image.has_value(), image.error().message);
    return *image;
  };
  const auto pixel = [&](const FloatImage& image, std::uint32_t x, std::uint32_t y) {
    const float* p = &image.rgba[(std::size_t{y} * w + x) * 4];
    return glm::vec4(p[0], p[1], p[2], p[3]);
  };
  const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 1), blue(0, 0, 1, 1), none(0, 0, 0, 0);
  const VkRect2D first{{8, 4}, {16, 8}};     // x 8..23, y 4..11
  const VkRect2D second{{20, 10}, {60, 40}}; // clamped to x 20..63, y 10..31
  const auto inside = [](const VkRect2D& r, std::uint32_t x, std::uint32_t y) {
    return x >= std::uint32_t(r.offset.x) && x < r.offset.x + r.extent.width &&
           y >= std::uint32_t(r.offset.y) && y < r.offset.y + r.extent.height;
  };
  const FloatImage a = copy(red, first);
  const FloatImage b = copy(green, second);
  int mismatches = 0;
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      // Before any copy the snapshot is transparent black (samplable from creation).
      const glm::vec4 want_a = inside(first, x, y) ? red : none;
      const glm::vec4 want_b = inside(second, x, y) ? green : want_a;
      mismatches += pixel(a, x, y) != want_a ? 1 : 0;
      mismatches += pixel(b, x, y) != want_b ? 1 : 0;
    }
  }
  CHECK(mismatches == 0);
  const FloatImage c = copy(blue, VkRect2D{}); // everything
  CHECK(pixel(c, 0, 0) == blue);
  CHECK(pixel(c, w - 1, h - 1) == blue);

  // The union of what effects sample: "everything" absorbs any rectangle.
  CHECK(union_region(VkRect2D{}, first).extent.width == 0);
  const VkRect2D u = union_region(first, VkRect2D{{30, 2}, {4, 4}});
  CHECK(u.offset.x == 8);
  CHECK(u.offset.y == 2);
  CHECK(u.extent.width == 26);
  CHECK(u.extent.height == 10);
}

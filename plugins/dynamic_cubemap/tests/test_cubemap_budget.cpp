// The capture budget shared by probes (snell/capture_budget.hpp): its allocation order on its
// own, then 16 dynamic_cubemap probes under a budget of 6 faces a frame (lavapipe, validation on).
#include "frame_rig.hpp"

#include <snell/capture_budget.hpp>
#include <snell/dynamic_cubemap.hpp>

#include <algorithm>
#include <bitset>
#include <numeric>

using namespace snell;

namespace {

int face_count(std::uint32_t mask) {
  return static_cast<int>(std::bitset<32>(mask).count());
}

} // namespace

// Fails if the allocation ignores age or distance, exceeds the budget, grants faces nobody asked
// for, or lets a stale ticket (another frame) draw.
TEST_CASE("capture budget: stalest first, then nearest, never more than the budget") {
  CaptureBudget budget(6);
  CHECK(budget.faces_per_frame() == 6);
  const std::uint32_t far_stale = budget.request(7, {0x3Fu, 10, 50.0f});
  const std::uint32_t near_fresh = budget.request(7, {0x3Fu, 2, 1.0f});
  const std::uint32_t near_stale = budget.request(7, {0x0Cu, 10, 5.0f}); // faces 2 and 3 left
  CHECK(budget.grant(7, near_stale) == 0x0Cu);
  CHECK(budget.grant(7, far_stale) == 0x0Fu); // what the budget has left: 4 faces, lowest first
  CHECK(budget.grant(7, near_fresh) == 0u);
  CHECK(budget.faces_granted() == 6);
  CHECK(budget.grant(6, far_stale) == 0u); // not this frame
  CHECK(budget.grant(7, 99) == 0u);        // no such ticket
  const std::uint32_t next = budget.request(8, {0x3Fu, 3, 1.0f});
  CHECK(budget.grant(7, near_fresh) == 0u); // frame 7 is over
  budget.set_faces_per_frame(2);
  CHECK(budget.grant(8, next) == 0x03u);
  CHECK(budget.faces_granted() == 2);
}

// Fails if a probe under the budget draws more than granted, if the frame's faces exceed the
// budget, if a cube is published before its six faces are drawn, or if the order is not
// "stalest, then nearest". 16 probes in a row going away from the camera: frame 1 captures
// every cube whole (a budget never withholds a first capture); from then on each frame draws
// 6 faces in all, one cube is published a frame, nearest first, and each probe's second
// publication comes 16 frames after its first, in the same order.
TEST_CASE("dynamic_cubemap: 16 probes share a budget of 6 faces, stalest and nearest first") {
  test::GpuFixture gpu;
  test::FrameRig rig;
  rig.scene = test::empty_dark_scene();
  const int red = test::add_emissive_material(rig.scene, {1.0f, 0.0f, 0.0f});
  test::add_object(rig.scene, test::make_box_mesh(glm::vec3(0.3f), red), {0.0f, 2.0f, 0.0f});
  rig.camera.eye = {0.0f, 0.5f, 4.0f};
  rig.camera.target = {0.0f, 0.5f, 0.0f};
  rig.width = 96;
  rig.height = 64;
  rig.init_frame(gpu.ctx());
  CaptureBudget budget(6);
  EffectCreateInfo info = rig.effect_info(gpu.ctx());
  info.capture_budget = &budget;
  constexpr int probes = 16;
  std::vector<std::unique_ptr<DynamicCubemapEffect>> owned;
  std::vector<Effect*> effects;
  // Created in a shuffled order, so that filing order cannot pass for distance order.
  const int order[probes] = {5, 12, 0, 9, 14, 3, 7, 1, 15, 10, 6, 2, 13, 8, 4, 11};
  for (const int k : order) {
    auto created = create_dynamic_cubemap(info);
    REQUIRE_MESSAGE(created.has_value(), (created ? std::string() : created.error().message));
    DynamicCubemapParams p;
    p.center = {0.0f, 0.5f, 2.0f - 1.5f * static_cast<float>(k)}; // k-th nearest
    p.radius = 0.2f;
    p.face_size = 16;
    REQUIRE((*created)->set_params(p).has_value());
    effects.push_back(created->get());
    owned.push_back(std::move(*created));
  }
  const auto nearest_rank = [&](std::size_t i) { return order[i]; };

  float time = 0.0f;
  (void)rig.render_effects(effects, time);
  for (std::size_t i = 0; i < owned.size(); ++i) {
    CHECK(owned[i]->publications() == 1);
    CHECK(owned[i]->faces_captured() == 0x3Fu);
  }
  std::vector<int> published_order;
  for (int frame = 2; frame <= 2 + 2 * probes - 1; ++frame) {
    CAPTURE(frame);
    time += 1.0f / 60.0f;
    std::vector<std::uint64_t> before;
    for (const auto& p : owned) {
      before.push_back(p->publications());
    }
    (void)rig.render_effects(effects, time);
    int faces = 0;
    for (std::size_t i = 0; i < owned.size(); ++i) {
      faces += face_count(owned[i]->faces_captured());
      if (owned[i]->publications() != before[i]) {
        CHECK(owned[i]->publications() == before[i] + 1);
        published_order.push_back(nearest_rank(i));
      }
    }
    CHECK(faces == 6);
    CHECK(budget.faces_granted() == 6);
  }
  std::vector<int> expected(probes);
  std::iota(expected.begin(), expected.end(), 0);
  expected.insert(expected.end(), expected.begin(), expected.end());
  CHECK(published_order == expected);
  for (const auto& p : owned) {
    CHECK(p->publications() == 3);
  }
}

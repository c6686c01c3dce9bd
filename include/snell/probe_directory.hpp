// Snell runtime: the probes a host's effects publish, for other effects and host materials to
// sample. A dynamic_cubemap probe lists its published cube here; the glass effect then reflects
// the nearest probe's capture instead of the sky, and a host's own shader can do the same with
// shaders/snell/probe.glsl (docs/cubemap.md, "Host shading").
#pragma once

#include <glm/vec3.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace snell {

/// What a probe publishes: its cube and how to look it up (probe.glsl's probe_lookup and
/// probe_box_direction take these values).
struct ProbeView {
  /// Cube view of the published capture (all mip levels), SHADER_READ_ONLY_OPTIMAL from the
  /// probe's record_passes() on, valid for the rest of the frame and the frames in flight.
  VkImageView cube = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE; ///< Trilinear, clamp to edge.
  std::uint32_t mip_levels = 1;       ///< Levels of `cube` (roughness * (levels - 1)). Default 1.
  glm::vec3 center{0.0f};             ///< Where the capture was taken, world m. Default origin.
  bool box_projection = false;        ///< Lookups are box-projected. Default false.
  glm::vec3 box_min{0.0f};            ///< The room's corners when box_projection, world m.
  glm::vec3 box_max{0.0f};
  std::uint64_t publications = 0; ///< Cubes the probe published so far (0: none yet).
};

/// The host's list of published probes. The host owns one and hands it to its effects through
/// EffectCreateInfo::probes; it must outlive them. Probes publish in phase 2 (record_passes), so
/// every effect's record_draw (phase 5) sees this frame's cubes. Not thread-safe (frames are
/// recorded on one thread).
class ProbeDirectory {
public:
  /// Lists or updates the probe `owner` (any stable address, e.g. the effect).
  void publish(const void* owner, const ProbeView& view);
  /// Removes `owner` (a probe being destroyed or with nothing to show). No-op if absent.
  void withdraw(const void* owner);
  /// The listed probe whose centre is nearest to `position` with something published, or
  /// nullptr when none is.
  [[nodiscard]] const ProbeView* nearest(const glm::vec3& position) const;
  /// A consumer that samples `view` (a ProbeView this directory returned) above level 0 (a
  /// rough surface) says so every frame it does: the probe then builds its mip chain with its
  /// next capture. A probe builds the chain anyway for its first capture and when it samples
  /// blurred itself; otherwise it skips that work (a blit chain per capture) and publishes one
  /// level (mip_levels = 1, so roughness * (levels - 1) reads level 0).
  void want_levels(const ProbeView* view);
  /// For the probe `owner`: whether a consumer called want_levels() on its view since the last
  /// call (which clears it).
  [[nodiscard]] bool take_levels_wanted(const void* owner);
  /// How many probes are listed.
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

private:
  struct Entry {
    const void* owner = nullptr;
    ProbeView view{};
    bool levels_wanted = false; ///< want_levels() since the owner last asked.
  };
  std::vector<Entry> entries_{};
};

} // namespace snell

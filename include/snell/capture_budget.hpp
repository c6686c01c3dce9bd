// Snell runtime: a per-frame budget of cube-face captures shared by every probe of a host.
// Unity's realtime probes each refresh on their own, so a scene with many probes costs many
// captures a frame; here the host sets how many faces all probes together may draw in one frame,
// and the stalest (then nearest) probes get them. A probe's faces go into a back cube that is
// published whole, so a budget never shows a half-updated cube (docs/cubemap.md, "Budget").
#pragma once

#include <cstdint>
#include <vector>

namespace snell {

/// Faces all probes of a frame may capture together. The host owns one per renderer and hands it
/// to effects through EffectCreateInfo::capture_budget; it must outlive them. Not thread-safe:
/// frames are recorded on one thread (the frame phases of DESIGN.md).
///
/// Per frame: in phase 1 (update) every probe files a request(); in phase 2 (record_passes) each
/// asks grant() for its faces. The first grant() of a frame allocates: requests sorted by age
/// (frames since the probe's cube was last published, largest first), then by distance from the
/// eye (smallest first), then by filing order; each takes the faces it asked for, lowest face
/// first, while the budget lasts.
class CaptureBudget {
public:
  /// What a probe asks for in one frame.
  struct Request {
    /// Faces wanted, one bit per face (bit f = CubeFace f). Default 0x3F (all six).
    std::uint32_t faces = 0x3Fu;
    /// Frames since the probe's cube was last published (stalest first). Default 0.
    std::uint64_t age = 0;
    /// Distance of the probe from the main view's eye, m (nearest first among equally stale).
    /// Default 0.
    float distance = 0.0f;
  };

  /// `faces_per_frame`: how many faces all probes together may capture in one frame. 0 freezes
  /// every probe after its first capture (which a budget never withholds: a probe with nothing
  /// published has nothing to show). Default 6: about one full capture a frame.
  explicit CaptureBudget(std::uint32_t faces_per_frame = 6) : faces_per_frame_(faces_per_frame) {}

  /// Changes the budget from the next allocation on.
  void set_faces_per_frame(std::uint32_t faces) { faces_per_frame_ = faces; }
  /// The budget, faces a frame.
  [[nodiscard]] std::uint32_t faces_per_frame() const { return faces_per_frame_; }

  /// Phase 1: files `request` for frame `frame_index` (FrameInfo::frame_index) and returns its
  /// ticket for grant(). A frame index other than the last one's starts a new frame (the old
  /// requests are dropped).
  [[nodiscard]] std::uint32_t request(std::uint64_t frame_index, const Request& request);

  /// Phase 2: the faces granted to `ticket` in frame `frame_index` (a subset of what it asked
  /// for; 0 when the budget ran out, or for a ticket or frame that is not the current one).
  [[nodiscard]] std::uint32_t grant(std::uint64_t frame_index, std::uint32_t ticket);

  /// Faces granted in the current frame so far, in total (after its first grant()).
  [[nodiscard]] std::uint32_t faces_granted() const { return granted_total_; }

private:
  void allocate();

  std::uint32_t faces_per_frame_ = 6;
  std::uint64_t frame_ = 0;
  bool started_ = false;   ///< A frame's requests are being collected.
  bool allocated_ = false; ///< The current frame's grants are made.
  std::uint32_t granted_total_ = 0;
  std::vector<Request> requests_{};
  std::vector<std::uint32_t> granted_{};
};

} // namespace snell

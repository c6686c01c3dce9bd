// Snell plugin toolkit: destruction deferred past the frames in flight. An effect that replaces
// a target or a texture while the host may still be executing earlier frames hands the old one
// here instead of idling the host's device (vkDeviceWaitIdle on a device Snell does not own
// would stall the host's whole frame pipeline).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace snell {

/// Keeps retired resources alive until no frame in flight can use them.
///
/// Contract with the host (FrameInfo::frame_index, EffectCreateInfo::frames_in_flight): before
/// it records frame N the host has waited for frame N - frames_in_flight. A resource retired
/// while frame R was the newest recorded (or being recorded) is therefore unused once frame
/// R + frames_in_flight is being recorded; collect(N) destroys exactly those.
class DeferredRelease {
public:
  /// `frames_in_flight` >= 1 (0 is treated as 1). Default 2.
  explicit DeferredRelease(std::uint32_t frames_in_flight = 2)
      : frames_in_flight_(frames_in_flight == 0 ? 1 : frames_in_flight) {}

  /// Takes ownership of `resource` (any movable RAII object: RenderTarget, Texture2D, Buffer,
  /// Pipeline, ...) retired during frame `frame_index`.
  template <class T> void retire(std::uint64_t frame_index, T&& resource) {
    using V = std::decay_t<T>;
    items_.push_back(Item{frame_index, std::make_shared<V>(std::forward<T>(resource))});
  }

  /// Destroys everything retired at frames <= frame_index - frames_in_flight. Call once per frame
  /// (the toolkit's effects do it in update()).
  void collect(std::uint64_t frame_index) {
    std::size_t kept = 0;
    for (Item& item : items_) {
      if (item.frame + frames_in_flight_ > frame_index) {
        items_[kept++] = std::move(item);
      }
    }
    items_.resize(kept);
  }

  /// Destroys everything now. Only when the GPU is known to be idle (effect destruction).
  void release_all() { items_.clear(); }

  /// Number of resources waiting.
  [[nodiscard]] std::size_t pending() const { return items_.size(); }
  /// The frames-in-flight count this queue waits for.
  [[nodiscard]] std::uint32_t frames_in_flight() const { return frames_in_flight_; }

private:
  struct Item {
    std::uint64_t frame = 0;
    std::shared_ptr<void> resource{}; ///< Type-erased owner: its deleter destroys the resource.
  };
  std::uint32_t frames_in_flight_ = 2;
  std::vector<Item> items_;
};

} // namespace snell

// `snell view`: an interactive viewer of a scene with Snell's effects, and Snell's reference for
// a host that presents to a swapchain with frames in flight (docs/viewer.md).
//
// Frame loop (two frames in flight, per-frame command buffer, fence, acquire semaphore, GPU
// timer, scene colour + depth target and thumbnail descriptors; a "rendered" semaphore per
// swapchain image):
//   wait for this slot's fence (the frame two back) -> read its GPU times and screenshots ->
//   acquire an image (out of date: recreate, try again) -> UI and camera -> record Snell's frame
//   phases into the slot's target (effects' passes, opaque scene, snapshot, surfaces) -> blit it
//   to the swapchain image -> UI pass (Dear ImGui, thumbnails) -> submit -> present (out of date
//   or suboptimal: recreate). Minimised windows render nothing until restored.
#pragma once

namespace snell::viewer {

/// Frames the viewer records ahead of the GPU (EffectCreateInfo::frames_in_flight).
inline constexpr unsigned kFramesInFlight = 2;

} // namespace snell::viewer

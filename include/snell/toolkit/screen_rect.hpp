// Snell plugin toolkit: the pixels a world-space box covers on screen. Effects use it to scissor
// their passes and to tell the host which part of the scene snapshot they sample
// (Effect::snapshot_region), so that nothing outside it is drawn or copied.
#pragma once

#include <snell/math/bounds.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <vulkan/vulkan.h>

namespace snell {

/// The rectangle of pixels of an image of `extent` (covering the view's whole screen) that the
/// world box `box` projects to through `view_proj` (Vulkan clip space: uv = ndc * 0.5 + 0.5),
/// widened by `margin` pixels per side and clamped to the image.
/// - Some corner at or behind the eye (w <= 1e-4): the projection is unbounded, so the whole
///   image.
/// - An empty box, or one that projects entirely off the image: {{0, 0}, {1, 1}} (one pixel: a
///   render area must not be empty, and an extent of 0 x 0 means "everything" elsewhere).
[[nodiscard]] VkRect2D screen_rect(const glm::mat4& view_proj, const Aabb& box, VkExtent2D extent,
                                   glm::vec2 margin = glm::vec2(0.0f));

/// The union of two rectangles where an extent of 0 x 0 means "nothing" (the identity).
[[nodiscard]] VkRect2D rect_union(VkRect2D a, VkRect2D b);

} // namespace snell

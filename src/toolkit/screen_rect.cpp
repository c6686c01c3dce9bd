// The pixels a world-space box covers on screen (see snell/toolkit/screen_rect.hpp).
#include <snell/toolkit/screen_rect.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace snell {

VkRect2D screen_rect(const glm::mat4& view_proj, const Aabb& box, VkExtent2D extent,
                     glm::vec2 margin) {
  const VkRect2D whole{{0, 0}, extent};
  const VkRect2D none{{0, 0}, {1, 1}};
  if (is_empty(box) || extent.width == 0 || extent.height == 0) {
    return none;
  }
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                           (i & 4) ? box.max.z : box.min.z);
    const glm::vec4 clip = view_proj * glm::vec4(corner, 1.0f);
    if (!(clip.w > 1e-4f)) {
      return whole;
    }
    const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
    lo = glm::min(lo, uv);
    hi = glm::max(hi, uv);
  }
  const glm::vec2 size(static_cast<float>(extent.width), static_cast<float>(extent.height));
  lo = glm::clamp(lo * size - margin, glm::vec2(0.0f), size);
  hi = glm::clamp(hi * size + margin, glm::vec2(0.0f), size);
  const auto x0 = static_cast<std::uint32_t>(std::floor(lo.x));
  const auto y0 = static_cast<std::uint32_t>(std::floor(lo.y));
  const auto x1 = static_cast<std::uint32_t>(std::ceil(hi.x));
  const auto y1 = static_cast<std::uint32_t>(std::ceil(hi.y));
  if (x1 <= x0 || y1 <= y0) {
    return none;
  }
  return VkRect2D{{static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)},
                  {x1 - x0, y1 - y0}};
}

VkRect2D rect_union(VkRect2D a, VkRect2D b) {
  if (a.extent.width == 0 || a.extent.height == 0) {
    return b;
  }
  if (b.extent.width == 0 || b.extent.height == 0) {
    return a;
  }
  const std::int64_t x0 = std::min(a.offset.x, b.offset.x);
  const std::int64_t y0 = std::min(a.offset.y, b.offset.y);
  const std::int64_t x1 = std::max<std::int64_t>(a.offset.x + std::int64_t{a.extent.width},
                                                 b.offset.x + std::int64_t{b.extent.width});
  const std::int64_t y1 = std::max<std::int64_t>(a.offset.y + std::int64_t{a.extent.height},
                                                 b.offset.y + std::int64_t{b.extent.height});
  return VkRect2D{{static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)},
                  {static_cast<std::uint32_t>(x1 - x0), static_cast<std::uint32_t>(y1 - y0)}};
}

} // namespace snell

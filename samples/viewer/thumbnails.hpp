// Debug-target thumbnails inside Dear ImGui windows. Debian's Dear ImGui 1.86 Vulkan backend
// draws only its font texture (ImTextureID is ignored), so a thumbnail is an ImDrawList
// callback: inside the UI render pass it binds the viewer's own pipeline and draws the target's
// view into the item's rectangle, clipped to the window, then lets ImGui restore its state.
#pragma once

#include <snell/context.hpp>
#include <snell/effect.hpp>
#include <snell/result.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

struct ImDrawList;
struct ImDrawCmd;

namespace snell::viewer {

class Thumbnails {
public:
  /// The most thumbnails one frame draws (more are listed without a picture).
  static constexpr std::uint32_t kMaxPerFrame = 64;

  Thumbnails() = default;
  Thumbnails(const Thumbnails&) = delete;
  Thumbnails& operator=(const Thumbnails&) = delete;
  ~Thumbnails();

  /// Pipeline for `render_pass` (subpass 0), a descriptor pool per frame in flight.
  [[nodiscard]] Result<void> init(const Context& ctx, VkRenderPass render_pass,
                                  std::uint32_t frames_in_flight);
  /// Starts a frame in slot `slot` (whose previous frame the GPU has finished): frees that
  /// slot's descriptor sets. `cmd` is where the UI pass will be recorded, `extent` its size.
  void begin_frame(std::uint32_t slot, VkCommandBuffer cmd, VkExtent2D extent);
  /// Adds an ImGui item of `width` x `height` pixels showing `target` (in the current window).
  /// Returns false (and adds a plain placeholder) when this frame's thumbnails are used up.
  bool image(const DebugTarget& target, float width, float height);

private:
  struct Draw {
    Thumbnails* self = nullptr;
    VkDescriptorSet set = VK_NULL_HANDLE;
    bool depth = false;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0; ///< Screen pixels.
  };
  static void callback(const ImDrawList* list, const ImDrawCmd* cmd);
  void draw(const Draw& d, const ImDrawCmd& cmd) const;

  const Context* ctx_ = nullptr;
  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorPool> pools_;
  std::uint32_t slot_ = 0;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkExtent2D extent_{0, 0};
  std::vector<std::unique_ptr<Draw>> draws_; ///< This frame's (stable addresses for ImGui).
};

} // namespace snell::viewer

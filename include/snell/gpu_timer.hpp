// Snell runtime: GPU timestamps around passes (the benchmark's source of truth).
#pragma once

#include <snell/context.hpp>

#include <string>
#include <vector>

namespace snell {

/// One timed pass of a frame.
struct PassTime {
  std::string name{}; ///< Pass name ("main", "water.reflection", ...).
  double ms = 0.0;    ///< GPU time in milliseconds.
};

/// Records timestamp pairs around named passes in one command buffer and reads them after the
/// submission completed. Devices without timestamps report zeros (DeviceInfo::timestamp_period_ns).
class GpuTimer {
public:
  /// `max_passes`: how many begin/end pairs one frame may record (>= 1). Default 64.
  [[nodiscard]] static Result<GpuTimer> create(const Context& ctx, std::uint32_t max_passes = 64);
  GpuTimer() = default;
  GpuTimer(GpuTimer&&) noexcept;
  GpuTimer& operator=(GpuTimer&&) noexcept;
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;
  ~GpuTimer();

  /// Resets the queries for a new frame (record before any begin()).
  void reset(VkCommandBuffer cmd);
  /// Starts timing `name` (extra passes beyond max_passes are ignored).
  void begin(VkCommandBuffer cmd, std::string name);
  /// Ends the innermost pass begun.
  void end(VkCommandBuffer cmd);
  /// After the submission completed: the passes' times, in recording order.
  [[nodiscard]] Result<std::vector<PassTime>> read() const;

private:
  const ContextState* ctx_ = nullptr;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  std::uint32_t max_ = 0;
  std::vector<std::string> names_;
  std::vector<std::uint32_t> open_;
  std::uint32_t ended_ = 0;
};

/// Times the enclosing C++ scope as one pass: begin() on construction, end() on destruction,
/// nothing when `timer` is null (effects time their passes only when the host gives a timer).
class GpuTimerScope {
public:
  /// `timer`: may be null. `name`: the pass's name ("pass" when null).
  GpuTimerScope(GpuTimer* timer, VkCommandBuffer cmd, const char* name) : timer_(timer), cmd_(cmd) {
    if (timer_ != nullptr) {
      timer_->begin(cmd_, name != nullptr ? name : "pass");
    }
  }
  ~GpuTimerScope() {
    if (timer_ != nullptr) {
      timer_->end(cmd_);
    }
  }
  GpuTimerScope(const GpuTimerScope&) = delete;
  GpuTimerScope& operator=(const GpuTimerScope&) = delete;

private:
  GpuTimer* timer_;
  VkCommandBuffer cmd_;
};

} // namespace snell

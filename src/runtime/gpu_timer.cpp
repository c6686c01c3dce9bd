#include <snell/gpu_timer.hpp>

#include "context_impl.hpp"
#include "vk_util.hpp"

#include <utility>

namespace snell {

using detail::vk_init;

Result<GpuTimer> GpuTimer::create(const Context& ctx, std::uint32_t max_passes) {
  if (max_passes == 0) {
    return fail(ErrorCode::invalid_argument, "GpuTimer::create: max_passes must be >= 1");
  }
  GpuTimer t;
  t.ctx_ = context_state(ctx);
  t.max_ = max_passes;
  auto ci = vk_init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
  ci.queryCount = 2 * max_passes;
  SNELL_VK_TRY(vkCreateQueryPool(ctx.device(), &ci, nullptr, &t.pool_), "GPU timer query pool");
  return t;
}

GpuTimer::GpuTimer(GpuTimer&& o) noexcept
    : ctx_(std::exchange(o.ctx_, nullptr)), pool_(std::exchange(o.pool_, VK_NULL_HANDLE)),
      max_(o.max_), names_(std::move(o.names_)), open_(std::move(o.open_)), ended_(o.ended_) {}

GpuTimer& GpuTimer::operator=(GpuTimer&& o) noexcept {
  GpuTimer moved(std::move(o));
  std::swap(ctx_, moved.ctx_);
  std::swap(pool_, moved.pool_);
  std::swap(max_, moved.max_);
  std::swap(names_, moved.names_);
  std::swap(open_, moved.open_);
  std::swap(ended_, moved.ended_);
  return *this;
}

GpuTimer::~GpuTimer() {
  if (ctx_ != nullptr && pool_ != VK_NULL_HANDLE) {
    vkDestroyQueryPool(ctx_->device, pool_, nullptr);
  }
}

void GpuTimer::reset(VkCommandBuffer cmd) {
  vkCmdResetQueryPool(cmd, pool_, 0, 2 * max_);
  names_.clear();
  open_.clear();
  ended_ = 0;
}

void GpuTimer::begin(VkCommandBuffer cmd, std::string name) {
  if (names_.size() >= max_) {
    open_.push_back(UINT32_MAX);
    return;
  }
  const auto index = static_cast<std::uint32_t>(names_.size());
  names_.push_back(std::move(name));
  open_.push_back(index);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * index);
}

void GpuTimer::end(VkCommandBuffer cmd) {
  if (open_.empty()) {
    return;
  }
  const std::uint32_t index = open_.back();
  open_.pop_back();
  if (index != UINT32_MAX) {
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * index + 1);
    ++ended_;
  }
}

Result<std::vector<PassTime>> GpuTimer::read() const {
  std::vector<PassTime> out;
  if (names_.empty()) {
    return out;
  }
  if (ended_ != names_.size()) {
    return fail(ErrorCode::invalid_argument,
                "GpuTimer::read: " + std::to_string(names_.size() - ended_) +
                    " pass(es) begun but not ended");
  }
  std::vector<std::uint64_t> ticks(2 * names_.size());
  SNELL_VK_TRY(vkGetQueryPoolResults(
                   ctx_->device, pool_, 0, static_cast<std::uint32_t>(ticks.size()),
                   ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
               "reading GPU timestamps");
  const double period_ms = ctx_->info.timestamp_period_ns * 1e-6;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    out.push_back({names_[i], static_cast<double>(ticks[2 * i + 1] - ticks[2 * i]) * period_ms});
  }
  return out;
}

} // namespace snell

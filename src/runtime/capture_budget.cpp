// The shared per-frame face budget of the probes (include/snell/capture_budget.hpp).
#include <snell/capture_budget.hpp>

#include <algorithm>
#include <numeric>

namespace snell {

std::uint32_t CaptureBudget::request(std::uint64_t frame_index, const Request& request) {
  if (!started_ || frame_index != frame_) {
    frame_ = frame_index;
    started_ = true;
    allocated_ = false;
    granted_total_ = 0;
    requests_.clear();
    granted_.clear();
  }
  requests_.push_back(request);
  granted_.push_back(0);
  return static_cast<std::uint32_t>(requests_.size() - 1);
}

std::uint32_t CaptureBudget::grant(std::uint64_t frame_index, std::uint32_t ticket) {
  if (!started_ || frame_index != frame_ || ticket >= requests_.size()) {
    return 0;
  }
  if (!allocated_) {
    allocate();
    allocated_ = true;
  }
  return granted_[ticket];
}

void CaptureBudget::allocate() {
  std::vector<std::uint32_t> order(requests_.size());
  std::iota(order.begin(), order.end(), 0u);
  // Stalest first, then nearest; filing order keeps equal requests deterministic.
  std::stable_sort(order.begin(), order.end(), [this](std::uint32_t a, std::uint32_t b) {
    const Request& ra = requests_[a];
    const Request& rb = requests_[b];
    if (ra.age != rb.age) {
      return ra.age > rb.age;
    }
    return ra.distance < rb.distance;
  });
  std::uint32_t left = faces_per_frame_;
  for (const std::uint32_t i : order) {
    for (std::uint32_t face = 0; face < 6 && left > 0; ++face) {
      const std::uint32_t bit = 1u << face;
      if ((requests_[i].faces & bit) != 0) {
        granted_[i] |= bit;
        --left;
        ++granted_total_;
      }
    }
  }
}

} // namespace snell

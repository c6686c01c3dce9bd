// Per-pass GPU times over the last seconds, for the viewer's plot (and its exit summary).
#pragma once

#include <snell/gpu_timer.hpp>

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace snell::viewer {

class PassHistory {
public:
  /// Keeps the frames of the last `seconds` (at most `max_frames` of them).
  explicit PassHistory(double seconds = 5.0, std::size_t max_frames = 1200)
      : seconds_(seconds), max_frames_(max_frames) {}

  /// One finished frame: when it was submitted (seconds, any monotonic clock), its passes (as
  /// GpuTimer::read gives them; same-named passes of a frame are summed) and its CPU time.
  void add(double when, const std::vector<PassTime>& passes, double cpu_ms);

  /// Pass names in the order they first appear in the newest frames ("frame" first).
  [[nodiscard]] std::vector<std::string> names() const;
  /// The values of pass `name` over the kept frames, oldest first (0 where a frame lacks it).
  [[nodiscard]] std::vector<float> series(const std::string& name) const;
  /// CPU milliseconds between frames over the kept frames, oldest first.
  [[nodiscard]] std::vector<float> cpu_series() const;
  [[nodiscard]] std::size_t size() const { return frames_.size(); }

  /// Draws one plot per pass (ImGui, inside a window): the last seconds, the latest and mean
  /// values, all on one scale (the largest "frame" time) so their heights compare.
  void draw() const;

private:
  struct Frame {
    double when = 0.0;
    double cpu_ms = 0.0;
    std::vector<std::pair<std::string, float>> passes;
  };
  double seconds_;
  std::size_t max_frames_;
  std::deque<Frame> frames_;
};

} // namespace snell::viewer

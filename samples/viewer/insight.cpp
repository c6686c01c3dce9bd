#include "insight.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace snell::viewer {

void PassHistory::add(double when, const std::vector<PassTime>& passes, double cpu_ms) {
  Frame f;
  f.when = when;
  f.cpu_ms = cpu_ms;
  for (const PassTime& p : passes) {
    auto it = std::find_if(f.passes.begin(), f.passes.end(),
                           [&](const auto& e) { return e.first == p.name; });
    if (it == f.passes.end()) {
      f.passes.emplace_back(p.name, static_cast<float>(p.ms));
    } else {
      it->second += static_cast<float>(p.ms); // several probes' captures: the frame pays all
    }
  }
  frames_.push_back(std::move(f));
  while (!frames_.empty() &&
         (frames_.size() > max_frames_ || frames_.front().when < when - seconds_)) {
    frames_.pop_front();
  }
}

std::vector<std::string> PassHistory::names() const {
  std::vector<std::string> out;
  for (auto it = frames_.rbegin(); it != frames_.rend(); ++it) {
    for (const auto& [name, ms] : it->passes) {
      if (std::find(out.begin(), out.end(), name) == out.end()) {
        out.push_back(name);
      }
    }
    if (out.size() > 0 && std::distance(frames_.rbegin(), it) > 8) {
      break; // the newest frames name what is running now
    }
  }
  std::stable_partition(out.begin(), out.end(), [](const std::string& n) { return n == "frame"; });
  return out;
}

std::vector<float> PassHistory::series(const std::string& name) const {
  std::vector<float> out;
  out.reserve(frames_.size());
  for (const Frame& f : frames_) {
    float v = 0.0f;
    for (const auto& [n, ms] : f.passes) {
      if (n == name) {
        v = ms;
      }
    }
    out.push_back(v);
  }
  return out;
}

std::vector<float> PassHistory::cpu_series() const {
  std::vector<float> out;
  out.reserve(frames_.size());
  for (const Frame& f : frames_) {
    out.push_back(static_cast<float>(f.cpu_ms));
  }
  return out;
}

void PassHistory::draw() const {
  if (frames_.empty()) {
    ImGui::TextDisabled("no GPU times yet");
    return;
  }
  const double span = frames_.back().when - frames_.front().when;
  ImGui::TextDisabled("last %.1f s, %zu frames; ms (latest / mean)", span, frames_.size());
  const std::vector<std::string> passes = names();
  float scale = 0.1f;
  for (const std::string& n : passes) {
    for (const float v : series(n)) {
      scale = std::max(scale, v);
    }
  }
  const float width = ImGui::GetContentRegionAvail().x;
  auto plot = [&](const std::string& label, const std::vector<float>& values, float max) {
    const float mean = values.empty() ? 0.0f
                                      : std::accumulate(values.begin(), values.end(), 0.0f) /
                                            static_cast<float>(values.size());
    char overlay[96];
    std::snprintf(overlay, sizeof(overlay), "%s  %.2f / %.2f", label.c_str(),
                  values.empty() ? 0.0f : values.back(), mean);
    ImGui::PlotLines(("##" + label).c_str(), values.data(), static_cast<int>(values.size()), 0,
                     overlay, 0.0f, max, ImVec2(width, 36.0f));
  };
  for (const std::string& n : passes) {
    plot(n, series(n), scale);
  }
  const std::vector<float> cpu = cpu_series();
  plot("CPU frame", cpu, std::max(*std::max_element(cpu.begin(), cpu.end()), 0.1f));
}

} // namespace snell::viewer

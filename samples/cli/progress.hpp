// Progress of long work on stderr: one line, redrawn in place, only on a terminal.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace snell::cli {

/// A progress line for work that may take long (start-up, many frames, PNG encoding).
///
/// Nothing is shown unless stderr is a terminal (piped or redirected output stays clean), and
/// nothing before `delay` has passed since construction, so quick commands print no line at all.
/// After that a background thread redraws one line ("snell: <phase> <done>/<total>, <elapsed> s")
/// in place four times a second, cut to the terminal's width so it never wraps. stop() (or the
/// destructor) erases it; call it before printing anything else.
class ProgressLine {
public:
  /// `enabled`: usually stderr_is_terminal().
  explicit ProgressLine(bool enabled,
                        std::chrono::milliseconds delay = std::chrono::milliseconds(2000));
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// The current phase; `total` > 0 adds "done/total".
  void set(std::string phase, std::uint64_t done = 0, std::uint64_t total = 0);
  /// Stops the thread and erases the line if one was drawn. Idempotent.
  void stop();

  /// True when stderr is a terminal (and TERM is not "dumb").
  [[nodiscard]] static bool stderr_is_terminal();

private:
  void run();
  void draw(); // with mutex_ held

  using Clock = std::chrono::steady_clock;
  const Clock::time_point start_ = Clock::now();
  const std::chrono::milliseconds delay_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::string phase_;
  std::uint64_t done_ = 0;
  std::uint64_t total_ = 0;
  bool stopping_ = false;
  bool drawn_ = false;
  std::thread thread_;
};

} // namespace snell::cli

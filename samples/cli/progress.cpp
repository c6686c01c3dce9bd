#include "progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace snell::cli {

ProgressLine::ProgressLine(bool enabled, std::chrono::milliseconds delay) : delay_(delay) {
  if (enabled) {
    thread_ = std::thread([this] { run(); });
  }
}

ProgressLine::~ProgressLine() {
  stop();
}

bool ProgressLine::stderr_is_terminal() {
  const char* term = std::getenv("TERM");
  return ::isatty(STDERR_FILENO) == 1 && !(term != nullptr && std::string_view(term) == "dumb");
}

void ProgressLine::set(std::string phase, std::uint64_t done, std::uint64_t total) {
  const std::lock_guard lock(mutex_);
  phase_ = std::move(phase);
  done_ = done;
  total_ = total;
}

void ProgressLine::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) {
    thread_.join();
  }
  if (drawn_) {
    std::fputs("\r\033[K", stderr); // erase the line, leave the cursor at its start
    std::fflush(stderr);
    drawn_ = false;
  }
}

void ProgressLine::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stopping_; });
    if (!stopping_ && Clock::now() - start_ >= delay_) {
      draw();
    }
  }
}

void ProgressLine::draw() {
  winsize ws{};
  const std::size_t columns =
      ::ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1 ? ws.ws_col : 80;
  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  char numbers[96];
  if (total_ > 0) {
    std::snprintf(numbers, sizeof numbers, " %llu/%llu, %.0f s",
                  static_cast<unsigned long long>(done_), static_cast<unsigned long long>(total_),
                  seconds);
  } else {
    std::snprintf(numbers, sizeof numbers, ", %.0f s", seconds);
  }
  std::string line("snell: ");
  line.append(phase_).append(numbers);
  if (line.size() > columns - 1) {
    line.resize(columns - 1); // never wrap: a wrapped line cannot be redrawn in place
  }
  std::fprintf(stderr, "\r%s\033[K", line.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

} // namespace snell::cli

#include "progress.h"

#include <cstdio>
#include <unistd.h>

namespace prism {

ProgressReporter::ProgressReporter(bool enabled)
    : enabled_(enabled), terminal_(isatty(STDERR_FILENO) != 0) {}

ProgressReporter::~ProgressReporter() {
  if (printed_ && terminal_) std::fputs("\r\033[K", stderr);
}

void ProgressReporter::update(const RenderProgress& progress) {
  show([&](double elapsed) {
    char line[96];
    std::snprintf(line, sizeof line, "rendering: pass %d, %3.0f%% done, %.1f s", progress.pass,
                  100.0 * progress.fraction, elapsed);
    return std::string(line);
  });
}

void ProgressReporter::show(const std::function<std::string(double elapsedSeconds)>& text) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  const auto now = Clock::now();
  if (now - start_ < std::chrono::seconds(1)) return;
  // A terminal line can be redrawn often; a log file gets a line every 5 s.
  const auto interval =
      terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(5000);
  if (printed_ && now - lastPrint_ < interval) return;
  lastPrint_ = now;
  printed_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "%s%s%s", terminal_ ? "\r\033[K" : "", text(elapsed).c_str(),
               terminal_ ? "" : "\n");
  std::fflush(stderr);
}

} // namespace prism

#include "progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace prism {

std::string durationText(double seconds) {
  char text[48];
  if (!(seconds >= 0.0)) seconds = 0.0; // also NaN
  if (seconds >= 59.95) {
    const long long whole = std::llround(std::min(seconds, 1e12));
    if (whole < 3600)
      std::snprintf(text, sizeof text, "%lld min %02lld s", whole / 60, whole % 60);
    else
      std::snprintf(text, sizeof text, "%lld h %02lld min", whole / 3600, whole % 3600 / 60);
  } else {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  }
  return text;
}

std::string progressLine(const RenderProgress& progress, double elapsedSeconds, double pass1Seconds,
                         bool antialias) {
  const bool pass1 = progress.pass == 1;
  const double own =
      std::clamp(pass1 ? 2.0 * progress.fraction : 2.0 * progress.fraction - 1.0, 0.0, 1.0);
  const double shown = pass1 && !antialias ? own : progress.fraction;
  char head[64];
  std::snprintf(head, sizeof head, "rendering: pass %d, %3.0f%% done, ", progress.pass,
                100.0 * shown);
  std::string line = head + durationText(elapsedSeconds);
  const double spent = pass1 ? elapsedSeconds : elapsedSeconds - pass1Seconds;
  if (own > 0.0 && own < 1.0 && spent > 0.0) {
    line += ", about " + durationText(spent * (1.0 - own) / own) + " left";
    if (pass1 && antialias) line += " in pass 1, then pass 2";
  }
  return line;
}

ProgressReporter::ProgressReporter(bool enabled, bool antialias)
    : enabled_(enabled), terminal_(isatty(STDERR_FILENO) != 0), antialias_(antialias) {}

ProgressReporter::~ProgressReporter() {
  if (printed_ && terminal_) std::fputs("\r\033[K", stderr);
}

void ProgressReporter::update(const RenderProgress& progress) {
  if (!enabled_) return;
  double pass1Seconds = 0.0;
  {
    std::lock_guard lock(mutex_);
    if (progress.pass == 1)
      pass1Seconds_ = std::chrono::duration<double>(Clock::now() - start_).count();
    pass1Seconds = pass1Seconds_;
  }
  show([&](double elapsed) { return progressLine(progress, elapsed, pass1Seconds, antialias_); });
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

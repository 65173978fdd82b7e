// Progress of a long render on stderr: silent for the first second, then a
// line updated in place on a terminal, or an occasional line in a log.
#pragma once

#include "core/render/renderer.h"

#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace prism {

class ProgressReporter {
public:
  explicit ProgressReporter(bool enabled);
  ~ProgressReporter(); // ends the progress line

  void update(const RenderProgress& progress); // thread-safe
  // Any progress text (thread-safe): shown at the same pace and place.
  // `text` is called only when a line is due.
  void show(const std::function<std::string(double elapsedSeconds)>& text);

private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool terminal_;
  bool printed_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastPrint_ = start_;
  std::mutex mutex_;
};

} // namespace prism

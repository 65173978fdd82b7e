// Progress of a long render on stderr: silent for the first second, then a
// line updated in place on a terminal, or an occasional line in a log.
#pragma once

#include "core/render/renderer.h"

#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace prism {

// A duration for the progress line: "4.1 s" under a minute, "2 min 05 s"
// under an hour, "1 h 02 min" beyond.
std::string durationText(double seconds);

// The progress line of a render, with the time left at the pace so far,
// honest about pass 2 as the previewer's estimate is (viewer/progress_estimate.h):
// pass 2 supersamples only where neighbours differ, so its length is unknown
// while pass 1 runs.
//   pass 1: "rendering: pass 1,  20% done, 1.2 s, about 2.4 s left in pass 1, then pass 2"
//   pass 2: "rendering: pass 2,  63% done, 4.1 s, about 2.4 s left"
// `progress.fraction` is of the whole render (RenderProgress: pass 1 the
// first half, pass 2 the second). Pass 1's time left is its elapsed time
// times (1 - its share done) / its share done; pass 2's the same from its own
// time, elapsed - pass1Seconds (when pass 1 ended), and its own share. No
// estimate before any of a pass is done, nor at its end. `antialias` false
// (--no-aa): pass 1 is the whole render, and its share is the share shown.
std::string progressLine(const RenderProgress& progress, double elapsedSeconds, double pass1Seconds,
                         bool antialias);

class ProgressReporter {
public:
  // `antialias`: the render has a pass 2 (not --no-aa), for progressLine.
  explicit ProgressReporter(bool enabled, bool antialias = true);
  ~ProgressReporter(); // ends the progress line

  void update(const RenderProgress& progress); // thread-safe
  // Any progress text (thread-safe): shown at the same pace and place.
  // `text` is called only when a line is due.
  void show(const std::function<std::string(double elapsedSeconds)>& text);

private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool terminal_;
  bool antialias_;
  bool printed_ = false;
  double pass1Seconds_ = 0.0; // when the last pass-1 progress came
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastPrint_ = start_;
  std::mutex mutex_;
};

} // namespace prism

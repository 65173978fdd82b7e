#include "frame_stats.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace prism {

namespace {

// The q-quantile (nearest rank) of `values`, in milliseconds.
double quantileMs(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = std::size_t(q * double(values.size() - 1) + 0.5);
  return values[std::min(rank, values.size() - 1)] * 1000.0;
}

} // namespace

void FrameStats::record(double interval, double work, bool rendering) {
  if (interval > 0.0) {
    // An exponential average over ~30 frames: steady enough to read.
    const double fps = 1.0 / interval;
    recentFps_ = recentFps_ == 0.0 ? fps : recentFps_ + (fps - recentFps_) / 30.0;
  }
  if (!rendering) {
    ++idleFrames_;
    return;
  }
  renderingIntervals_.push_back(interval);
  renderingWork_.push_back(work);
}

FrameStats::Figures FrameStats::whileRendering() const {
  Figures f;
  f.frames = renderingIntervals_.size();
  f.seconds = std::accumulate(renderingIntervals_.begin(), renderingIntervals_.end(), 0.0);
  f.fps = f.seconds > 0.0 ? double(f.frames) / f.seconds : 0.0;
  f.intervalP50 = quantileMs(renderingIntervals_, 0.5);
  f.intervalP95 = quantileMs(renderingIntervals_, 0.95);
  f.intervalMax = quantileMs(renderingIntervals_, 1.0);
  f.workP50 = quantileMs(renderingWork_, 0.5);
  f.workP95 = quantileMs(renderingWork_, 0.95);
  f.workMax = quantileMs(renderingWork_, 1.0);
  return f;
}

std::string FrameStats::summary() const {
  const Figures f = whileRendering();
  char text[320];
  std::snprintf(text, sizeof text,
                "frames while rendering: %zu in %.2f s = %.1f fps; frame interval ms p50 %.1f "
                "p95 %.1f max %.1f; frame work ms p50 %.1f p95 %.1f max %.1f; idle frames: %zu",
                f.frames, f.seconds, f.fps, f.intervalP50, f.intervalP95, f.intervalMax, f.workP50,
                f.workP95, f.workMax, idleFrames_);
  return text;
}

} // namespace prism

// Frame timing of the previewer: how smoothly the window redraws while the
// render threads work. Kept per frame so a scripted session can report the
// figures docs/previewer.md quotes (frame rate while rendering, frame-time percentiles).
#pragma once

#include <string>
#include <vector>

namespace prism {

class FrameStats {
public:
  // One frame: `interval` seconds since the previous frame began, `work`
  // seconds spent on it before waiting for the next (events, upload, drawing).
  // `rendering` says whether the render was still running.
  void record(double interval, double work, bool rendering);

  // Frames per second over the last second or so, for the panel.
  double recentFps() const { return recentFps_; }

  // "frames while rendering: N in S s = F fps; interval ms p50/p95/max: ...;
  // work ms p50/p95/max: ...". Frames after the render finished are counted
  // separately (the window then just idles at the capped rate).
  std::string summary() const;

  struct Figures {
    std::size_t frames = 0;
    double seconds = 0.0;
    double fps = 0.0;
    double intervalP50 = 0.0, intervalP95 = 0.0, intervalMax = 0.0; // milliseconds
    double workP50 = 0.0, workP95 = 0.0, workMax = 0.0;             // milliseconds
  };
  Figures whileRendering() const;

private:
  std::vector<double> renderingIntervals_;
  std::vector<double> renderingWork_;
  std::size_t idleFrames_ = 0;
  double recentFps_ = 0.0;
};

} // namespace prism

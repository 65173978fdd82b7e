#include "core/render/renderer.h"

#include "core/render/parallel.h"
#include "core/render/pass_schedule.h"

#include <algorithm>
#include <mutex>

namespace prism {

namespace {

// Keeps what render() returns besides the film, and reports progress.
class ResultSink final : public ScheduleSink {
public:
  ResultSink(RenderResult& result, int tileCount, const ProgressCallback& progress)
      : result_(result), tileCount_(tileCount), progress_(progress) {}

  void tileDone(const TileSamples& tile) override {
    if (!progress_) return;
    std::lock_guard lock(mutex_);
    const int done = ++tilesDone_[tile.pass - 1];
    // Pass 2 costs more per tile than pass 1, but both are shown as halves:
    // progress is for reassurance, not for estimating the end to the second.
    progress_({tile.pass, 0.5 * double(done) / double(tileCount_) + (tile.pass == 2 ? 0.5 : 0.0)});
  }
  void pass1Complete(double avgmax) override { result_.avgmax = avgmax; }
  void done(const RayCounts& counts) override { result_.counts = counts; }

private:
  RenderResult& result_;
  int tileCount_;
  const ProgressCallback& progress_;
  std::mutex mutex_;
  int tilesDone_[2] = {0, 0}; // per pass
};

} // namespace

RenderResult render(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                    const ProgressCallback& progress, const StopCheck& stop) {
  ThreadPoolExecutor executor(resolveThreadCount(settings.threads));
  return render(scene, accel, settings, executor, progress, stop);
}

RenderResult render(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                    Executor& executor, const ProgressCallback& progress, const StopCheck& stop) {
  // Pass 1 in one go: a preview level would only change the order.
  const PassSchedule schedule(scene, accel, settings);
  RenderResult result;
  result.film = Film(settings.width, settings.height);
  ResultSink sink(result, schedule.tileCount(), progress);
  if (!schedule.run(result.film, executor, sink, stop)) {
    result.cancelled = true;
    return result;
  }
  result.supersampledPixels =
      std::count(result.film.supersampled.begin(), result.film.supersampled.end(), std::uint8_t(1));
  return result;
}

void recordInStats(const RenderSettings& settings, const RenderResult& result, RenderStats& stats) {
  stats.width = settings.width;
  stats.height = settings.height;
  stats.maxDepth = settings.maxDepth;
  stats.thresh = settings.thresh;
  stats.jitter = settings.jitter;
  stats.noAa = settings.noAa;
  stats.bailout = settings.bailout;
  stats.threads = settings.threads;
  stats.counts = result.counts;
  stats.supersampledPixels = result.supersampledPixels;
  stats.avgmax = result.avgmax;
}

} // namespace prism

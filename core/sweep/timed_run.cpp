#include "core/sweep/timed_run.h"

#include "core/system/system_info.h"

#include <algorithm>
#include <chrono>
#include <mutex>

namespace prism {

namespace {

// Keeps avgmax and the counts; reports the share of the run's tiles done,
// pass 1 and pass 2 each half of it when the run traces both.
class CaptureSink final : public ScheduleSink {
public:
  CaptureSink(TimedRun& run, int tiles, int passes, const TileProgress& progress)
      : run_(run), tiles_(tiles), passes_(passes), progress_(progress) {}

  void tileDone(const TileSamples& tile) override {
    if (!progress_) return;
    std::lock_guard lock(mutex_);
    const int passIndex = passes_ == 2 ? tile.pass - 1 : 0;
    progress_((double(passIndex) + double(++done_[tile.pass - 1]) / double(tiles_)) /
              double(passes_));
  }
  void pass1Complete(double avgmax) override { run_.avgmax = avgmax; }
  void done(const RayCounts& counts) override { run_.counts = counts; }

private:
  TimedRun& run_;
  int tiles_;
  int passes_;
  const TileProgress& progress_;
  std::mutex mutex_;
  int done_[2] = {0, 0};
};

} // namespace

TimedRun runTimed(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                  Executor& executor, Film film, Pass1 pass1, const TileProgress& progress) {
  const PassSchedule schedule(scene, accel, settings);
  TimedRun run;
  run.film = std::move(film);
  const int passes = (pass1 == Pass1::Trace ? 1 : 0) + (settings.noAa ? 0 : 1);
  CaptureSink sink(run, schedule.tileCount(), std::max(passes, 1), progress);
  const double cpuStart = processCpuSeconds();
  const auto wallStart = std::chrono::steady_clock::now();
  schedule.run(run.film, executor, sink, {}, pass1);
  run.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  run.cpuSeconds = processCpuSeconds() - cpuStart;
  return run;
}

} // namespace prism

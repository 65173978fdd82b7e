#include "core/sweep/timed_run.h"

#include "core/system/system_info.h"

#include <chrono>

namespace prism {

namespace {

// Keeps what a run reports besides the film: avgmax and the counts.
class CaptureSink final : public ScheduleSink {
public:
  explicit CaptureSink(TimedRun& run) : run_(run) {}

  void pass1Complete(double avgmax) override { run_.avgmax = avgmax; }
  void done(const RayCounts& counts) override { run_.counts = counts; }

private:
  TimedRun& run_;
};

} // namespace

TimedRun runTimed(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                  Executor& executor, Film film, Pass1 pass1) {
  const PassSchedule schedule(scene, accel, settings);
  TimedRun run;
  run.film = std::move(film);
  CaptureSink sink(run);
  const double cpuStart = processCpuSeconds();
  const auto wallStart = std::chrono::steady_clock::now();
  schedule.run(run.film, executor, sink, {}, pass1);
  run.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  run.cpuSeconds = processCpuSeconds() - cpuStart;
  return run;
}

} // namespace prism

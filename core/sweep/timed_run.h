// One run of the pass schedule on a given executor, with the resources it
// took: what the sweep measures each setting by.
#pragma once

#include "core/render/executor.h"
#include "core/render/pass_schedule.h"

namespace prism {

struct TimedRun {
  Film film;
  double avgmax = 0.0;
  RayCounts counts;        // every ray this run traced (not those of a kept pass 1)
  double cpuSeconds = 0.0; // the whole process, all threads, while it ran
  double wallSeconds = 0.0;
};

// Runs the schedule of `settings` over `film` (its size; with Pass1::Keep its
// centres must be a complete pass 1 of the same scene, size and depth). CPU
// time is the process's: nothing else should be running meanwhile.
TimedRun runTimed(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                  Executor& executor, Film film, Pass1 pass1);

} // namespace prism

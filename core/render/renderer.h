// A complete render (docs/image-formation.md) on all cores: the pass schedule
// (core/render/pass_schedule.h: pass 1 over tiles, avgmax, pass 2 over tiles)
// run to completion on the thread pool. The picture is the same for any thread
// count: every pixel's value depends only on the scene and settings, and
// counts are summed per worker.
#pragma once

#include "core/accel/accel.h"
#include "core/render/executor.h"
#include "core/render/film.h"
#include "core/render/ray_counts.h"
#include "core/render/stats.h"

#include <functional>

namespace prism {

// What a render is asked to do. Every member restarts a render when changed.
struct RenderSettings {
  int width = 512; // pixels
  int height = 512;
  int maxDepth = 5;    // D >= 1; 1 is ray casting with shadows
  double thresh = 0.1; // antialiasing threshold in [0, 1], a fraction of avgmax
  bool jitter = false; // jitter sub-samples within their 4x4 cells
  bool noAa = false;   // pass 1 only: one eye ray per pixel, no pass 2
  // W >= 0: skip mirror and refracted rays whose whole contribution to a
  // sample stays within W levels of its 8-bit value (core/render/bailout.h);
  // 0 traces exactly.
  double bailout = 0.0;
  int threads = 0;   // 0: every hardware thread
  int tileSize = 32; // pixels per tile side: the unit of work
  // Pass 2 only inside the pixels [cropX0, cropX1) x [cropY0, cropY1)
  // (`prism render --crop`); pass 1, avgmax and pass 2's decisions stay the
  // whole frame's, so the pixels inside are those of the uncropped render.
  // cropX1 == 0: no crop.
  int cropX0 = 0, cropY0 = 0, cropX1 = 0, cropY1 = 0;
};

struct RenderProgress {
  int pass = 1;          // 1: pixel centres, 2: adaptive antialiasing
  double fraction = 0.0; // of the whole render, 0..1
};

struct RenderResult {
  Film film;
  double avgmax = 0.0;
  RayCounts counts;
  long long supersampledPixels = 0;
  // `stop` ended the render early: the film is incomplete and the rest of
  // the result unset.
  bool cancelled = false;
};

using ProgressCallback = std::function<void(const RenderProgress&)>;

// `progress` is called from worker threads (one at a time) after each tile;
// `stop`, if given, between tiles: once it returns true the render ends
// early, as soon as the tiles in flight are done.
RenderResult render(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                    const ProgressCallback& progress = {}, const StopCheck& stop = {});

// The same on `executor` (settings.threads is then the executor's business):
// for a distributed executor the result is whole on rank 0 only, and
// `progress` hears this process's tiles.
RenderResult render(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                    Executor& executor, const ProgressCallback& progress = {},
                    const StopCheck& stop = {});

// A render's settings and what it counted (rays, supersampled pixels,
// avgmax) into its statistics; the scene, machine and times are the caller's.
void recordInStats(const RenderSettings& settings, const RenderResult& result, RenderStats& stats);

} // namespace prism

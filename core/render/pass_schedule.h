// The pass schedule of image formation (docs/image-formation.md), defined once for every
// way of running it:
//
//   coarse levels (one pixel-centre sample per 8x8 block, then 4x4, 2x2, 1x1;
//   each level traces only the centres the coarser ones did not)   = pass 1
//   -> reduction point 1 (Executor::completePass1) -> avgmax
//   -> pass 2: 16 sub-samples where pass-1 neighbours differ
//   -> reduction point 2 (Executor::completeRender)
//
// render() runs it with a single level (pass 1 in one go) to completion; the
// previewer's RenderSession runs it with the preview levels, cancels it on
// every edit and keeps pass 1 when only the threshold or jitter changed. Every
// sample taken is a sample of the final picture, whatever the levels: each
// pixel's value depends only on the scene and the settings, so the film is
// bit-for-bit the same for any level count, executor, worker count or order.
//
// The work items are tiles, run by an Executor (core/render/executor.h). A
// tile's samples are written into the film when the whole tile is done (a
// cancelled tile writes nothing) and then reported to a ScheduleSink, which
// publishes them: progress for `prism render`, the display buffers of the
// previewer.
#pragma once

#include "core/accel/accel.h"
#include "core/render/executor.h"
#include "core/render/film.h"
#include "core/render/image_formation.h"
#include "core/render/ray_counts.h"
#include "core/render/renderer.h"
#include "core/scene/camera.h"

#include <vector>

namespace prism {

// The previewer's first level: one sample per 8x8 block.
inline constexpr int kPreviewCoarsestLevel = 8;

// True when pixel (x, y) gets its centre sample at coarse `level` of a
// schedule whose first level is `coarsest` (levels halve down to 1, all powers
// of two): it lies on that level's grid and on no coarser one. Every pixel is
// new at exactly one level, so the levels together are pass 1, each centre
// traced once. Bit tests rather than remainders: it runs for every pixel of
// pass 1, and the levels are powers of two.
inline bool isNewAtLevel(int x, int y, int level, int coarsest = kPreviewCoarsestLevel) {
  if (((x | y) & (level - 1)) != 0) return false;     // off this level's grid
  return level == coarsest || ((x | y) & level) != 0; // the first, or off the coarser grid
}

// What one tile produced in one pass (or coarse level): already in the film
// when a sink sees it.
struct TileSamples {
  int pass = 1;  // 1: pixel centres, 2: adaptive antialiasing
  int level = 1; // pass 1's coarse level (block side); 1 in pass 2
  int tile = 0;  // index into PassSchedule::tiles()
  std::vector<Sample> samples;
  RayCounts counts; // every ray traced for these samples
};

// Told what the schedule produces, in this order: pilotDone when a bailout
// traced its pilot (core/render/bailout.h), levelStarted for each
// level, tileDone for each of its tiles, pass1Complete, tileDone for each
// tile of pass 2, done. tileDone is called from the executor's workers,
// possibly at the same time; the others from the thread that runs the
// schedule, between passes. A cancelled run stops telling anywhere.
class ScheduleSink {
public:
  virtual ~ScheduleSink() = default;
  // The pilot's rays (RayCounts::bailoutPilot), which no tile reports.
  virtual void pilotDone(const RayCounts& counts) { (void)counts; }
  virtual void levelStarted(int level) { (void)level; }
  virtual void tileDone(const TileSamples& tile) { (void)tile; }
  virtual void pass1Complete(double avgmax) { (void)avgmax; }
  // `counts`: every ray this run traced (after reduction point 2).
  virtual void done(const RayCounts& counts) { (void)counts; }
};

enum class Pass1 {
  Trace, // the whole schedule
  Keep,  // the film's centres are this scene's pass 1 already: redo pass 2 only
};

class PassSchedule {
public:
  // Over `scene` with `settings` (size, depth, threshold, jitter, tile size;
  // not the thread count, which is the executor's business). `coarsestLevel`:
  // the side of the first level's blocks, a power of two (else
  // std::invalid_argument); 1 traces pass 1 in one go, in the bundles
  // render() has always traced.
  PassSchedule(const Scene& scene, const Accel& accel, const RenderSettings& settings,
               int coarsestLevel = 1);

  const std::vector<Tile>& tiles() const { return tiles_; }
  int tileCount() const { return int(tiles_.size()); }

  // Runs the schedule into `film` (of the settings' size), telling `sink`.
  // Returns false when `stop` ended it early (then `sink` is not told done and
  // the film holds a part of the samples). With Pass1::Keep the film's
  // centres must be a complete pass 1 of the same scene, camera, size and
  // depth; its radiance starts over from them.
  bool run(Film& film, Executor& executor, ScheduleSink& sink, const StopCheck& stop = {},
           Pass1 pass1 = Pass1::Trace) const;

private:
  class Run; // one run's film, executor, sink and counts

  const Scene& scene_;
  const Accel& accel_;
  RenderSettings settings_;
  int coarsestLevel_;
  Camera camera_;
  std::vector<Tile> tiles_;
};

} // namespace prism

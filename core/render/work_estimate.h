// A cheap look ahead at a deep render's work (docs/rendering-model.md#work-estimate),
// made before it starts so that `prism render` can warn when the ray tree
// explodes: a glass sphere between two mirrors doubles it at every glass hit,
// and at depth 200 pass 1 would never end.
//
// The pixel centres of a regular grid of at most 16 x 16 pixels are traced
// at depth 5, 6, 7, 8, 9, ... until the rays traced exceed a budget (or, for
// a growing tree, 1% of the render's rays up to a cap) or the depth reaches
// the render's. The rays a sampled
// pixel gains from one depth to the next, R(k) - R(k-1), are the rays of depth exactly k; their
// ratio from level to level is how fast the tree grows. A tree of mirror chains (no branching)
// gains at most as many rays per level as before, and is extrapolated linearly; a branching one
// geometrically. Only pass 1 is estimated: pass 2 traces 16 more eye rays per supersampled pixel on
// top.
#pragma once

#include "core/accel/accel.h"
#include "core/render/renderer.h"
#include "core/scene/scene.h"

#include <string>

namespace prism {

// Renders up to this depth are never estimated: their trees are at most
// 2^8 rays deep per eye ray, and the estimate would cost as much as it saves.
inline constexpr int kEstimateFromDepth = 8;

// The sampled rays (all depths traced so far, every kind) after which the
// estimate stops going deeper, some milliseconds of tracing; unless the tree
// still grows and 1% of the rays of the render it foresees is more, up to the
// cap, a tenth of a second or so.
inline constexpr double kEstimateRayBudget = 100'000.0;
inline constexpr double kEstimateRayCap = 1'000'000.0;

// Pass 1 expected to take longer than this (on the render's threads) is
// reported as exploding: 10 minutes, far beyond any render of the example
// scenes, and far below what a geometric tree reaches: it grows by orders of
// magnitude over a few tens of levels, so the verdict does not hinge on the
// estimate being accurate to a factor of a few.
inline constexpr double kExplodingSeconds = 600.0;

struct WorkEstimate {
  bool made = false;         // false: maxDepth <= kEstimateFromDepth, nothing traced
  int sampledPixels = 0;     // the grid's pixels
  int measuredDepth = 0;     // the deepest level traced
  double raysPerPixel = 0.0; // R(measuredDepth): rays per sampled pixel (pass 1)
  // The ratio of the rays gained per level, R(k) - R(k-1), over the last two
  // levels (the geometric mean of two steps, which cancels a tree that grows
  // more on even levels than on odd ones). 0 once the tree ended; at most 1
  // for mirror chains.
  double growth = 0.0;
  double estimatedRaysPerPixel = 0.0; // R(maxDepth), extrapolated; may be +infinity
  double estimatedSeconds = 0.0; // pass 1 of the whole image on the render's threads; may be +inf
  double raysPerCpuSecond = 0.0; // measured on the sample (0 when too fast to time)
  double sampleRays = 0.0;       // rays the estimate itself traced, every level
  bool explodes = false;         // estimatedSeconds > kExplodingSeconds

  // Everything but the timings (rays per CPU second and the seconds).
  bool sameCounts(const WorkEstimate& o) const;
};

// The estimate for rendering `scene` with `settings` (size, depth, bailout,
// threads), or one with made = false when settings.maxDepth is at most
// kEstimateFromDepth. With a bailout the sample is traced with it, with an
// allowance from the sample's own depth-1 avgmax (the render takes it from
// every pixel), so a bailout that bounds the tree is seen to bound it.
WorkEstimate estimateWork(const Scene& scene, const Accel& accel, const RenderSettings& settings);

// Rays per pixel at depth `maxDepth` from R(k) = `raysPerPixel` at `depth`,
// gaining `gained` rays at that last level and `growth` times more per level
// beyond: R + gained (g + g^2 + ... + g^(maxDepth - depth)). +infinity
// past the largest double.
double extrapolateRays(double raysPerPixel, double gained, double growth, int depth, int maxDepth);

// The one-line warning (without "prism: warning: " and the newline) for an
// estimate that explodes, for a render with `settings`.
std::string workWarning(const WorkEstimate& estimate, const RenderSettings& settings);

// "3 minutes", "2.1 hours", "4e+52 years": a duration for people.
std::string roughDuration(double seconds);

} // namespace prism

// The bailout of `--bailout W` (docs/rendering-model.md#bailout): a mirror or
// refracted ray is not traced when everything it could bring back is too
// little to move the sample's 8-bit value by its share of W levels. This file
// holds the two numbers the tracer decides by, computed once per render:
//
//   beyond[k]  an upper bound on the radiance (every channel) any ray of depth
//              k can return in this scene at this maximum depth;
//   allowance  the radiance W levels stand for, W * avgmax / 128, with a lower
//              bound on the render's avgmax.
//
// The proof that the skipped rays of one sample sum to at most `allowance` is
// in the docs; the tracer's part of it is Tracer::reflection/transmission.
#pragma once

#include "core/scene/scene.h"

#include <vector>

namespace prism {

struct BailoutBound {
  std::vector<double> beyond; // index k = 1..maxDepth; empty: no bailout
  double allowance = 0.0;     // radiance; the eye ray's share of W levels

  bool active() const { return !beyond.empty(); }
};

// The smallest distance from each light to any primitive's bounding box (a
// lower bound on its distance r_j to any hit point; 0 when it lies in one).
std::vector<double> lightClearances(const Scene& scene);

// beyond[k] for k = 1..maxDepth (index 0 unused): with S = sum_j E_j / d_j^2
// over the lights' clearances d_j, a local term is at most
// C kdr (A + S) + ksr S, and
//   beyond[D] = max(B, F, max over materials of local)
//   beyond[k] = max(B, F, max over materials of local + (ksr + kst) beyond[k+1])
// (F the fog's colour, when the scene has fog)
// taken per channel, then the largest channel. Infinite when a light touches
// a box: nothing is then ever skipped.
std::vector<double> radianceBounds(const Scene& scene, int maxDepth);

// False when no ray of any sample could pass the tracer's test at W =
// `levels`, whatever the avgmax: a ray of depth k + 1 from a hit on material
// m is skipped when beyond[k + 1] (ksr + kst)_m <= a, and a is at most
// W * beyond[1] / 128 (no sample, so no avgmax, exceeds beyond[1]) divided
// by (ksr + kst) of each hit above it, each at least the smallest positive
// (ksr + kst) of the scene. Then the render traces exactly, without a pilot.
bool bailoutCanSkip(const Scene& scene, const std::vector<double>& beyond, double levels);

// The radiance W = `levels` levels stand for when the picture is exposed by
// `avgmax` or more: the exposure maps avgmax / 128 to one level.
inline double bailoutAllowance(double levels, double avgmax) { return levels * avgmax / 128.0; }

} // namespace prism

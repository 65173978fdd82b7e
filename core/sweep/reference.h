// The reference picture a sweep measures every setting against
// (docs/choosing-settings.md): the model's picture with its two
// approximations taken to their limit. Each pixel is the mean of
// kReferenceSide^2 stratified, jittered eye rays (the integral of radiance
// over the pixel that 4x4 adaptive supersampling approximates), traced to a
// depth of its own: the depth beyond which a deeper trace changes no 8-bit
// value of its centre or of its neighbours' centres. The exposure is the
// model's, avgmax over the pixel centres at those depths.
//
// The depth is found per pixel because glass doubles the ray tree at every
// hit: a whole picture traced as deep as its slowest pixel needs (often 20
// and more) would cost thousands of times its depth-8 picture, while all but
// a few pixels settle by depth 10 or 12.
#pragma once

#include "core/accel/accel.h"
#include "core/render/executor.h"
#include "core/render/film.h"
#include "core/render/ray_counts.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace prism {

// 8 x 8 = 64 samples per pixel, one bundle of eye rays.
inline constexpr int kReferenceSide = 8;

struct ReferenceSettings {
  int width = 0, height = 0;
  // Every centre is traced at firstDepth and firstDepth + depthStep; those
  // whose 8-bit value changed again each depthStep deeper, until they stop
  // changing or reach lastDepth (then the picture is not `converged`). Steps
  // of two: a ray caught between two surfaces alternates between them.
  int firstDepth = 8;
  int depthStep = 2;
  int lastDepth = 32;
};

struct ReferencePicture {
  int width = 0, height = 0;
  std::vector<Rgb> radiance;       // per pixel, the mean of its samples
  std::vector<Rgb> centres;        // per pixel, the centre sample at its depth
  std::vector<std::uint8_t> depth; // per pixel, the depth its samples were traced to
  double avgmax = 0.0;             // of the centres: the model's exposure
  int deepest = 0;                 // the largest depth of any pixel
  bool converged = false;          // no centre still changed at lastDepth
  RayCounts counts;                // every ray traced, the depth search's included
  double cpuSeconds = 0.0;
  double wallSeconds = 0.0;
};

// `progress` gets a share of the whole job, 0..1 (the depth search is counted
// as its first tenth). Needs lastDepth <= 255.
ReferencePicture renderReference(const Scene& scene, const Accel& accel,
                                 const ReferenceSettings& settings, Executor& executor,
                                 const std::function<void(double)>& progress = {});

// The point of pixel (x, y)'s stratum (i, j) of kReferenceSide x
// kReferenceSide where the reference samples it: jittered within the stratum
// by a hash of pixel and stratum, in image coordinates.
void referenceSamplePoint(int x, int y, int i, int j, double& px, double& py);

} // namespace prism

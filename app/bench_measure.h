// What `prism bench` measures, one function per figure: recorded ray queries,
// ray throughput of an Accel (intersection only) and of the Tracer (with
// shading), and whole renders. Timings on one thread are that thread's CPU
// time, so other processes on a shared machine disturb them little; timings on
// several threads are wall time.
#pragma once

#include "core/accel/accel.h"
#include "core/render/renderer.h"

#include <vector>

namespace prism {

// One query as the tracer made it.
struct RayQuery {
  Ray ray;
  Interval range;
  PrimitiveRef skip;
  bool hasSkip = false;
};

// The rays of a scene at a given image size: eye rays through every pixel
// centre, in the renderer's order and bundles (core/render/image_formation.h: tile by
// tile, kBundleSide x kBundleSide block by block), and the shadow and
// secondary (reflected and transmitted) queries the tracer makes for them at
// `maxDepth`, at most `cap` of each kind.
struct RaySet {
  std::vector<RayQuery> eye, shadow, secondary;
  // Bundle k is eye[eyeBundles[k] .. eyeBundles[k + 1]).
  std::vector<std::size_t> eyeBundles;
};
RaySet recordRays(const Scene& scene, const Accel& accel, int width, int height, int maxDepth,
                  std::size_t cap);

struct Throughput {
  double raysPerSecond = 0.0;
  bool sampled = false; // measured on a subset, to stay within the time budget
};

// Intersection only: closestHit (or anyHit) for each query, on `threads`
// threads. Measures all queries, or an evenly spread subset when the first few
// show that all would take longer than `budgetSeconds`.
Throughput measureQueries(const Accel& accel, const std::vector<RayQuery>& queries, bool anyHit,
                          int threads, double budgetSeconds);

// Intersection only, as the renderer finds eye rays' hits: Accel::closestHits
// of each bundle of eye rays.
Throughput measureEyeBundles(const Accel& accel, const RaySet& rays, int threads,
                             double budgetSeconds);

// With shading: Tracer::traceBundle of every bundle of eye rays at `maxDepth`,
// counting every ray traced (eye, shadow, reflected, transmitted).
Throughput measureShaded(const Scene& scene, const Accel& accel, const RaySet& rays, int maxDepth,
                         int threads, double budgetSeconds);

struct RenderTiming {
  double wallSeconds = 0.0;
  double cpuSeconds = 0.0; // process user + system
  RayCounts counts;
};
RenderTiming timeRender(const Scene& scene, const Accel& accel, const RenderSettings& settings);

// Seconds of CPU time of the calling thread.
double threadCpuSeconds();

} // namespace prism

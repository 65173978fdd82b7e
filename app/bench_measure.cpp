#include "bench_measure.h"

#include "core/render/image_formation.h"
#include "core/render/parallel.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "core/system/system_info.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <optional>
#include <span>

namespace prism {

namespace {

// Passes every query through to another Accel and keeps a copy of the shadow
// (anyHit) and secondary (closestHit after the eye ray's own) queries.
class RecordingAccel final : public Accel {
public:
  RecordingAccel(const Accel& inner, RaySet& rays, std::size_t cap)
      : inner_(inner), rays_(rays), cap_(cap) {}

  void nextIsEyeRay() { eyeRayNext_ = true; }

  bool closestHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
                  Hit& hit) const override {
    if (eyeRayNext_) {
      eyeRayNext_ = false;
    } else if (rays_.secondary.size() < cap_) {
      rays_.secondary.push_back(query(ray, range, skip));
    }
    return inner_.closestHit(ray, range, skip, hit);
  }
  bool anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
              PrimitiveRef* blocker = nullptr) const override {
    if (rays_.shadow.size() < cap_) rays_.shadow.push_back(query(ray, range, skip));
    return inner_.anyHit(ray, range, skip, blocker);
  }
  std::size_t memoryBytes() const override { return inner_.memoryBytes(); }

private:
  static RayQuery query(const Ray& ray, Interval range, const PrimitiveRef* skip) {
    RayQuery q{ray, range, {}, skip != nullptr};
    if (skip != nullptr) q.skip = *skip;
    return q;
  }

  const Accel& inner_;
  RaySet& rays_;
  std::size_t cap_;
  mutable bool eyeRayNext_ = false;
};

using Clock = std::chrono::steady_clock;

// Runs work(i, worker) -> rays traced over work items [0, n) with the given
// stride, on `threads` threads (worker 0 .. threads - 1), handing out
// `chunk` items at a time, and returns rays per second. A set that takes less
// than kMinSeconds (or the budget, if smaller) is run again until it has:
// figures of a few milliseconds move too much from run to run.
constexpr double kMinSeconds = 0.25;
constexpr int kMaxPasses = 64;
template <class Work>
Throughput run(std::size_t n, int threads, double budgetSeconds, const Work& work,
               std::size_t itemsPerChunk = 256) {
  Throughput result;
  if (n == 0) return result;
  // A probe of up to 64 queries spread over the set estimates the whole cost.
  const std::size_t probeStride = std::max<std::size_t>(1, n / 64);
  const double probeStart = threadCpuSeconds();
  std::size_t probed = 0;
  for (std::size_t i = 0; i < n; i += probeStride, ++probed)
    (void)work(i, 0);
  const double perQuery = (threadCpuSeconds() - probeStart) / double(probed);
  std::size_t stride = 1;
  if (perQuery * double(n) > budgetSeconds * double(threads)) {
    stride = std::size_t(std::ceil(perQuery * double(n) / (budgetSeconds * double(threads))));
    result.sampled = true;
  }
  const std::size_t count = (n + stride - 1) / stride;
  const std::size_t kChunk = itemsPerChunk;
  const int chunks = int((count + kChunk - 1) / kChunk);
  std::vector<std::uint64_t> rays(std::size_t(threads), 0);
  auto chunk = [&](int c, int worker) {
    const std::size_t end = std::min(count, (std::size_t(c) + 1) * kChunk);
    // Summed locally: the workers' totals share a cache line.
    std::uint64_t traced = 0;
    for (std::size_t k = std::size_t(c) * kChunk; k < end; ++k)
      traced += work(k * stride, worker);
    rays[std::size_t(worker)] += traced;
  };
  const double minSeconds = std::min(kMinSeconds, budgetSeconds);
  double seconds = 0.0;
  for (int pass = 0; pass < kMaxPasses && seconds < minSeconds; ++pass) {
    if (threads == 1) {
      const double start = threadCpuSeconds();
      for (int c = 0; c < chunks; ++c)
        chunk(c, 0);
      seconds += threadCpuSeconds() - start;
    } else {
      const auto start = Clock::now();
      parallelFor(chunks, threads, chunk);
      seconds += std::chrono::duration<double>(Clock::now() - start).count();
    }
  }
  std::uint64_t totalRays = 0;
  for (std::uint64_t r : rays)
    totalRays += r;
  result.raysPerSecond = seconds > 0.0 ? double(totalRays) / seconds : 0.0;
  return result;
}

// The eye rays side by side, so a bundle is a span of them.
std::vector<Ray> eyeRays(const RaySet& rays) {
  std::vector<Ray> out;
  out.reserve(rays.eye.size());
  for (const RayQuery& q : rays.eye)
    out.push_back(q.ray);
  return out;
}

std::span<const Ray> eyeBundle(const RaySet& rays, const std::vector<Ray>& eye, std::size_t k) {
  return std::span(eye).subspan(rays.eyeBundles[k], rays.eyeBundles[k + 1] - rays.eyeBundles[k]);
}

// Work items of 64 rays: a few per chunk, so two threads share the work evenly.
constexpr std::size_t kBundlesPerChunk = 4;

} // namespace

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

RaySet recordRays(const Scene& scene, const Accel& accel, int width, int height, int maxDepth,
                  std::size_t cap) {
  RaySet rays;
  RecordingAccel recorder(accel, rays, cap);
  const Camera camera(scene.camera, width, height);
  // Every shadow ray reaches the recorder: none is answered by the tracer's
  // blocker cache, so the shadow rays measured are all of them.
  Tracer tracer(scene, recorder, maxDepth, Tracer::BlockerCache::Off);
  RayCounts counts;
  rays.eye.reserve(std::size_t(width) * std::size_t(height));
  // In the order and the bundles the renderer traces them: tile by tile, block
  // by block of a tile, rows within a block.
  for (const Tile& tile : makeTiles(width, height, RenderSettings{}.tileSize)) {
    for (const Tile& block : splitTile(tile, kBundleSide)) {
      rays.eyeBundles.push_back(rays.eye.size());
      for (int y = block.y0; y < block.y1; ++y) {
        for (int x = block.x0; x < block.x1; ++x) {
          const Ray ray = camera.eyeRay(x + 0.5, y + 0.5);
          rays.eye.push_back({ray, Interval{}, {}, false});
          recorder.nextIsEyeRay();
          tracer.trace(ray, 1, counts);
        }
      }
    }
  }
  rays.eyeBundles.push_back(rays.eye.size());
  return rays;
}

Throughput measureQueries(const Accel& accel, const std::vector<RayQuery>& queries, bool anyHit,
                          int threads, double budgetSeconds) {
  return run(queries.size(), threads, budgetSeconds, [&](std::size_t i, int) {
    const RayQuery& q = queries[i];
    const PrimitiveRef* skip = q.hasSkip ? &q.skip : nullptr;
    Hit hit;
    if (anyHit)
      (void)accel.anyHit(q.ray, q.range, skip);
    else
      (void)accel.closestHit(q.ray, q.range, skip, hit);
    return std::uint64_t(1);
  });
}

Throughput measureEyeBundles(const Accel& accel, const RaySet& rays, int threads,
                             double budgetSeconds) {
  const std::vector<Ray> eye = eyeRays(rays);
  return run(
      rays.eyeBundles.size() - 1, threads, budgetSeconds,
      [&](std::size_t k, int) {
        const std::span<const Ray> bundle = eyeBundle(rays, eye, k);
        Hit hits[Accel::kMaxBundle];
        (void)accel.closestHits(bundle, std::span(hits, bundle.size()));
        return std::uint64_t(bundle.size());
      },
      kBundlesPerChunk);
}

Throughput measureShaded(const Scene& scene, const Accel& accel, const RaySet& rays, int maxDepth,
                         int threads, double budgetSeconds) {
  const std::vector<Ray> eye = eyeRays(rays);
  // One tracer per worker, made on its own thread, as the renderer makes them.
  std::vector<std::optional<Tracer>> tracers(static_cast<std::size_t>(threads));
  return run(
      rays.eyeBundles.size() - 1, threads, budgetSeconds,
      [&](std::size_t k, int worker) {
        std::optional<Tracer>& tracer = tracers[std::size_t(worker)];
        if (!tracer) tracer.emplace(scene, accel, maxDepth);
        const std::span<const Ray> bundle = eyeBundle(rays, eye, k);
        RayCounts counts;
        counts.eyePrimary += (long long)bundle.size();
        Color colors[Accel::kMaxBundle];
        tracer->traceBundle(bundle, std::span(colors, bundle.size()), counts);
        return std::uint64_t(counts.total());
      },
      kBundlesPerChunk);
}

RenderTiming timeRender(const Scene& scene, const Accel& accel, const RenderSettings& settings) {
  RenderTiming timing;
  const double cpuStart = processCpuSeconds();
  const auto start = Clock::now();
  const RenderResult result = render(scene, accel, settings);
  timing.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  timing.cpuSeconds = processCpuSeconds() - cpuStart;
  timing.counts = result.counts;
  return timing;
}

} // namespace prism

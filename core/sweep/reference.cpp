#include "core/sweep/reference.h"

#include "core/math/hash.h"
#include "core/render/exposure.h"
#include "core/render/image_formation.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "core/system/system_info.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>
#include <span>

namespace prism {

namespace {

// Keeps the reference's jitter apart from antialiasing's (image_formation.cpp),
// which hashes the same pixel keys.
constexpr std::uint64_t kReferenceSalt = 0x7265666572656e63ull; // "referenc"

// The centres of `pixels` traced at `depth`, into `centres`, in bundles of
// neighbouring pixels on every worker.
void traceCentres(const Scene& scene, const Accel& accel, const Camera& camera, int depth,
                  const std::vector<Pixel>& pixels, int width, Executor& executor,
                  std::vector<Rgb>& centres, std::vector<RayCounts>& counts) {
  constexpr int kChunk = int(Accel::kMaxBundle);
  const int chunks = (int(pixels.size()) + kChunk - 1) / kChunk;
  executor.forEach(chunks,
                   [&](int item, int worker) {
                     Tracer tracer(scene, accel, depth);
                     const std::size_t first = std::size_t(item) * kChunk;
                     const std::size_t n = std::min<std::size_t>(kChunk, pixels.size() - first);
                     std::vector<Sample> samples;
                     tracePixelCentres(tracer, camera, std::span(pixels.data() + first, n), samples,
                                       counts[std::size_t(worker)]);
                     for (const Sample& sample : samples)
                       centres[std::size_t(sample.y) * std::size_t(width) + std::size_t(sample.x)] =
                           sample.radiance;
                   },
                   {});
}

static_assert(kReferenceSide * kReferenceSide <= int(Accel::kMaxBundle));

} // namespace

void referenceSamplePoint(int x, int y, int i, int j, double& px, double& py) {
  const std::uint64_t pixelKey =
      (std::uint64_t(std::uint32_t(y)) << 32) | std::uint64_t(std::uint32_t(x));
  const std::uint64_t h =
      splitmix64(pixelKey ^ kReferenceSalt ^ splitmix64(std::uint64_t(j * kReferenceSide + i)));
  px = x + (i + unitFromBits(h)) / kReferenceSide;
  py = y + (j + unitFromBits(splitmix64(h))) / kReferenceSide;
}

ReferencePicture renderReference(const Scene& scene, const Accel& accel,
                                 const ReferenceSettings& settings, Executor& executor,
                                 const std::function<void(double)>& progress) {
  const double cpuStart = processCpuSeconds();
  const auto wallStart = std::chrono::steady_clock::now();
  const int width = settings.width, height = settings.height;
  const std::size_t pixelCount = std::size_t(width) * std::size_t(height);
  const Camera camera(scene.camera, width, height);
  std::vector<RayCounts> counts(std::size_t(executor.workers()));

  ReferencePicture reference;
  reference.width = width;
  reference.height = height;
  reference.centres.assign(pixelCount, Rgb(0.0f));
  std::vector<std::uint8_t> centreDepth(pixelCount, std::uint8_t(settings.firstDepth));

  // The depth search, centre by centre. `unsettled` holds the pixels whose
  // value a trace one step deeper may still change.
  std::vector<Pixel> unsettled;
  unsettled.reserve(pixelCount);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      unsettled.push_back({x, y});
  traceCentres(scene, accel, camera, settings.firstDepth, unsettled, width, executor,
               reference.centres, counts);
  std::vector<Rgb> deeper(pixelCount, Rgb(0.0f));
  for (int depth = settings.firstDepth + settings.depthStep;
       !unsettled.empty() && depth <= settings.lastDepth; depth += settings.depthStep) {
    if (progress) progress(0.1 * double(depth) / double(settings.lastDepth));
    traceCentres(scene, accel, camera, depth, unsettled, width, executor, deeper, counts);
    // Compared at one exposure, the one the deeper centres give: a change of
    // avgmax alone moves every pixel a little and is not a change of theirs.
    std::vector<Rgb> next = reference.centres;
    for (const Pixel& p : unsettled) {
      const std::size_t i = std::size_t(p.y) * std::size_t(width) + std::size_t(p.x);
      next[i] = deeper[i];
    }
    const float scale = exposureScale(averageMax(next));
    std::vector<Pixel> changed;
    for (const Pixel& p : unsettled) {
      const std::size_t i = std::size_t(p.y) * std::size_t(width) + std::size_t(p.x);
      for (int c = 0; c < 3; ++c) {
        if (exposeChannel(reference.centres[i][c], scale) != exposeChannel(next[i][c], scale)) {
          changed.push_back(p);
          break;
        }
      }
      centreDepth[i] = std::uint8_t(depth);
    }
    reference.centres = std::move(next);
    unsettled = std::move(changed);
  }
  reference.converged = unsettled.empty();
  reference.avgmax = averageMax(reference.centres);

  // Each pixel's samples go as deep as its own centre and its neighbours'
  // needed: an edge between two depths runs through the pixels on both sides.
  reference.depth.assign(pixelCount, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t d = 0;
      for (int ny = std::max(0, y - 1); ny <= std::min(height - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(width - 1, x + 1); ++nx)
          d = std::max(d, centreDepth[std::size_t(ny) * std::size_t(width) + std::size_t(nx)]);
      reference.depth[std::size_t(y) * std::size_t(width) + std::size_t(x)] = d;
      reference.deepest = std::max(reference.deepest, int(d));
    }
  }

  // Every pixel integrated at its depth.
  const std::vector<Tile> tiles = makeTiles(width, height, 16);
  reference.radiance.assign(pixelCount, Rgb(0.0f));
  int tilesDone = 0;
  std::mutex progressMutex;
  executor.forEach(int(tiles.size()),
                   [&](int item, int worker) {
                     const Tile& tile = tiles[std::size_t(item)];
                     std::optional<Tracer> tracer;
                     Ray rays[kReferenceSide * kReferenceSide];
                     Color colors[kReferenceSide * kReferenceSide];
                     for (int y = tile.y0; y < tile.y1; ++y) {
                       for (int x = tile.x0; x < tile.x1; ++x) {
                         const std::size_t index =
                             std::size_t(y) * std::size_t(width) + std::size_t(x);
                         if (!tracer || tracer->maxDepth() != reference.depth[index]) {
                           tracer.emplace(scene, accel, reference.depth[index]);
                           tracer->setEyeFootprint(camera.pixelSpread() / kReferenceSide);
                         }
                         for (int j = 0; j < kReferenceSide; ++j) {
                           for (int i = 0; i < kReferenceSide; ++i) {
                             double px = 0.0, py = 0.0;
                             referenceSamplePoint(x, y, i, j, px, py);
                             rays[j * kReferenceSide + i] = camera.eyeRay(px, py);
                           }
                         }
                         RayCounts& local = counts[std::size_t(worker)];
                         tracer->traceBundle(rays, colors, local);
                         local.eyeAntialias += kReferenceSide * kReferenceSide;
                         Color sum(0.0);
                         for (const Color& c : colors)
                           sum += c;
                         reference.radiance[index] =
                             toRgb(sum / double(kReferenceSide * kReferenceSide));
                       }
                     }
                     if (progress) {
                       std::lock_guard lock(progressMutex);
                       progress(0.1 + 0.9 * double(++tilesDone) / double(tiles.size()));
                     }
                   },
                   {});
  for (const RayCounts& c : counts)
    reference.counts += c;
  reference.cpuSeconds = processCpuSeconds() - cpuStart;
  reference.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return reference;
}

} // namespace prism

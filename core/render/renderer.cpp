#include "core/render/renderer.h"

#include "core/render/image_formation.h"
#include "core/render/parallel.h"

#include <mutex>

namespace prism {

RenderResult render(const Scene& scene, const Accel& accel, const RenderSettings& settings,
                    const ProgressCallback& progress) {
  const Camera camera(scene.camera, settings.width, settings.height);
  const std::vector<Tile> tiles = makeTiles(settings.width, settings.height, settings.tileSize);
  const int threads = resolveThreadCount(settings.threads);
  const int tileCount = int(tiles.size());

  RenderResult result;
  result.film = Film(settings.width, settings.height);
  std::vector<RayCounts> counts(static_cast<std::size_t>(threads));
  std::vector<long long> supersampled(tiles.size(), 0);

  std::mutex progressMutex;
  int tilesDone = 0;
  auto reportTile = [&](int pass) {
    if (!progress) return;
    std::lock_guard lock(progressMutex);
    ++tilesDone;
    // Pass 2 costs more per tile than pass 1, but both are shown as halves:
    // progress is for reassurance, not for estimating the end to the second.
    progress({pass, 0.5 * double(tilesDone) / double(tileCount) + (pass == 2 ? 0.5 : 0.0)});
  };

  // A Tracer per tile: it belongs to one thread (see core/render/tracer.h). A tile
  // counts its rays in counts of its own, added to its worker's at the end:
  // the workers' counts sit side by side in memory, and incrementing them ray
  // by ray from two cores would bounce their cache line between the cores.
  parallelFor(tileCount, threads, [&](int i, int worker) {
    Tracer tracer(scene, accel, settings.maxDepth);
    RayCounts tileCounts;
    tracePixelCentres(tracer, camera, tiles[std::size_t(i)], result.film, tileCounts);
    counts[std::size_t(worker)] += tileCounts;
    reportTile(1);
  });
  result.avgmax = averageMax(result.film.centre);

  tilesDone = 0;
  parallelFor(tileCount, threads, [&](int i, int worker) {
    Tracer tracer(scene, accel, settings.maxDepth);
    RayCounts tileCounts;
    supersampled[std::size_t(i)] =
        antialiasTile(tracer, camera, tiles[std::size_t(i)], result.avgmax, settings.thresh,
                      settings.jitter, result.film, tileCounts);
    counts[std::size_t(worker)] += tileCounts;
    reportTile(2);
  });

  for (const RayCounts& c : counts)
    result.counts += c;
  for (long long s : supersampled)
    result.supersampledPixels += s;
  return result;
}

} // namespace prism

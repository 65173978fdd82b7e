// The passes of image formation (docs/image-formation.md), each its own function so each can be tested and reused
// by the progressive previewer: pixel centres, avgmax, the supersampling
// decision, and the 4x4 supersampling itself. They work on tiles, the unit of
// parallel work.
#pragma once

#include "core/render/film.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"

#include <span>
#include <vector>

namespace prism {

struct Tile {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0; // pixels [x0, x1) x [y0, y1)
};

// Row-major tiles of at most `size` x `size` pixels covering the image.
std::vector<Tile> makeTiles(int width, int height, int size = 32);

// Row-major parts of at most `size` x `size` pixels covering `tile`.
std::vector<Tile> splitTile(const Tile& tile, int size);

// Eye rays through neighbouring pixels are traced as bundles
// (Tracer::traceBundle) of kBundleSide x kBundleSide pixels: 64 rays, the
// most a bundle holds; the tree is then walked once for all of them.
inline constexpr int kBundleSide = 8;

struct Pixel {
  int x = 0, y = 0;
};

// Pass 1 over a tile: one eye ray through each pixel centre (ix + 0.5, iy + 0.5),
// block by block of kBundleSide x kBundleSide pixels.
void tracePixelCentres(Tracer& tracer, const Camera& camera, const Tile& tile, Film& film,
                       RayCounts& counts);

// The eye rays through the centres of `pixels` (at most Accel::kMaxBundle) as
// one bundle, their colours into `out`, counted as pass-1 eye rays.
void tracePixelCentres(Tracer& tracer, const Camera& camera, std::span<const Pixel> pixels,
                       std::span<Color> out, RayCounts& counts);

// Mean over all pixels of max(r, g, b), summed in pixel order so the result is
// the same for any thread count.
double averageMax(const std::vector<Rgb>& radiance);

// Pass 2's decision: true when some 4-neighbour's pass-1 colour differs by more than
// avgmax * thresh in Euclidean RGB distance (strictly greater).
bool needsSupersampling(const Film& film, int x, int y, double avgmax, double thresh);

// The mean of 16 eye rays on a 4x4 grid of sub-pixel cells: cell centres, or a
// point jittered within each cell (deterministic per pixel and cell).
Rgb supersamplePixel(Tracer& tracer, const Camera& camera, int x, int y, bool jitter,
                     RayCounts& counts);

// Pass 2 over a tile: every pixel that needsSupersampling gets supersamplePixel;
// the others keep their centre sample. Returns the number supersampled.
int antialiasTile(Tracer& tracer, const Camera& camera, const Tile& tile, double avgmax,
                  double thresh, bool jitter, Film& film, RayCounts& counts);

} // namespace prism

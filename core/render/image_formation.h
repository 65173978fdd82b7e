// The steps of image formation (docs/image-formation.md), each its own function so each
// can be tested: pixel centres, avgmax, the supersampling decision, and the
// 4x4 supersampling itself, on blocks of a tile (the unit of parallel work).
// The order they run in is the pass schedule's (core/render/pass_schedule.h).
#pragma once

#include "core/math/exact_sum.h"
#include "core/render/film.h"
#include "core/render/tile.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"

#include <span>
#include <vector>

namespace prism {

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

// One sample of the final picture: a pixel's centre (pass 1) or the mean of
// its 16 sub-samples (pass 2). The passes hand out samples rather than write
// the film, so that whoever runs them decides when a sample is published.
struct Sample {
  int x = 0, y = 0;
  Rgb radiance{0.0f};
};

// Pass 1 for `pixels` (at most Accel::kMaxBundle, traced as one bundle): one
// eye ray through each pixel centre (x + 0.5, y + 0.5), counted as a pass-1
// eye ray, its sample appended to `out`.
void tracePixelCentres(Tracer& tracer, const Camera& camera, std::span<const Pixel> pixels,
                       std::vector<Sample>& out, RayCounts& counts);

// Mean over all pixels of max(r, g, b). The sum is exact (core/math/exact_sum.h),
// so the result is the same for any order and any split of the pixels between
// threads or processes: sumOfMaxima of each part, added, then averageMax.
ExactSum sumOfMaxima(std::span<const Rgb> radiance);
double averageMax(const ExactSum& sumOfMaxima, std::size_t pixelCount);
double averageMax(const std::vector<Rgb>& radiance);

// Pass 2's decision: true when some 4-neighbour's pass-1 colour differs by more than
// avgmax * thresh in Euclidean RGB distance (strictly greater).
bool needsSupersampling(const Film& film, int x, int y, double avgmax, double thresh);

// The mean of 16 eye rays on a 4x4 grid of sub-pixel cells: cell centres, or a
// point jittered within each cell (deterministic per pixel and cell).
Rgb supersamplePixel(Tracer& tracer, const Camera& camera, int x, int y, bool jitter,
                     RayCounts& counts);

// Pass 2's decisions for the pixels of `tile`, whose centres and the centres
// around it are pass 1's: marks[i] = needsSupersampling, 1 or 0, for each
// of its pixels (marks holds one byte per pixel of the film).
void markForSupersampling(const Tile& tile, const Film& film, double avgmax, double thresh,
                          std::vector<std::uint8_t>& marks);

// Pass 2 over `block` of `film`: the supersamplePixel of every pixel marked
// (markForSupersampling), appended to `out`. Needs no centres: whoever runs
// it may have no pass-1 samples near it (another MPI rank traced them).
void antialiasBlock(Tracer& tracer, const Camera& camera, const Tile& block, const Film& film,
                    const std::vector<std::uint8_t>& marks, bool jitter, std::vector<Sample>& out,
                    RayCounts& counts);

// Samples into the film. A pass-1 sample is the pixel's centre and its value
// in the picture; a pass-2 sample replaces the value and marks the pixel
// supersampled, and leaves the centre, which neighbours' decisions read.
void storeCentres(std::span<const Sample> samples, Film& film);
void storeSupersampled(std::span<const Sample> samples, Film& film);

} // namespace prism

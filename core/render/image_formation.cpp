#include "core/render/image_formation.h"

#include "core/math/hash.h"

#include <algorithm>

namespace prism {

namespace {

double distanceSquared(const Rgb& a, const Rgb& b) {
  const double dr = double(a.r) - double(b.r);
  const double dg = double(a.g) - double(b.g);
  const double db = double(a.b) - double(b.b);
  return dr * dr + dg * dg + db * db;
}

} // namespace

static_assert(kBundleSide * kBundleSide <= int(Accel::kMaxBundle));

std::vector<Tile> splitTile(const Tile& tile, int size) {
  std::vector<Tile> parts;
  for (int y = tile.y0; y < tile.y1; y += size)
    for (int x = tile.x0; x < tile.x1; x += size)
      parts.push_back({x, y, std::min(x + size, tile.x1), std::min(y + size, tile.y1)});
  return parts;
}

std::vector<Tile> makeTiles(int width, int height, int size) {
  return splitTile({0, 0, width, height}, size);
}

void tracePixelCentres(Tracer& tracer, const Camera& camera, std::span<const Pixel> pixels,
                       std::vector<Sample>& out, RayCounts& counts) {
  Ray rays[Accel::kMaxBundle];
  for (std::size_t i = 0; i < pixels.size(); ++i)
    rays[i] = camera.eyeRay(pixels[i].x + 0.5, pixels[i].y + 0.5);
  counts.eyePrimary += (long long)pixels.size();
  tracer.setEyeFootprint(camera.pixelSpread());
  Color colors[Accel::kMaxBundle];
  tracer.traceBundle(std::span(rays, pixels.size()), std::span(colors, pixels.size()), counts);
  for (std::size_t i = 0; i < pixels.size(); ++i)
    out.push_back({pixels[i].x, pixels[i].y, toRgb(colors[i])});
}

ExactSum sumOfMaxima(std::span<const Rgb> radiance) {
  ExactSum sum;
  for (const Rgb& c : radiance)
    sum.add(std::max({c.r, c.g, c.b}));
  return sum;
}

double averageMax(const ExactSum& sumOfMaxima, std::size_t pixelCount) {
  return pixelCount == 0 ? 0.0 : sumOfMaxima.value() / double(pixelCount);
}

double averageMax(const std::vector<Rgb>& radiance) {
  return averageMax(sumOfMaxima(radiance), radiance.size());
}

bool needsSupersampling(const Film& film, int x, int y, double avgmax, double thresh) {
  const double limit = avgmax * thresh;
  const double limit2 = limit * limit;
  const Rgb& c = film.centre[film.index(x, y)];
  auto differs = [&](int nx, int ny) {
    return distanceSquared(c, film.centre[film.index(nx, ny)]) > limit2;
  };
  return (x > 0 && differs(x - 1, y)) || (x + 1 < film.width && differs(x + 1, y)) ||
         (y > 0 && differs(x, y - 1)) || (y + 1 < film.height && differs(x, y + 1));
}

Rgb supersamplePixel(Tracer& tracer, const Camera& camera, int x, int y, bool jitter,
                     RayCounts& counts) {
  const std::uint64_t pixelKey =
      (std::uint64_t(std::uint32_t(y)) << 32) | std::uint64_t(std::uint32_t(x));
  Ray rays[16];
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      double u = 0.5, v = 0.5;
      if (jitter) {
        // A hash of (pixel, cell), so each has its own fixed jitter whatever
        // the order in which pixels are traced.
        const std::uint64_t h = splitmix64(pixelKey ^ splitmix64(std::uint64_t(j * 4 + i)));
        u = unitFromBits(h);
        v = unitFromBits(splitmix64(h));
      }
      rays[j * 4 + i] = camera.eyeRay(x + (i + u) / 4.0, y + (j + v) / 4.0);
    }
  }
  // The 16 rays share the eye: one bundle. Each samples a sixteenth of the
  // pixel, so its footprint is a quarter of the pixel's side.
  tracer.setEyeFootprint(camera.pixelSpread() / 4.0);
  Color colors[16];
  tracer.traceBundle(rays, colors, counts);
  counts.eyeAntialias += 16;
  Color sum(0.0);
  for (const Color& c : colors)
    sum += c;
  return toRgb(sum / 16.0);
}

void markForSupersampling(const Tile& tile, const Film& film, double avgmax, double thresh,
                          std::vector<std::uint8_t>& marks) {
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x)
      marks[film.index(x, y)] = needsSupersampling(film, x, y, avgmax, thresh) ? 1 : 0;
}

void antialiasBlock(Tracer& tracer, const Camera& camera, const Tile& block, const Film& film,
                    const std::vector<std::uint8_t>& marks, bool jitter, std::vector<Sample>& out,
                    RayCounts& counts) {
  for (int y = block.y0; y < block.y1; ++y)
    for (int x = block.x0; x < block.x1; ++x)
      if (marks[film.index(x, y)] != 0)
        out.push_back({x, y, supersamplePixel(tracer, camera, x, y, jitter, counts)});
}

void storeCentres(std::span<const Sample> samples, Film& film) {
  for (const Sample& sample : samples) {
    const std::size_t i = film.index(sample.x, sample.y);
    film.centre[i] = film.radiance[i] = sample.radiance;
  }
}

void storeSupersampled(std::span<const Sample> samples, Film& film) {
  for (const Sample& sample : samples) {
    const std::size_t i = film.index(sample.x, sample.y);
    film.radiance[i] = sample.radiance;
    film.supersampled[i] = 1;
  }
}

} // namespace prism

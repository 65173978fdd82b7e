#include "core/render/work_estimate.h"

#include "core/render/bailout.h"
#include "core/render/image_formation.h"
#include "core/render/parallel.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "core/scene/material_blend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <span>
#include <vector>

namespace prism {

namespace {

// The grid's side at most: 256 pixel centres, a few per tile of a 640 x 480 image.
constexpr int kSampleSide = 16;

// The first depth traced: levels 5..8 give two steps of the rays gained per
// level by depth 8.
constexpr int kFirstDepth = kEstimateFromDepth - 3;

// The share of the rays of the render it foresees the estimate may trace
// beyond kEstimateRayBudget (up to kEstimateRayCap).
constexpr double kEstimateShare = 0.01;

// CPU time of the calling thread: the estimate runs on one, and the other
// threads of the process (a previewer's, a test's) must not count.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

// The pixels of a regular grid of at most kSampleSide x kSampleSide, each at
// the centre of its cell of the image.
std::vector<Pixel> samplePixels(int width, int height) {
  const int nx = std::min(kSampleSide, width), ny = std::min(kSampleSide, height);
  std::vector<Pixel> pixels;
  pixels.reserve(std::size_t(nx) * std::size_t(ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      pixels.push_back({int((i + 0.5) * width / nx), int((j + 0.5) * height / ny)});
  return pixels;
}

// Pass 1 of the sampled pixels at `depth`; returns the rays traced and their
// samples' avgmax.
std::pair<double, double> traceSample(const Scene& scene, const Accel& accel, const Camera& camera,
                                      std::span<const Pixel> pixels, int depth,
                                      const BailoutBound& bound) {
  Tracer tracer(scene, accel, depth);
  tracer.setBailout(bound);
  RayCounts counts;
  std::vector<Sample> samples;
  for (std::size_t at = 0; at < pixels.size(); at += Accel::kMaxBundle)
    tracePixelCentres(tracer, camera,
                      pixels.subspan(at, std::min(Accel::kMaxBundle, pixels.size() - at)), samples,
                      counts);
  std::vector<Rgb> radiance;
  radiance.reserve(samples.size());
  for (const Sample& s : samples)
    radiance.push_back(s.radiance);
  return {double(counts.total()), averageMax(radiance)};
}

// With a bailout, the depth past which it traces no ray at all, or `maxDepth`:
// a ray of depth j + 1 is traced only where beyond[j + 1] times the product
// of (ksr + kst) over the j hits above it exceeds the eye ray's allowance
// (Tracer::traceOrSkip), and that product is at most c^j, c the largest
// (ksr + kst) of the scene. With c < 1 that ends the tree.
int bailoutDepthLimit(const Scene& scene, const BailoutBound& bound, int maxDepth) {
  if (!bound.active()) return maxDepth;
  double c = 0.0;
  for (const Material& m : scene.materials) // over a texture's blends too
    c = std::max(c, coefficientCeiling(m).ksr + coefficientCeiling(m).kst);
  double product = 1.0; // c^j
  for (int j = 1; j < maxDepth; ++j) {
    product *= c;
    if (bound.beyond[std::size_t(j) + 1] * product <= bound.allowance) return j;
  }
  return maxDepth;
}

// "3e58", "120", "more than 1e308".
std::string roughCount(double x) {
  if (!std::isfinite(x)) return "more than 1e308";
  char buffer[32];
  if (x < 1e6) {
    std::snprintf(buffer, sizeof buffer, "%.0f", x);
    return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.0e", x); // "3e+58"
  std::string text = buffer;
  const std::size_t e = text.find("e+");
  if (e != std::string::npos) {
    std::size_t digits = e + 2;
    while (digits + 1 < text.size() && text[digits] == '0')
      ++digits;
    text = text.substr(0, e + 1) + text.substr(digits);
  }
  return text;
}

} // namespace

bool WorkEstimate::sameCounts(const WorkEstimate& o) const {
  return made == o.made && sampledPixels == o.sampledPixels && measuredDepth == o.measuredDepth &&
         raysPerPixel == o.raysPerPixel && growth == o.growth &&
         estimatedRaysPerPixel == o.estimatedRaysPerPixel && sampleRays == o.sampleRays;
}

double extrapolateRays(double raysPerPixel, double gained, double growth, int depth, int maxDepth) {
  const int levels = maxDepth - depth;
  if (levels <= 0 || gained <= 0.0 || growth <= 0.0) return raysPerPixel;
  // g + g^2 + ... + g^n = g (g^n - 1) / (g - 1), with expm1 so that a g near
  // 1 keeps its digits; it overflows to +infinity, never to NaN.
  const double series =
      growth == 1.0 ? double(levels)
                    : growth * std::expm1(double(levels) * std::log(growth)) / (growth - 1.0);
  const double rays = raysPerPixel + gained * series;
  return std::isfinite(rays) ? rays : std::numeric_limits<double>::infinity();
}

WorkEstimate estimateWork(const Scene& scene, const Accel& accel, const RenderSettings& settings) {
  WorkEstimate estimate;
  if (settings.maxDepth <= kEstimateFromDepth) return estimate;
  estimate.made = true;

  const double cpuStart = threadCpuSeconds();
  const Camera camera(scene.camera, settings.width, settings.height);
  const double pixelsInImage = double(settings.width) * double(settings.height);
  const std::vector<Pixel> pixels = samplePixels(settings.width, settings.height);
  const double n = double(pixels.size());
  estimate.sampledPixels = int(pixels.size());

  // The render's bailout, with an allowance from the sample's depth-1 avgmax
  // in place of the whole image's (PassSchedule's pilot). Its decisions
  // depend only on the path to a ray, so a trace at depth k is the render's
  // tree cut at depth k, exactly as without one.
  BailoutBound bound;
  if (settings.bailout > 0.0) {
    bound.beyond = radianceBounds(scene, settings.maxDepth);
    if (bailoutCanSkip(scene, bound.beyond, settings.bailout)) {
      const auto [rays, avgmax] = traceSample(scene, accel, camera, pixels, 1, BailoutBound{});
      estimate.sampleRays += rays;
      bound.allowance = bailoutAllowance(settings.bailout, avgmax);
    } else {
      bound.beyond.clear();
    }
  }

  // The deepest level the render can reach: with a bailout possibly less.
  const int reach = bailoutDepthLimit(scene, bound, settings.maxDepth);

  // perPixel[i]: R(kFirstDepth + i), the rays per sampled pixel at that depth.
  std::vector<double> perPixel;
  // The growth at the last level: what it added over what the level two
  // before added, square-rooted (0 once a level adds nothing).
  auto growthAt = [&](std::size_t last) {
    const double gained = perPixel[last] - perPixel[last - 1];
    const double before = perPixel[last - 2] - perPixel[last - 3];
    return gained > 0.0 && before > 0.0 ? std::sqrt(gained / before) : 0.0;
  };
  int depth = kFirstDepth;
  for (;; ++depth) {
    const double rays = traceSample(scene, accel, camera, pixels, depth, bound).first;
    estimate.sampleRays += rays;
    perPixel.push_back(rays / n);
    if (depth < kEstimateFromDepth) continue;
    const std::size_t last = perPixel.size() - 1;
    const double gained = perPixel[last] - perPixel[last - 1];
    if (depth >= reach || gained == 0.0) break; // exact from here
    // The next level adds at most twice what this one did (two new rays per
    // hit at most): never past the cap.
    if (estimate.sampleRays + n * (perPixel[last] + 2.0 * gained) > kEstimateRayCap) break;
    // Past the budget only while the tree grows, and while the estimate
    // costs at most 1% of the render it foresees: a tree whose branching part
    // is still small beside its chains (glass between mirrors: 1.05 per
    // level at depth 15, 1.09 from depth 25 on) shows its rate late.
    const double growth = growthAt(last);
    const double foreseen =
        growth > 1.0 ? extrapolateRays(perPixel[last], gained, growth, depth, reach) * pixelsInImage
                     : 0.0;
    if (estimate.sampleRays > std::max(kEstimateRayBudget, kEstimateShare * foreseen)) break;
  }
  const double seconds = threadCpuSeconds() - cpuStart;

  const std::size_t last = perPixel.size() - 1;
  estimate.measuredDepth = depth;
  estimate.raysPerPixel = perPixel[last];
  estimate.growth = growthAt(last);
  estimate.estimatedRaysPerPixel = extrapolateRays(
      estimate.raysPerPixel, perPixel[last] - perPixel[last - 1], estimate.growth, depth, reach);
  estimate.raysPerCpuSecond = seconds > 0.0 ? estimate.sampleRays / seconds : 0.0;

  const double threads = double(resolveThreadCount(settings.threads));
  if (!std::isfinite(estimate.estimatedRaysPerPixel))
    estimate.estimatedSeconds = std::numeric_limits<double>::infinity();
  else if (estimate.raysPerCpuSecond > 0.0)
    estimate.estimatedSeconds =
        estimate.estimatedRaysPerPixel * pixelsInImage / (estimate.raysPerCpuSecond * threads);
  estimate.explodes = estimate.estimatedSeconds > kExplodingSeconds;
  return estimate;
}

std::string roughDuration(double seconds) {
  if (!std::isfinite(seconds)) return "forever, in practice";
  struct Unit {
    const char* name;
    double seconds;
  };
  static constexpr Unit kUnits[] = {
      {"years", 365.25 * 86400.0}, {"days", 86400.0}, {"hours", 3600.0}, {"minutes", 60.0}};
  for (const Unit& unit : kUnits) {
    if (seconds >= 2.0 * unit.seconds || &unit == &kUnits[std::size(kUnits) - 1]) {
      const double amount = seconds / unit.seconds;
      char buffer[48];
      if (amount < 100.0) {
        std::snprintf(buffer, sizeof buffer, "%.2g %s", amount, unit.name);
        return buffer;
      }
      return roughCount(amount) + " " + unit.name;
    }
  }
  return ""; // not reached
}

std::string workWarning(const WorkEstimate& estimate, const RenderSettings& settings) {
  char growth[32];
  std::snprintf(growth, sizeof growth, "%.3g", estimate.growth);
  const int threads = resolveThreadCount(settings.threads);
  std::string text = "depth " + std::to_string(settings.maxDepth) + ": ";
  if (estimate.growth > 1.0)
    text += "the ray tree grows " + std::string(growth) + "x per level from depth " +
            std::to_string(estimate.measuredDepth) + "; ";
  text += "pass 1 alone may need about " + roughCount(estimate.estimatedRaysPerPixel) +
          " rays per pixel (" + roughDuration(estimate.estimatedSeconds) + " on " +
          std::to_string(threads) + (threads == 1 ? " thread" : " threads") + "); ";
  text += settings.bailout > 0.0 ? "a lower --depth bounds it"
                                 : "--bailout 0.5 or a lower --depth bounds it";
  return text;
}

} // namespace prism

#include "bench/embree/ray_sets.h"

#include "core/math/hash.h"
#include "core/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace prism::bench {

namespace {

// Secondary rays start this far off the surface, relative to the size of the
// coordinates (as Prism's own offset, core/render/tracer.cpp, but 2^27 times
// larger): Prism's offset of a few hundred double ulps would vanish when the
// origin is rounded to float, and Embree would find the surface the ray
// leaves. 2^-17 is 128 float ulps of the largest coordinate. Neither engine
// skips the primitive a ray leaves (Embree cannot without a filter callback).
constexpr double kFloatRayOffset = 0x1p-17;

Vec3 toFloatPrecision(const Vec3& v) {
  return {double(float(v.x)), double(float(v.y)), double(float(v.z))};
}

// The ray as Embree will see it: origin and direction rounded to float (the
// direction is then unit only to a float's precision, which Prism's tests
// allow: t stays a distance to 1e-7).
Ray floatRay(const Vec3& origin, const Vec3& dir) {
  return {toFloatPrecision(origin), toFloatPrecision(dir)};
}

std::vector<std::size_t> chosenPixels(std::size_t pixels, const RaySetOptions& o) {
  std::vector<std::size_t> chosen(pixels);
  std::iota(chosen.begin(), chosen.end(), std::size_t(0));
  if (o.maxEyeRays == 0 || o.maxEyeRays >= pixels) return chosen;
  // A partial Fisher-Yates shuffle picks the sample; sorting restores scanline order.
  SplitMix64 random(o.seed);
  for (std::size_t i = 0; i < o.maxEyeRays; ++i) {
    const std::size_t j = i + std::size_t(random.next() % (pixels - i));
    std::swap(chosen[i], chosen[j]);
  }
  chosen.resize(o.maxEyeRays);
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

Vec3 reflect(const Vec3& d, const Vec3& n) { return glm::normalize(d - 2.0 * glm::dot(d, n) * n); }

// The rays leaving one eye ray's hit, made as the tracer makes its own
// (which side the ray meets, where new rays start, which lights face the
// surface) but without its material rules: every hit reflects.
void addSecondaryRays(const Scene& scene, const Ray& eye, const Hit& hit, RaySets& sets) {
  const Vec3 point = eye.at(hit.t);
  const SurfacePoint surface = scene.surfaceAt(hit.primitive, point);
  const bool leaving = glm::dot(surface.outward, eye.dir) > 0.0;
  const Vec3 g = leaving ? -surface.outward : surface.outward;
  const Vec3 turned = leaving ? -surface.shading : surface.shading;
  const Vec3 n = glm::dot(turned, g) > 0.0 ? turned : g;
  const Vec3 start = !leaving && surface.outwardStart ? *surface.outwardStart : point;
  const double offset = kFloatRayOffset * (maxAbsComponent(start) + maxAbsComponent(eye.origin) +
                                           surface.roundoffScale);
  const Vec3 above = start + offset * g;

  const Vec3 nr = glm::dot(eye.dir, n) < 0.0 ? n : g;
  sets.secondary.push_back({floatRay(above, reflect(eye.dir, nr)), Interval{}});

  for (const Light& light : scene.lights) {
    const Vec3 toLight = light.position - point;
    if (!(glm::dot(n, toLight) > 0.0)) continue; // behind the surface: the tracer casts none
    const Ray ray = floatRay(above, glm::normalize(light.position - above));
    // The light's distance from the rounded origin, rounded down to a float,
    // so that Embree's float range ends no further than Prism's.
    const double length = glm::length(light.position - ray.origin);
    float end = float(length);
    if (double(end) > length) end = std::nextafter(end, 0.0f);
    if (end > 0.0f) sets.shadow.push_back({ray, Interval{0.0, double(end)}});
  }
}

} // namespace

RaySets makeRaySets(const Scene& scene, const Accel& accel, const RaySetOptions& o) {
  const Camera camera(scene.camera, o.width, o.height);
  RaySets sets;
  const std::size_t width = std::size_t(o.width);
  for (std::size_t pixel : chosenPixels(width * std::size_t(o.height), o)) {
    const Ray centre = camera.eyeRay(double(pixel % width) + 0.5, double(pixel / width) + 0.5);
    sets.eye.push_back({floatRay(centre.origin, centre.dir), Interval{}});
  }
  for (const Query& eye : sets.eye) {
    Hit hit;
    if (accel.closestHit(eye.ray, eye.range, nullptr, hit))
      addSecondaryRays(scene, eye.ray, hit, sets);
  }
  return sets;
}

} // namespace prism::bench

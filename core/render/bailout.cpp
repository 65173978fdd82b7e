#include "core/render/bailout.h"

#include "core/scene/material_blend.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

namespace {

// Distance from p to the box (0 inside it).
double distanceToBox(const Vec3& p, const Aabb& box) {
  const Vec3 outside = glm::max(glm::max(box.lo - p, p - box.hi), Vec3(0.0));
  return glm::length(outside);
}

double largestChannel(const Color& c) { return std::max({c.r, c.g, c.b}); }

} // namespace

std::vector<double> lightClearances(const Scene& scene) {
  std::vector<double> clearance(scene.lights.size(), std::numeric_limits<double>::infinity());
  for (const PrimitiveRef ref : scene.allPrimitives()) {
    const Aabb box = scene.bounds(ref);
    for (std::size_t j = 0; j < scene.lights.size(); ++j)
      clearance[j] = std::min(clearance[j], distanceToBox(scene.lights[j].position, box));
  }
  // A hit point is computed, not exact: it may stray outside its primitive's
  // box by round-off (relative 1e-15 of its coordinates). A millionth of the
  // clearance, taken off, is far more than that.
  for (double& d : clearance)
    d *= 1.0 - 1e-6;
  return clearance;
}

std::vector<double> radianceBounds(const Scene& scene, int maxDepth) {
  const std::vector<double> clearance = lightClearances(scene);
  Color s(0.0); // sum_j E_j / d_j^2: no light is brighter than this at any hit
  for (std::size_t j = 0; j < scene.lights.size(); ++j)
    s += scene.lights[j].intensity / (clearance[j] * clearance[j]); // inf when d_j = 0
  std::vector<double> beyond(std::size_t(maxDepth) + 1, 0.0);
  if (!std::isfinite(largestChannel(s))) { // no bound: a light on a box
    std::fill(beyond.begin() + 1, beyond.end(), std::numeric_limits<double>::infinity());
    return beyond;
  }
  Color next(0.0); // the bound one depth further; none beyond maxDepth
  for (int k = maxDepth; k >= 1; --k) {
    Color bound = scene.background;
    for (const Material& material : scene.materials) {
      // Every coefficient at its largest over a texture's blends: the bound
      // grows with each of them.
      const Material m = coefficientCeiling(material);
      const Color local = m.color * m.kdr * (scene.ambient + s) + m.ksr * s;
      const double carried = m.ksr + m.kst; // both new rays' coefficients
      const Color deeper = k < maxDepth && carried > 0.0 ? carried * next : Color(0.0);
      bound = glm::max(bound, local + deeper);
    }
    // Fog mixes what a ray brings back with its colour (weights summing to
    // 1), absorption only takes away: the fog colour bounds it too.
    if (scene.fog.active()) bound = glm::max(bound, scene.fog.color);
    next = bound;
    // Slightly raised, so that the tracer's rounded comparison can never
    // skip a ray the exact bound would keep.
    beyond[std::size_t(k)] = largestChannel(bound) * (1.0 + 1e-9);
  }
  return beyond;
}

bool bailoutCanSkip(const Scene& scene, const std::vector<double>& beyond, double levels) {
  double smallest = std::numeric_limits<double>::infinity(); // of (ksr + kst) > 0
  // A texture's blends reach down to its smaller end, and approach 0 when
  // one end carries nothing (smallest 0: a blend can always be skipped).
  for (const Material& m : scene.materials) {
    const Material ceiling = coefficientCeiling(m), floor = coefficientFloor(m);
    if (ceiling.ksr + ceiling.kst > 0.0) smallest = std::min(smallest, floor.ksr + floor.kst);
  }
  if (std::isinf(smallest)) return false; // no material starts a new ray
  const int maxDepth = int(beyond.size()) - 1;
  const double largest = levels * beyond[1] / 128.0; // the eye ray's allowance at most
  // Hits at depths 1..k lie above a ray of depth k + 1: its allowance is at
  // most largest / smallest^(k - 1), and its test multiplies by a
  // (ksr + kst) of at least `smallest`.
  double shares = smallest; // smallest^k
  for (int k = 1; k < maxDepth; ++k, shares *= smallest)
    if (beyond[std::size_t(k) + 1] * shares <= largest) return true;
  return false;
}

} // namespace prism

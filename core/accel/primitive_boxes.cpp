#include "core/accel/primitive_boxes.h"

#include <algorithm>
#include <numeric>

namespace prism {

namespace {

// The summed half-area of the boxes of n slices of equal height.
double slicedArea(const Cone& cone, int n) {
  double area = 0.0;
  for (int i = 0; i < n; ++i)
    area += sliceBounds(cone, double(i) / n, double(i + 1) / n).halfArea();
  return area;
}

} // namespace

int coneSliceCount(const Cone& cone) {
  // A doubling that saves less than 30% of the area adds references
  // (and duplicate tests where a ray crosses two slices) for little.
  constexpr double kWorthwhile = 0.7;
  int n = 1;
  double area = cone.bounds.halfArea();
  while (n < kMaxConeSlices) {
    const double finer = slicedArea(cone, 2 * n);
    if (!(finer <= kWorthwhile * area)) break;
    n *= 2;
    area = finer;
  }
  return n;
}

std::vector<BoxedPrimitive> hierarchyBoxes(const Scene& scene, std::size_t extraBudget) {
  const std::vector<PrimitiveRef> prims = scene.allPrimitives();
  const std::vector<Cone>& cones = scene.shapes<Cone>();

  // The slices each cone would like, then granted most profitable first
  // (by the area saved; ties in index order, so the result is deterministic).
  std::vector<int> slices(cones.size(), 1);
  std::vector<double> saved(cones.size(), 0.0);
  for (std::size_t i = 0; i < cones.size(); ++i) {
    slices[i] = coneSliceCount(cones[i]);
    if (slices[i] > 1) saved[i] = cones[i].bounds.halfArea() - slicedArea(cones[i], slices[i]);
  }
  std::vector<std::size_t> byGain(cones.size());
  std::iota(byGain.begin(), byGain.end(), 0);
  std::stable_sort(byGain.begin(), byGain.end(),
                   [&](std::size_t a, std::size_t b) { return saved[a] > saved[b]; });
  for (const std::size_t i : byGain) {
    // Halve what does not fit: the slices stay of equal height.
    while (std::size_t(slices[i] - 1) > extraBudget)
      slices[i] /= 2;
    extraBudget -= std::size_t(slices[i] - 1);
  }

  std::vector<BoxedPrimitive> boxes;
  boxes.reserve(prims.size());
  for (const PrimitiveRef& p : prims) {
    if (p.kind == kindOf<Cone> && slices[p.index] > 1) {
      const Cone& cone = cones[p.index];
      const int n = slices[p.index];
      for (int i = 0; i < n; ++i)
        boxes.push_back({p, sliceBounds(cone, double(i) / n, double(i + 1) / n)});
    } else {
      boxes.push_back({p, scene.bounds(p)});
    }
  }
  return boxes;
}

} // namespace prism

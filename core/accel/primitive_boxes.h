// The boxes a hierarchy is built over: one per primitive, except that a long
// thin cone lying across the axes (a jack's bar, a branch) is bounded slice by
// slice. Its one box would be mostly empty, and every ray through the empty
// part would run the cone's test for nothing; a few slices' boxes hug it.
// Each slice refers to the whole primitive, so a leaf tests the cone as
// usual and the answers stay those of brute force: only how often a missing
// ray reaches the test changes.
#pragma once

#include "core/scene/scene.h"

#include <vector>

namespace prism {

struct BoxedPrimitive {
  PrimitiveRef primitive;
  Aabb box;
};

// Every primitive of the scene, in allPrimitives() order, each followed by
// any further slices of it. At most `extraBudget` extra entries in all (the
// cones that gain most are sliced first), so memory stays bounded.
std::vector<BoxedPrimitive> hierarchyBoxes(const Scene& scene, std::size_t extraBudget);

// How many slices of equal height the cone is bounded by (1: its own box):
// the count is doubled, up to kMaxConeSlices, while each doubling cuts the
// summed area of the boxes by at least 30%.
int coneSliceCount(const Cone& cone);
inline constexpr int kMaxConeSlices = 4;

} // namespace prism

// A binary bounding-volume hierarchy over boxes, built top-down with the surface
// area heuristic evaluated on bins of the centroids (Wald 2007): O(n log n), no
// sorting. The result is an intermediate tree; core/accel/bvh.cpp collapses it into
// the wide nodes that rays traverse.
#pragma once

#include "core/math/aabb.h"

#include <cstdint>
#include <vector>

namespace prism {

struct SahOptions {
  int bins = 32;             // candidate split planes per axis are the bins' borders
  std::uint32_t maxLeaf = 8; // a range larger than this is always split
  // Expected cost of testing one primitive, relative to visiting one node. The
  // wide nodes tested here cost about as much as one of our primitives;
  // measured on the shipped scenes and the benchmark's generated ones (with
  // 4-wide nodes), 0.8 traded a third of the memory for no loss of speed
  // against 1.5.
  double intersectCost = 0.8;
  // Past this depth ranges are split at the object median, so pathological
  // inputs (exponentially spaced primitives) cannot make the tree deep.
  int maxSahDepth = 48;
  // Primitives a leaf tests packetSize at a time (buildSahTree's `packed`)
  // cost packetCost times intersectCost a packet begun, not each: a leaf of
  // 4 triangles costs no more than one of 1, and splits that leave a few
  // over are not worth their nodes. 1: every primitive costs alone.
  std::uint32_t packetSize = 1;
  double packetCost = 1.0;
};

struct SahTree {
  // A leaf has count > 0 and owns order[first, first + count); an interior node
  // has count == 0 and children left and right.
  struct Node {
    Aabb box;
    std::uint32_t left = 0, right = 0;
    std::uint32_t first = 0, count = 0;
    bool leaf() const { return count > 0; }
  };
  std::vector<Node> nodes;          // nodes[0] is the root (when there is any box)
  std::vector<std::uint32_t> order; // indices of the input boxes in leaf order
  int depth = 0;                    // of the deepest leaf; the root is depth 1
};

// `boxes` must be non-empty boxes with finite or infinite (never NaN) bounds.
// `packed`, empty or one flag a box: which boxes' primitives are tested in
// packets (SahOptions::packetSize).
SahTree buildSahTree(const std::vector<Aabb>& boxes, const SahOptions& options = {},
                     const std::vector<bool>& packed = {});

} // namespace prism

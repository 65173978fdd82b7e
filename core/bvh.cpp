#include "core/bvh.h"

#include "core/sah_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prism {

namespace {

// Four double lanes, one per child box. With SSE2 (every x86-64) they are two
// register pairs written out, because GCC lowers 32-byte vector extensions
// poorly without AVX; elsewhere, GCC/Clang vector extensions.
#if defined(__SSE2__)
struct Lanes {
  __m128d lo, hi;
};
inline Lanes broadcast(double x) { return {_mm_set1_pd(x), _mm_set1_pd(x)}; }
inline Lanes loadBounds(const float* p) {
  const __m128 f = _mm_loadu_ps(p);
  return {_mm_cvtps_pd(f), _mm_cvtps_pd(_mm_movehl_ps(f, f))};
}
inline Lanes operator-(Lanes a, Lanes b) {
  return {_mm_sub_pd(a.lo, b.lo), _mm_sub_pd(a.hi, b.hi)};
}
inline Lanes operator*(Lanes a, Lanes b) {
  return {_mm_mul_pd(a.lo, b.lo), _mm_mul_pd(a.hi, b.hi)};
}
// a > b ? a : b and a < b ? a : b lane by lane: b wherever either is a NaN.
inline Lanes maxOr(Lanes a, Lanes b) { return {_mm_max_pd(a.lo, b.lo), _mm_max_pd(a.hi, b.hi)}; }
inline Lanes minOr(Lanes a, Lanes b) { return {_mm_min_pd(a.lo, b.lo), _mm_min_pd(a.hi, b.hi)}; }
// Bit i set where lane i of a <= b.
inline unsigned lessEqualMask(Lanes a, Lanes b) {
  return unsigned(_mm_movemask_pd(_mm_cmple_pd(a.lo, b.lo))) |
         unsigned(_mm_movemask_pd(_mm_cmple_pd(a.hi, b.hi))) << 2;
}
inline void store(double* out, Lanes a) {
  _mm_storeu_pd(out, a.lo);
  _mm_storeu_pd(out + 2, a.hi);
}
#else
// Internal and inlined, so GCC's note that such values are passed differently
// with AVX is moot.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
using Lanes = double __attribute__((vector_size(32)));
using LanesF = float __attribute__((vector_size(16)));
inline Lanes broadcast(double x) { return Lanes{x, x, x, x}; }
inline Lanes loadBounds(const float* p) {
  LanesF f;
  std::memcpy(&f, p, sizeof f);
  return __builtin_convertvector(f, Lanes);
}
inline Lanes maxOr(Lanes a, Lanes b) { return a > b ? a : b; }
inline Lanes minOr(Lanes a, Lanes b) { return a < b ? a : b; }
inline unsigned lessEqualMask(Lanes a, Lanes b) {
  const auto m = a <= b;
  unsigned mask = 0;
  for (int i = 0; i < 4; ++i)
    mask |= unsigned(m[i] != 0) << i;
  return mask;
}
inline void store(double* out, Lanes a) { std::memcpy(out, &a, sizeof a); }
#endif

constexpr std::uint32_t kKindShift = 29; // 3 bits of PrimitiveKind, 29 of index
constexpr std::uint32_t kIndexMask = (1u << kKindShift) - 1;

inline PrimitiveRef decodeRef(std::uint32_t code) {
  return {PrimitiveKind(code >> kKindShift), code & kIndexMask};
}

// One ray as the node test needs it: origin and reciprocal direction in every
// lane, and which bound of each axis the ray meets first (the lower one when
// travelling toward +axis).
struct NodeRay {
  Lanes origin[3];
  Lanes inv[3];
  int nearRow[3];
  int farRow[3];

  explicit NodeRay(const Ray& ray) {
    const Vec3 invDir = 1.0 / ray.dir;
    for (int a = 0; a < 3; ++a) {
      origin[a] = broadcast(ray.origin[a]);
      inv[a] = broadcast(invDir[a]);
      nearRow[a] = 2 * a + (invDir[a] < 0.0 ? 1 : 0);
      farRow[a] = 2 * a + (invDir[a] < 0.0 ? 0 : 1);
    }
  }

  // Where the ray enters each of the node's four child boxes (tNear), clipped
  // to `range`, and which children it meets inside `range` (tNear <= tFar).
  Lanes enter(const Bvh::Node& node, Interval range, Lanes& tFar) const {
    Lanes tNear = broadcast(range.min);
    tFar = broadcast(range.max);
    for (int a = 0; a < 3; ++a) {
      const Lanes t0 = (loadBounds(node.bounds[nearRow[a]]) - origin[a]) * inv[a];
      const Lanes t1 = (loadBounds(node.bounds[farRow[a]]) - origin[a]) * inv[a];
      // Written so a NaN (0 * inf, for a ray lying in a box's face plane)
      // leaves the range unchanged: that axis does not cull.
      tNear = maxOr(t0, tNear);
      tFar = minOr(t1, tFar);
    }
    return tNear;
  }
};

constexpr std::size_t kLocalStack = 256; // traversal stack entries kept on the machine stack

// Single-precision bounds that contain the double-precision ones.
float roundDown(double x) {
  float f = float(x);
  if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
float roundUp(double x) {
  float f = float(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

double halfArea(const Aabb& b) {
  const Vec3 e = b.extent();
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

} // namespace

struct Bvh::BuildContext {
  const SahTree& tree;
};

Bvh::Bvh(const Scene& scene) : scene_(scene) {
  const std::vector<PrimitiveRef> prims = scene.allPrimitives();
  if (prims.empty()) return;
  if (prims.size() > kFirstMask) throw std::length_error("too many primitives for the BVH");
  std::vector<Aabb> boxes;
  boxes.reserve(prims.size());
  for (const PrimitiveRef& p : prims)
    boxes.push_back(scene.bounds(p));
  SahOptions options;
  options.maxLeaf = std::min<std::uint32_t>(options.maxLeaf, kMaxLeaf);
  const SahTree tree = buildSahTree(boxes, options);

  refs_.reserve(prims.size());
  for (std::uint32_t i : tree.order)
    refs_.push_back(std::uint32_t(prims[i].kind) << kKindShift | prims[i].index);
  // A 4-wide tree has about a third as many nodes as the binary one has leaves.
  nodes_.reserve(tree.nodes.size() / 6 + 1);
  BuildContext context{tree};
  collapse(context, 0, 1);
}

// Makes the node for binary node `b` and its descendants: the node's children
// are the (up to four) binary descendants left after repeatedly opening the
// largest inner one. Returns the new node's index.
std::uint32_t Bvh::collapse(BuildContext& context, std::uint32_t b, int depth) {
  const SahTree& tree = context.tree;
  std::uint32_t kids[4];
  int count = 0;
  if (tree.nodes[b].leaf()) {
    kids[count++] = b; // only for a root that is a leaf
  } else {
    kids[count++] = tree.nodes[b].left;
    kids[count++] = tree.nodes[b].right;
    while (count < 4) {
      int open = -1;
      double largest = -1.0;
      for (int i = 0; i < count; ++i) {
        const SahTree::Node& n = tree.nodes[kids[i]];
        if (!n.leaf() && halfArea(n.box) > largest) {
          largest = halfArea(n.box);
          open = i;
        }
      }
      if (open < 0) break;
      const SahTree::Node& n = tree.nodes[kids[open]];
      kids[open] = n.left;
      kids[count++] = n.right;
    }
  }

  const auto index = std::uint32_t(nodes_.size());
  nodes_.emplace_back();
  depth_ = std::max(depth_, depth);
  Node node;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 4; ++i) {
      node.bounds[2 * axis][i] = std::numeric_limits<float>::infinity();
      node.bounds[2 * axis + 1][i] = -std::numeric_limits<float>::infinity();
    }
  for (int i = 0; i < 4; ++i)
    node.child[i] = 0;
  for (int i = 0; i < count; ++i) {
    const SahTree::Node& n = tree.nodes[kids[i]];
    Aabb box = n.box;
    // The same relative margin as every hierarchy here: round-off in a hit's t
    // must never put a primitive's hit outside its box.
    box.pad();
    for (int axis = 0; axis < 3; ++axis) {
      node.bounds[2 * axis][i] = roundDown(box.lo[axis]);
      node.bounds[2 * axis + 1][i] = roundUp(box.hi[axis]);
    }
    node.child[i] = n.leaf() ? kLeafBit | (n.count - 1) << kCountShift | n.first
                             : collapse(context, kids[i], depth + 1);
  }
  nodes_[index] = node;
  return index;
}

template <bool AnyHit>
bool Bvh::traverse(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const {
  if (nodes_.empty()) return false;
  const NodeRay nodeRay(ray);

  struct Entry {
    std::uint32_t ref;
    double t; // where the ray enters the child's box
  };
  Entry local[kLocalStack];
  std::vector<Entry> heap; // only for trees deeper than the local stack allows
  Entry* stack = local;
  if (std::size_t need = 3 * std::size_t(depth_) + 1; need > kLocalStack) {
    heap.resize(need);
    stack = heap.data();
  }
  std::size_t top = 0;
  bool found = false;
  std::uint32_t ref = 0;
  for (;;) {
    if ((ref & kLeafBit) == 0) {
      const Node& node = nodes_[ref];
      Lanes tFar;
      const Lanes tNear = nodeRay.enter(node, range, tFar);
      const unsigned hitMask = lessEqualMask(tNear, tFar);
      double tEnter[4];
      store(tEnter, tNear);
      Entry hits[4];
      int n = 0;
      for (int i = 0; i < 4; ++i)
        if ((hitMask >> i) & 1u) hits[n++] = {node.child[i], tEnter[i]};
      if (n > 0) {
        // Nearest first: sort the few hits, push all but the nearest, farthest
        // deepest, and descend into the nearest at once.
        for (int i = 1; i < n; ++i)
          for (int j = i; j > 0 && hits[j].t < hits[j - 1].t; --j)
            std::swap(hits[j], hits[j - 1]);
        for (int i = n - 1; i > 0; --i)
          stack[top++] = hits[i];
        ref = hits[0].ref;
        continue;
      }
    } else {
      const std::uint32_t first = ref & kFirstMask;
      const std::uint32_t end = first + ((ref >> kCountShift) & 0xf) + 1;
      for (std::uint32_t i = first; i < end; ++i) {
        const PrimitiveRef prim = decodeRef(refs_[i]);
        if (skip != nullptr && prim == *skip) continue;
        double t;
        if (intersectPrimitive(scene_, prim, ray, range, t)) {
          if constexpr (AnyHit) {
            if (hit != nullptr) *hit = {t, prim}; // the blocker, when asked for
            return true;
          }
          keepNearest({t, prim}, found, *hit, range);
        }
      }
    }
    // Next: the nearest waiting child that still starts before the nearest hit
    // (at exactly its t too, for the tie-break of keepNearest).
    for (;;) {
      if (top == 0) return found;
      --top;
      if (stack[top].t <= range.max) break;
    }
    ref = stack[top].ref;
  }
}

bool Bvh::closestHit(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit& hit) const {
  return traverse<false>(ray, range, skip, &hit);
}

bool Bvh::anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
                 PrimitiveRef* blocker) const {
  Hit hit;
  const bool found = traverse<true>(ray, range, skip, blocker != nullptr ? &hit : nullptr);
  if (found && blocker != nullptr) *blocker = hit.primitive;
  return found;
}

std::size_t Bvh::memoryBytes() const {
  return nodes_.size() * sizeof(Node) + refs_.size() * sizeof(std::uint32_t);
}

} // namespace prism

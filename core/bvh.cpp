#include "core/bvh.h"

#include "core/bvh_node_test.h"
#include "core/sah_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace prism {

namespace {

using namespace bvh_detail;

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
  if (std::size_t need = stackDepth(); need > kLocalStack) {
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
          if constexpr (AnyHit) return true;
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

bool Bvh::anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip) const {
  return traverse<true>(ray, range, skip, nullptr);
}

std::size_t Bvh::memoryBytes() const {
  return nodes_.size() * sizeof(Node) + refs_.size() * sizeof(std::uint32_t);
}

} // namespace prism

// The default acceleration structure: a bounding-volume hierarchy built with the
// surface area heuristic (core/accel/sah_builder.h) over every primitive, ignoring the
// push/pop groups, and collapsed into 4-wide nodes. A node stores its four
// children's boxes side by side in single precision, rounded outward, and the
// four are tested at once in double precision: a box is never missed where the
// double-precision test on the exact box would hit it, so the nearest hit is
// the same as brute force, bit for bit. Children are visited nearest first and
// skipped once they start beyond the nearest hit found.
#pragma once

#include "core/accel/traversal_accel.h"

#include <cstdint>
#include <vector>

namespace prism {

// Whether `rays` walk a Bvh together in Bvh::closestHits: 2 to
// Accel::kMaxBundle rays from one origin whose directions have, on each axis,
// one sign and no component so small (or zero) that its reciprocal is infinite.
bool walksTogether(std::span<const Ray> rays);

class Bvh final : public TraversalAccel<Bvh> {
public:
  explicit Bvh(const Scene& scene);

  // Eye rays through neighbouring pixels walk the tree together (see
  // core/accel/bvh.cpp); a bundle that does not start at one point, or whose
  // directions differ in sign or have a zero component, goes ray by ray.
  std::uint64_t closestHits(std::span<const Ray> rays, std::span<Hit> hits) const override;
  std::size_t memoryBytes() const override;

  std::size_t nodeCount() const { return nodes_.size(); }
  int depth() const { return depth_; }

  // 4 children a node; 64-byte aligned, so a node is two cache lines.
  struct alignas(64) Node {
    // bounds[2 * axis + 0] are the children's lower bounds on `axis`,
    // bounds[2 * axis + 1] their upper bounds. An unused slot has an empty box
    // (lower +inf, upper -inf), which no ray hits.
    float bounds[6][4];
    // An inner node's index, or kLeafBit | (count - 1) << kCountShift | first:
    // the primitives refs_[first, first + count).
    std::uint32_t child[4];
  };
  static constexpr std::uint32_t kLeafBit = 1u << 31;
  static constexpr int kCountShift = 27;
  static constexpr std::uint32_t kFirstMask = (1u << kCountShift) - 1;
  static constexpr std::uint32_t kMaxLeaf = 16;

private:
  friend class TraversalAccel<Bvh>;
  struct BuildContext;
  std::uint32_t collapse(BuildContext& context, std::uint32_t binaryNode, int depth);

  template <bool AnyHit>
  bool traverse(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const;
  std::uint64_t traverseBundle(std::span<const Ray> rays, std::span<Hit> hits) const;

  const Scene& scene_;
  std::vector<Node> nodes_;         // nodes_[0] is the root
  std::vector<std::uint32_t> refs_; // primitives in leaf order: kind << 28 | index (bvh.cpp)
  int depth_ = 0;                   // levels of nodes
};

} // namespace prism

// The default acceleration structure: a bounding-volume hierarchy built with the
// surface area heuristic (core/accel/sah_builder.h) over every primitive (a long
// thin cone by slices, core/accel/primitive_boxes.h), ignoring the push/pop
// groups, and collapsed into 8-wide nodes. A node stores its eight
// children's boxes side by side in single precision, rounded outward, and a
// ray tests the eight at once in single precision (one AVX register where the
// processor has AVX, else two SSE registers), widened so that it meets every
// box the double-precision test would (bvh.cpp; a ray too far out for float
// takes the double test): a box is never missed where a primitive in it is
// hit, so the nearest hit is the same as brute force, bit for bit.
// Children are visited nearest first and skipped once they start beyond the
// nearest hit found. A leaf's runs of triangles, or of small polygons, are
// tested up to four at once (core/accel/packets.h), with the
// one-primitive tests' answers.
#pragma once

#include "core/accel/packets.h"
#include "core/accel/primitive_boxes.h"
#include "core/accel/sah_builder.h"
#include "core/accel/traversal_accel.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace prism {

// Whether `rays` walk a Bvh together in Bvh::closestHits: 2 to
// Accel::kMaxBundle rays from one origin whose directions have, on each axis,
// one sign and no component so small (or zero) that its reciprocal is infinite.
bool walksTogether(std::span<const Ray> rays);

class Bvh final : public TraversalAccel<Bvh> {
public:
  // Slices of long cones are kept only while the hierarchy (nodes and
  // references, hierarchyBytes()) takes at most this much per primitive; where
  // they would take more (a scene of thin twigs, or nothing but bars) the
  // hierarchy of one box per primitive is built instead. 0: no bound (tests).
  struct Options {
    std::size_t maxBytesPerPrimitive = 64;
    // Whether one ray's node test may use AVX where the processor has it;
    // false takes the SSE test everywhere (tests, to check both).
    bool avx = true;
  };
  explicit Bvh(const Scene& scene) : Bvh(scene, Options{}) {}
  Bvh(const Scene& scene, Options options);

  // Eye rays through neighbouring pixels walk the tree together (see
  // core/accel/bvh.cpp); a bundle that does not start at one point, or whose
  // directions differ in sign or have a zero component, goes ray by ray.
  std::uint64_t closestHits(std::span<const Ray> rays, std::span<Hit> hits) const override;
  // The nodes, the references and the packets' stored data.
  std::size_t memoryBytes() const override;
  // The nodes and references alone, which the bound of Options limits.
  std::size_t hierarchyBytes() const;

  std::size_t nodeCount() const { return nodes_.size(); }
  // Whether one ray's node test runs in AVX: the processor has it, and
  // Options::avx allowed it.
  bool usesAvx() const { return avx_; }
  int depth() const { return depth_; }
  // Primitive references in the leaves: the primitive count, plus the extra
  // slices of long cones (core/accel/primitive_boxes.h).
  std::size_t referenceCount() const { return refs_.size(); }

  // 8 children a node: 224 bytes, 32-byte aligned so that a row of eight
  // bounds is one aligned AVX load. (Padded to 256 bytes, four whole cache
  // lines, the hierarchy outgrew its 64 bytes a primitive.)
  static constexpr int kWidth = 8;
  struct alignas(32) Node {
    // bounds[2 * axis + 0] are the children's lower bounds on `axis`,
    // bounds[2 * axis + 1] their upper bounds. An unused slot has an empty box
    // (lower +inf, upper -inf), which no ray hits.
    float bounds[6][kWidth];
    // An inner node's index, or kLeafBit | (count - 1) << kCountShift |
    // first, and kPacketsBit where the leaf holds a run tested at once: the
    // primitives refs_[first, first + count).
    std::uint32_t child[kWidth];
  };
  static constexpr std::uint32_t kLeafBit = 1u << 31;
  static constexpr int kCountShift = 27;
  static constexpr std::uint32_t kPacketsBit = 1u << 26;
  static constexpr std::uint32_t kFirstMask = kPacketsBit - 1;
  static constexpr std::uint32_t kMaxLeaf = 16;

private:
  friend class TraversalAccel<Bvh>;
  struct BuildContext;
  void build(const std::vector<BoxedPrimitive>& boxed);
  std::uint32_t collapse(BuildContext& context, std::uint32_t binaryNode, int depth);
  std::uint32_t emitLeaf(BuildContext& context, const SahTree::Node& leaf);

  template <bool AnyHit>
  bool traverse(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const;
  // The walk of traverse with a node test of bvh.cpp (single or double
  // precision), testing a leaf's runs of triangles or polygons together or not.
  template <bool AnyHit, class NodeTest, bool Packets>
  bool walk(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const;
  // walk with the single-precision test in one AVX register, compiled for AVX.
  template <bool AnyHit, bool Packets>
  bool walkAvx(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const;
  // What walk does in leaf `leaf` (a child reference).
  template <bool AnyHit, bool Packets, class L>
  bool testLeaf(std::uint32_t leaf, const Ray& ray, Interval& range, const PrimitiveRef* skip,
                bool& found, Hit* hit, std::optional<PacketTest<L>>& packets) const;
  std::uint64_t traverseBundle(std::span<const Ray> rays, std::span<Hit> hits) const;

  // How the walk tests refs_[i]: alone (length 0: or inside a run begun
  // before it), or as the first of a run of `length` (1 to 4) triangles or
  // polygons tested at once, whose data start at packetData_[data].
  struct PacketRun {
    std::uint32_t data = 0;
    std::uint8_t length = 0;
    std::uint8_t polygonVertices = 0; // PolygonCorners::vertices; 0 for triangles
  };
  const Scene& scene_;
  std::vector<Node> nodes_;         // nodes_[0] is the root
  std::vector<std::uint32_t> refs_; // primitives in leaf order: kind << 28 | index (bvh.cpp)
  // Beside refs_ where the walk tests runs (packetRuns_), else empty.
  std::vector<PacketRun> runs_;
  std::vector<double> packetData_; // the runs' data, in leaf order (packets.h)
  int depth_ = 0;                  // levels of nodes
  bool avx_ = false;               // one ray's walk takes walkAvx
  bool packetRuns_ =
      false; // the walk tests leaves' runs at once (bvh.cpp: enough leaves hold some)
};

} // namespace prism

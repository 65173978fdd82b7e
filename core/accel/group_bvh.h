// The modeller's hierarchy: one node per push/pop group, bounding its own
// primitives and its sub-groups. A group that lists many primitives directly
// gets a median-split binary tree over them, so a flat file is not a flat list.
#pragma once

#include "core/accel/traversal_accel.h"

#include <vector>

namespace prism {

class GroupBvh final : public TraversalAccel<GroupBvh> {
public:
  explicit GroupBvh(const Scene& scene);

  std::size_t memoryBytes() const override {
    return nodes_.size() * sizeof(Node) + children_.size() * sizeof(std::uint32_t) +
           prims_.size() * sizeof(PrimitiveRef);
  }

  std::size_t nodeCount() const { return nodes_.size(); }

private:
  friend class TraversalAccel<GroupBvh>;
  // A node bounds its primitives prims_[primBegin, +primCount) and its children
  // children_[childBegin, +childCount) (indices into nodes_).
  struct Node {
    Aabb box;
    std::uint32_t childBegin = 0, childCount = 0;
    std::uint32_t primBegin = 0, primCount = 0;
  };

  std::uint32_t buildGroups();
  std::uint32_t buildGroupNode(std::uint32_t group, std::vector<std::uint32_t> children);
  std::uint32_t addNode(const std::vector<std::uint32_t>& children,
                        const std::vector<PrimitiveRef>& prims);
  template <class T, class MakeLeaf>
  std::uint32_t buildSplit(std::vector<std::pair<T, Aabb>>& items, std::size_t begin,
                           std::size_t end, std::size_t leafSize, MakeLeaf makeLeaf);

  template <bool AnyHit>
  bool traverse(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const;

  const Scene& scene_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> children_;
  std::vector<PrimitiveRef> prims_;
  std::uint32_t root_ = 0;
  std::size_t stackNeed_ = 1; // traversal stack entries the deepest path can need
};

} // namespace prism

#include "core/accel/group_bvh.h"

#include <algorithm>

namespace prism {

namespace {
constexpr std::size_t kLeafSize = 4;         // primitives a node tests directly
constexpr std::size_t kMaxChildren = 8;      // wider groups get a tree over their sub-groups
constexpr std::size_t kGroupLocalStack = 64; // traversal stack kept on the machine stack

int longestAxis(const Vec3& extent) {
  return extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
}
} // namespace

GroupBvh::GroupBvh(const Scene& scene) : scene_(scene) {
  root_ = buildGroups();
  // A node's children wait on the stack while its last child is explored first;
  // nodes are stored after their children, so one forward sweep sizes the stack.
  std::vector<std::size_t> need(nodes_.size(), 1);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    std::size_t deepest = 0;
    for (std::uint32_t c = 0; c < n.childCount; ++c)
      deepest = std::max(deepest, need[children_[n.childBegin + c]]);
    need[i] = std::max<std::size_t>(1, n.childCount + deepest);
  }
  stackNeed_ = need[root_];
}

std::uint32_t GroupBvh::addNode(const std::vector<std::uint32_t>& children,
                                const std::vector<PrimitiveRef>& prims) {
  Node node;
  node.childBegin = std::uint32_t(children_.size());
  node.childCount = std::uint32_t(children.size());
  node.primBegin = std::uint32_t(prims_.size());
  node.primCount = std::uint32_t(prims.size());
  for (std::uint32_t c : children)
    node.box.extend(nodes_[c].box);
  for (const PrimitiveRef& p : prims)
    node.box.extend(scene_.bounds(p));
  node.box.pad();
  children_.insert(children_.end(), children.begin(), children.end());
  prims_.insert(prims_.end(), prims.begin(), prims.end());
  nodes_.push_back(node);
  return std::uint32_t(nodes_.size() - 1);
}

// Median split on the longest axis of the items' centres, down to `leafSize`
// items, each leaf made by makeLeaf(begin, end).
template <class T, class MakeLeaf>
std::uint32_t GroupBvh::buildSplit(std::vector<std::pair<T, Aabb>>& items, std::size_t begin,
                                   std::size_t end, std::size_t leafSize, MakeLeaf makeLeaf) {
  if (end - begin <= leafSize) return makeLeaf(begin, end);
  Aabb centres;
  for (std::size_t i = begin; i < end; ++i)
    centres.extend(items[i].second.centroid());
  const int axis = longestAxis(centres.extent());
  const std::size_t mid = begin + (end - begin) / 2;
  const auto first = items.begin();
  std::nth_element(first + std::ptrdiff_t(begin), first + std::ptrdiff_t(mid),
                   first + std::ptrdiff_t(end), [axis](const auto& a, const auto& b) {
                     return a.second.centroid()[axis] < b.second.centroid()[axis];
                   });
  const std::uint32_t left = buildSplit(items, begin, mid, leafSize, makeLeaf);
  const std::uint32_t right = buildSplit(items, mid, end, leafSize, makeLeaf);
  return addNode({left, right}, {});
}

// Every group's node is made after its sub-groups' nodes (the order a
// recursive build would give), with an explicit stack: push/pop may nest as
// deep as the reader allows, far deeper than the machine stack.
std::uint32_t GroupBvh::buildGroups() {
  struct Pending {
    std::uint32_t group;
    std::size_t nextChild = 0;
    std::vector<std::uint32_t> childNodes; // nodes of the sub-groups built so far
  };
  std::vector<Pending> stack;
  stack.push_back({0, 0, {}});
  for (;;) {
    Pending& top = stack.back();
    const Group& group = scene_.groups[top.group];
    if (top.nextChild < group.children.size()) {
      const std::uint32_t child = group.children[top.nextChild++];
      const Group& g = scene_.groups[child];
      if (!g.primitives.empty() || !g.children.empty())
        stack.push_back({child, 0, {}}); // invalidates top
      continue;
    }
    const std::uint32_t node = buildGroupNode(top.group, std::move(top.childNodes));
    stack.pop_back();
    if (stack.empty()) return node;
    stack.back().childNodes.push_back(node);
  }
}

// The node of one group whose sub-groups' nodes are `children`.
std::uint32_t GroupBvh::buildGroupNode(std::uint32_t groupIndex,
                                       std::vector<std::uint32_t> children) {
  const Group& group = scene_.groups[groupIndex];
  std::vector<PrimitiveRef> prims;
  if (group.primitives.size() <= kLeafSize) {
    prims = group.primitives;
  } else {
    std::vector<std::pair<PrimitiveRef, Aabb>> items;
    items.reserve(group.primitives.size());
    for (const PrimitiveRef& ref : group.primitives)
      items.emplace_back(ref, scene_.bounds(ref));
    children.push_back(buildSplit(items, 0, items.size(), kLeafSize, [&](auto b, auto e) {
      std::vector<PrimitiveRef> leaf;
      for (auto i = b; i < e; ++i)
        leaf.push_back(items[i].first);
      return addNode({}, leaf);
    }));
  }
  if (children.size() > kMaxChildren) {
    std::vector<std::pair<std::uint32_t, Aabb>> items;
    for (std::uint32_t c : children)
      items.emplace_back(c, nodes_[c].box);
    children = {buildSplit(items, 0, items.size(), kMaxChildren, [&](auto b, auto e) {
      std::vector<std::uint32_t> kids;
      for (auto i = b; i < e; ++i)
        kids.push_back(items[i].first);
      return addNode(kids, {});
    })};
  }
  // A group holding nothing but one sub-group adds a box test and nothing else.
  if (prims.empty() && children.size() == 1) return children[0];
  return addNode(children, prims);
}

template <bool AnyHit>
bool GroupBvh::traverse(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const {
  if (!isFinite(ray)) return false;
  const Vec3 invDir = 1.0 / ray.dir;
  const double slack = boxSlack(ray);
  std::uint32_t local[kGroupLocalStack];
  std::vector<std::uint32_t> heap; // only for pathologically deep nesting
  std::uint32_t* stack = local;
  if (stackNeed_ > kGroupLocalStack) {
    heap.resize(stackNeed_);
    stack = heap.data();
  }
  std::size_t top = 0;
  stack[top++] = root_;
  bool found = false;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.hit(ray, invDir, range, slack)) continue;
    for (std::uint32_t i = 0; i < node.primCount; ++i)
      if (testLeafPrimitive<AnyHit>(scene_, prims_[node.primBegin + i], ray, range, skip, found,
                                    hit))
        return true;
    for (std::uint32_t i = 0; i < node.childCount; ++i)
      stack[top++] = children_[node.childBegin + i];
  }
  return found;
}

// Every caller of closestHit and anyHit reaches the walk through these.
template bool GroupBvh::traverse<false>(const Ray&, Interval, const PrimitiveRef*, Hit*) const;
template bool GroupBvh::traverse<true>(const Ray&, Interval, const PrimitiveRef*, Hit*) const;

} // namespace prism

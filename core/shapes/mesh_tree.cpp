#include "core/shapes/mesh_tree.h"

#include <algorithm>

namespace prism {

namespace {

struct Builder {
  std::span<const Triangle> triangles;
  const Vec3* vertices;
  std::vector<Vec3> centroids;    // of triangles[i]
  std::span<std::uint32_t> order; // this mesh's part of the order
  std::vector<MeshTreeNode>& nodes;
  std::size_t root;

  Aabb boundsOf(std::uint32_t first, std::uint32_t count) const {
    Aabb box;
    for (std::uint32_t i = first; i < first + count; ++i)
      for (const std::uint32_t v : triangles[order[i]].vertex)
        box.extend(vertices[v]);
    box.pad();
    return box;
  }

  // Fills node `at` (already allocated) with order[first, first + count).
  void build(std::size_t at, std::uint32_t first, std::uint32_t count) {
    nodes[at].box = boundsOf(first, count);
    if (count <= kMeshTreeLeafSize) {
      nodes[at].first = first;
      nodes[at].count = count;
      return;
    }
    Aabb spread;
    for (std::uint32_t i = first; i < first + count; ++i)
      spread.extend(centroids[order[i]]);
    const Vec3 e = spread.extent();
    const int axis = e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
    // The median by centroid: both halves non-empty whatever the spread, so
    // the depth stays about log2(count / leaf size).
    const std::uint32_t half = count / 2;
    std::nth_element(
        order.begin() + first, order.begin() + first + half, order.begin() + first + count,
        [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
    const std::size_t children = nodes.size();
    nodes.resize(children + 2);
    nodes[at].first = std::uint32_t(children - root);
    nodes[at].count = 0;
    build(children, first, half);
    build(children + 1, first + half, count - half);
  }
};

} // namespace

void buildMeshTree(std::span<const Triangle> triangles, const Vec3* vertices,
                   std::vector<MeshTreeNode>& nodes, std::vector<std::uint32_t>& order) {
  const std::size_t base = order.size();
  for (std::uint32_t i = 0; i < triangles.size(); ++i)
    order.push_back(i);
  Builder b{triangles, vertices, {}, std::span(order).subspan(base), nodes, nodes.size()};
  b.centroids.reserve(triangles.size());
  for (const Triangle& t : triangles)
    b.centroids.push_back((vertices[t.vertex[0]] + vertices[t.vertex[1]] + vertices[t.vertex[2]]) /
                          3.0);
  nodes.emplace_back();
  b.build(b.root, 0, std::uint32_t(triangles.size()));
}

} // namespace prism

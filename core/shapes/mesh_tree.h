// A small bounding-box tree over the triangles of one closed mesh (a CSG
// operand, solid_mesh.h), so a ray tests the triangles near its line rather
// than all of them. The scene's hierarchies (core/accel) are built over whole
// primitives; a mesh operand is one leaf of a CSG node, which no hierarchy
// sees inside, so it keeps a tree of its own: median splits on the longest
// axis of the centroids' box, a few triangles a leaf. Built once when the
// mesh is made; nodes live in ShapeArrays::meshTreeNodes, and the order the
// leaves list the triangles in (indices into the mesh, which keeps its
// triangles as written, so a crossing's part is the triangle's place in the
// text) in ShapeArrays::meshTreeOrder, parallel to meshTriangles.
#pragma once

#include "core/math/aabb.h"
#include "core/shapes/triangle.h"

#include <cstdint>
#include <span>
#include <vector>

namespace prism {

struct MeshTreeNode {
  Aabb box;                // padded (Aabb::pad), so flat meshes have thickness
  std::uint32_t first = 0; // a leaf's first entry of the order; an inner node's first child
  std::uint32_t count = 0; // a leaf's triangles; 0 for an inner node (children first, first + 1)
};

// The most triangles in a leaf.
inline constexpr std::uint32_t kMeshTreeLeafSize = 4;

// Builds the tree over `triangles` (whose vertices index `vertices`):
// appends the nodes to `nodes`, the root first, child indices relative to the
// root, and one index into `triangles` per triangle to `order`, each leaf's
// contiguous.
void buildMeshTree(std::span<const Triangle> triangles, const Vec3* vertices,
                   std::vector<MeshTreeNode>& nodes, std::vector<std::uint32_t>& order);

// Calls hit(i) for each triangle i whose leaf's box the whole line of `ray`
// meets (`order` is the mesh's part of the order).
template <class Hit>
void visitMeshTree(std::span<const MeshTreeNode> nodes, std::span<const std::uint32_t> order,
                   const Ray& ray, Hit&& hit) {
  const Interval line{-std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity()};
  const Vec3 invDir = 1.0 / ray.dir;
  const double slack = boxSlack(ray);
  // Depth is at most about log2(n / leaf size) + a few: 64 levels hold any mesh.
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const MeshTreeNode& node = nodes[stack[--top]];
    if (!node.box.hit(ray, invDir, line, slack)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        hit(order[i]);
    } else {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }
}

} // namespace prism

// The arrays of a scene that shapes index into rather than hold: polygon
// vertices and edge indices, mesh vertices and vertex normals, CSG operands
// and nested CSG nodes (csg.h), blob components, the triangles and trees of
// closed meshes that are CSG operands (solid_mesh.h). A view, cheap to pass; the
// Scene owns the storage.
#pragma once

#include "core/math/math.h"

#include <cstdint>
#include <span>

namespace prism {

class PolygonEdgeIndex;
struct Csg;
struct CsgOperand;
struct BlobComponent;
struct Triangle;
struct MeshTreeNode;

struct ShapeArrays {
  std::span<const Vec3> polygonVertices;
  std::span<const PolygonEdgeIndex> polygonEdgeIndices;
  std::span<const Vec3> meshVertices;
  std::span<const Vec3> meshNormals;       // unit vertex normals of smooth triangles
  std::span<const CsgOperand> csgOperands; // the operands of every CSG node
  std::span<const Csg> csgNodes;           // the nested (not top-level) CSG nodes
  std::span<const BlobComponent> blobComponents;
  std::span<const Triangle> meshTriangles;      // of the closed meshes that are CSG operands
  std::span<const MeshTreeNode> meshTreeNodes;  // their trees (mesh_tree.h)
  std::span<const std::uint32_t> meshTreeOrder; // the trees' order of meshTriangles
};

} // namespace prism

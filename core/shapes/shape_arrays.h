// The arrays of a scene that shapes index into rather than hold: polygon
// vertices and edge indices, mesh vertices and vertex normals, CSG operands
// and nested CSG nodes (csg.h), blob components. A view, cheap to pass; the
// Scene owns the storage.
#pragma once

#include "core/math/math.h"

#include <span>

namespace prism {

class PolygonEdgeIndex;
struct Csg;
struct CsgOperand;
struct BlobComponent;

struct ShapeArrays {
  std::span<const Vec3> polygonVertices;
  std::span<const PolygonEdgeIndex> polygonEdgeIndices;
  std::span<const Vec3> meshVertices;
  std::span<const Vec3> meshNormals;       // unit vertex normals of smooth triangles
  std::span<const CsgOperand> csgOperands; // the operands of every CSG node
  std::span<const Csg> csgNodes;           // the nested (not top-level) CSG nodes
  std::span<const BlobComponent> blobComponents;
};

} // namespace prism

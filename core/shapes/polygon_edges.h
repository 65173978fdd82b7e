// Which edges of a large polygon a horizontal line can cross, found in
// logarithmic time. The polygon test (core/shapes/polygon.cpp) counts the edges that
// cross the half-line from the hit point toward +u in the polygon's 2D
// projection; an edge can cross only where the line's v lies in its v-range
// [min(va, vb), max(va, vb)). For a polygon of many vertices, testing every
// edge makes each ray cost O(n) (a 10^6-vertex polygon took 20 s for a
// 128 x 128 image). This index is a segment tree over the sorted distinct v
// of the vertices: each edge is listed at the O(log n) nodes whose slabs its
// v-range covers, so the edges that can cross are exactly those listed on the
// path from the root to the leaf holding v. Those are then tested with the
// same arithmetic as the full test, so the answer is the same.
//
// Within one node every edge spans the node's whole slab. Unless edges cross
// inside it (possible only in a polygon that is not simple), they keep one
// left-to-right order across the slab, and a node with many edges is searched
// by bisection for the first edge right of the point: O(log^2 n) per ray even
// for a comb whose teeth all cross one line. (There, a point within rounding
// of two edges' meeting point may count one crossing differently from the
// full test; every other answer is the full test's.)
//
// Before the tree, a uniform grid over the polygon's projection answers most
// points in constant time (a gear's 144-gon: most of its area lies away from
// its teeth). A cell that no edge comes within a margin of lies wholly inside
// or wholly outside, and is classified once when the index is built; a point
// in such a cell gets that answer, every other point goes to the tree. Why
// that answer is the full test's, bit for bit: polygon_edges.cpp, above
// buildGrid.
#pragma once

#include "core/math/math.h"

#include <cstdint>
#include <span>
#include <vector>

namespace prism {

// Polygons of at least this many vertices get an edge index.
inline constexpr std::uint32_t kIndexedPolygonVertices = 64;

// Where the edge from (au, av) to (bu, bv) meets the line v = qv: computed
// from its lower endpoint, so that two polygons sharing the edge compute the
// same u (part of the rule that a point on a shared edge belongs to one).
inline double edgeCrossingU(double au, double av, double bu, double bv, double qv) {
  const bool aLower = av < bv;
  const double loU = aLower ? au : bu, loV = aLower ? av : bv;
  const double hiU = aLower ? bu : au, hiV = aLower ? bv : av;
  return loU + (qv - loV) * (hiU - loU) / (hiV - loV);
}

class PolygonEdgeIndex {
public:
  PolygonEdgeIndex() = default;
  // `vertices` of one polygon; `uAxis`, `vAxis` the axes kept by its projection.
  PolygonEdgeIndex(std::span<const Vec3> vertices, int uAxis, int vAxis);

  // Whether the point (qu, qv) is inside by the crossing-number rule, with the
  // edges of `vertices` (the same vertices the index was built from).
  bool contains(const Vec3* vertices, std::uint32_t vertexCount, int uAxis, int vAxis, double qu,
                double qv) const;

  // The grid's answer for the point (qu, qv): kInside or kOutside where it
  // knows, kNearEdge where the tree must decide (near an edge, or outside the
  // grid). contains() asks it first; public for the tests.
  enum GridAnswer : std::uint8_t { kNearEdge = 0, kInside = 1, kOutside = 2 };
  GridAnswer gridAnswer(double qu, double qv) const;

  std::size_t memoryBytes() const;

private:
  bool treeContains(const Vec3* vertices, std::uint32_t vertexCount, int uAxis, int vAxis,
                    double qu, double qv) const;
  void buildGrid(std::span<const Vec3> vertices, int uAxis, int vAxis);
  // The cell column of u (row of v, with the v members), or -1 outside the grid.
  std::int32_t column(double qu) const;
  std::int32_t row(double qv) const;

  // A segment tree in the compact layout: leaf k (the slab between the k-th
  // and the next distinct v) is node leaves_ + k, node i's children are 2i
  // and 2i + 1, and a point's nodes are its leaf and the leaf's ancestors.
  std::vector<double> cuts_;          // sorted distinct v of the vertices
  std::vector<std::uint32_t> begin_;  // node i's edges: edges_[begin_[i], begin_[i + 1])
  std::vector<std::uint8_t> ordered_; // 1: node i's edges run left to right
  std::vector<std::uint32_t> edges_;  // edge i runs from vertex i - 1 (n - 1 for 0) to i
  std::uint32_t leaves_ = 0;

  // The grid: columns_ x rows_ cells over the projection's box, from (u0_, v0_),
  // cell (i, j) at cells_[j * columns_ + i]; empty when the polygon has no
  // grid (a flat box, cells too small for the margin, too much marking, or no
  // cell classified: see buildGrid).
  std::vector<GridAnswer> cells_;
  double u0_ = 0.0, v0_ = 0.0, uScale_ = 0.0, vScale_ = 0.0; // cells per unit
  std::int32_t columns_ = 0, rows_ = 0;
};

} // namespace prism

#include "core/shapes/polygon_edges.h"

#include <algorithm>
#include <cmath>

namespace prism {

namespace {

// Nodes with more edges than this are searched by bisection when ordered.
constexpr std::uint32_t kLinearScanEdges = 16;

// The grid: this many cells per vertex, at most kMaxGridCells in all (1 MB).
// A gear of 144 vertices gets 1,152 cells.
constexpr std::uint32_t kGridCellsPerVertex = 8;
constexpr std::uint32_t kMaxGridCells = 1u << 20;
// Marking the cells near the edges may visit at most this many cells per
// cell of the grid; beyond that (many long edges crossing the whole polygon,
// as in a polygon of random points) the grid would be slow to make and
// nearly all near an edge, and the polygon goes without one.
constexpr std::uint64_t kMaxMarkingPerCell = 16;

// Where edge `i` of the polygon `v` (n vertices) meets the line v = qv.
double crossingU(const Vec3* v, std::uint32_t n, std::uint32_t i, int uAxis, int vAxis, double qv) {
  const Vec3& a = v[i == 0 ? n - 1 : i - 1];
  const Vec3& b = v[i];
  return edgeCrossingU(a[uAxis], a[vAxis], b[uAxis], b[vAxis], qv);
}

} // namespace

PolygonEdgeIndex::PolygonEdgeIndex(std::span<const Vec3> vertices, int uAxis, int vAxis) {
  const auto n = std::uint32_t(vertices.size());
  const Vec3* v = vertices.data();
  for (const Vec3& p : vertices)
    cuts_.push_back(p[vAxis]);
  std::sort(cuts_.begin(), cuts_.end());
  cuts_.erase(std::unique(cuts_.begin(), cuts_.end()), cuts_.end());
  if (cuts_.size() < 2) return; // every edge horizontal: no line crosses any
  leaves_ = std::uint32_t(cuts_.size() - 1);
  const std::uint32_t nodes = 2 * leaves_;

  // Calls list(node, edge) for the nodes that together cover the slabs edge
  // `edge` spans: from its lower v up to (not including) its upper v.
  const auto leafOf = [&](double value) {
    return std::uint32_t(std::lower_bound(cuts_.begin(), cuts_.end(), value) - cuts_.begin());
  };
  const auto forEachListing = [&](auto&& list) {
    for (std::uint32_t i = 0; i < n; ++i) {
      const double av = v[i == 0 ? n - 1 : i - 1][vAxis], bv = v[i][vAxis];
      if (av == bv) continue; // horizontal: never crossed (the half-open rule)
      std::uint32_t lo = leafOf(std::min(av, bv)) + leaves_,
                    hi = leafOf(std::max(av, bv)) + leaves_;
      for (; lo < hi; lo >>= 1, hi >>= 1) {
        if (lo & 1) list(lo++, i);
        if (hi & 1) list(--hi, i);
      }
    }
  };
  // Counted first, then filled, so each node's edges lie together.
  begin_.assign(nodes + 1, 0);
  forEachListing([&](std::uint32_t node, std::uint32_t) { ++begin_[node + 1]; });
  for (std::uint32_t i = 0; i < nodes; ++i)
    begin_[i + 1] += begin_[i];
  edges_.resize(begin_[nodes]);
  std::vector<std::uint32_t> fill(begin_.begin(), begin_.end() - 1);
  forEachListing([&](std::uint32_t node, std::uint32_t edge) { edges_[fill[node]++] = edge; });

  // The slabs under each node (leaves lo .. hi - 1), and the edges of large
  // nodes ordered left to right by where they meet the middle of those
  // slabs; the order is kept if it holds at both borders too.
  std::vector<std::uint32_t> lo(nodes), hi(nodes);
  for (std::uint32_t k = 0; k < leaves_; ++k) {
    lo[leaves_ + k] = k;
    hi[leaves_ + k] = k + 1;
  }
  for (std::uint32_t i = leaves_ - 1; i >= 1; --i) {
    lo[i] = std::min(lo[2 * i], lo[2 * i + 1]);
    hi[i] = std::max(hi[2 * i], hi[2 * i + 1]);
  }
  ordered_.assign(nodes, 0);
  for (std::uint32_t i = 1; i < nodes; ++i) {
    std::uint32_t* first = edges_.data() + begin_[i];
    std::uint32_t* last = edges_.data() + begin_[i + 1];
    if (last - first <= std::ptrdiff_t(kLinearScanEdges)) continue;
    const double bottom = cuts_[lo[i]], top = cuts_[hi[i]];
    const double middle = bottom + 0.5 * (top - bottom);
    const auto u = [&](std::uint32_t edge, double at) {
      return crossingU(v, n, edge, uAxis, vAxis, at);
    };
    std::sort(first, last,
              [&](std::uint32_t a, std::uint32_t b) { return u(a, middle) < u(b, middle); });
    bool increasing = true;
    for (const double at : {bottom, top})
      for (const std::uint32_t* e = first + 1; e < last && increasing; ++e)
        increasing = u(e[-1], at) <= u(e[0], at);
    ordered_[i] = increasing ? 1 : 0;
  }
  buildGrid(vertices, uAxis, vAxis);
}

// Why a cell the grid classifies answers as the full test would, bit for
// bit. Let m = 2^-36 x the largest coordinate of the projection (M below is
// 2m). The full test computes, for each edge crossing the point's row, the
// edge's u there and compares; the rounding in that makes its answer the
// exact answer of a point moved by a few units in the last place of that
// magnitude, far less than m. So a point farther than m from every edge gets
// the exact answer of even-odd crossing, and that answer is the same all over
// a connected region that no edge enters. A point's cell is found by
// rounding ((qu - u0) x scale, and the same for v), monotonic in qu and qv:
// the points a cell receives are a rectangle. Marking covers, for each edge
// and each row the edge's v-range widened by M reaches, the columns from the
// u where the edge enters the row's band widened by M to where it leaves,
// widened by M, with the same rounding; the u found at a band's border is
// the edge's u at a v within rounding of it, so the columns cover every
// point within m of the edge. An unmarked cell's rectangle is therefore
// farther than m from every edge, and so is a run of unmarked cells side by
// side in a row: one full test anywhere in the run answers for all of it.
void PolygonEdgeIndex::buildGrid(std::span<const Vec3> vertices, int uAxis, int vAxis) {
  double uMin = vertices[0][uAxis], uMax = uMin, vMin = vertices[0][vAxis], vMax = vMin;
  for (const Vec3& p : vertices) {
    uMin = std::min(uMin, p[uAxis]);
    uMax = std::max(uMax, p[uAxis]);
    vMin = std::min(vMin, p[vAxis]);
    vMax = std::max(vMax, p[vAxis]);
  }
  const double width = uMax - uMin, height = vMax - vMin;
  const double magnitude = std::max({-uMin, uMax, -vMin, vMax});
  if (!(width > 0.0 && height > 0.0 && std::isfinite(width * height * magnitude))) return;
  const double margin = std::ldexp(magnitude, -35); // M = 2m
  const auto n = std::uint32_t(vertices.size());
  const std::uint32_t cells = std::min(std::max(n, 1u) * kGridCellsPerVertex, kMaxGridCells);
  const double wanted = std::sqrt(double(cells) * width / height);
  columns_ = std::int32_t(std::clamp(std::round(wanted), 1.0, double(cells)));
  rows_ = std::max<std::int32_t>(1, std::int32_t(cells / std::uint32_t(columns_)));
  // Cells not much larger than the margin would all be near an edge.
  if (width / columns_ < 8.0 * margin || height / rows_ < 8.0 * margin) return;
  u0_ = uMin;
  v0_ = vMin;
  uScale_ = columns_ / width;
  vScale_ = rows_ / height;
  const auto clampedColumn = [&](double u) {
    const double c = (u - u0_) * uScale_;
    return c < 0.0 ? 0 : c >= columns_ ? columns_ - 1 : std::int32_t(c);
  };
  const auto clampedRow = [&](double v) {
    const double c = (v - v0_) * vScale_;
    return c < 0.0 ? 0 : c >= rows_ ? rows_ - 1 : std::int32_t(c);
  };

  cells_.assign(std::size_t(columns_) * std::size_t(rows_), kInside); // kInside: not marked
  const std::uint64_t budget = kMaxMarkingPerCell * cells_.size();
  std::uint64_t visited = 0;
  const Vec3* v = vertices.data();
  for (std::uint32_t e = 0; e < n; ++e) {
    const double au = v[e == 0 ? n - 1 : e - 1][uAxis], av = v[e == 0 ? n - 1 : e - 1][vAxis];
    const double bu = v[e][uAxis], bv = v[e][vAxis];
    const std::int32_t firstRow = clampedRow(std::min(av, bv) - margin);
    const std::int32_t lastRow = clampedRow(std::max(av, bv) + margin);
    for (std::int32_t j = firstRow; j <= lastRow; ++j) {
      const double bandLo = v0_ + j / vScale_ - margin, bandHi = v0_ + (j + 1) / vScale_ + margin;
      double uLo = std::min(au, bu), uHi = std::max(au, bu);
      const bool aIn = av >= bandLo && av <= bandHi, bIn = bv >= bandLo && bv <= bandHi;
      if (!(aIn && bIn) && av != bv) {
        // The part of the edge within the band (t from a to b, clamped).
        const double tLo = std::clamp((bandLo - av) / (bv - av), 0.0, 1.0);
        const double tHi = std::clamp((bandHi - av) / (bv - av), 0.0, 1.0);
        const double uAtLo = au + tLo * (bu - au), uAtHi = au + tHi * (bu - au);
        uLo = std::min(uAtLo, uAtHi);
        uHi = std::max(uAtLo, uAtHi);
      }
      const std::int32_t first = clampedColumn(uLo - margin), last = clampedColumn(uHi + margin);
      visited += std::uint64_t(last - first + 1);
      if (visited > budget) {
        cells_.clear();
        return;
      }
      std::fill(cells_.begin() + std::ptrdiff_t(j) * columns_ + first,
                cells_.begin() + std::ptrdiff_t(j) * columns_ + last + 1, kNearEdge);
    }
  }

  // Each run of unmarked cells in a row: one test at its middle, if that
  // point rounds into the run (it does but for rounding at absurd scales;
  // otherwise the run is left to the tree).
  bool anyClassified = false;
  for (std::int32_t j = 0; j < rows_; ++j) {
    GridAnswer* line = cells_.data() + std::ptrdiff_t(j) * columns_;
    for (std::int32_t i = 0; i < columns_;) {
      if (line[i] == kNearEdge) {
        ++i;
        continue;
      }
      std::int32_t end = i;
      while (end < columns_ && line[end] != kNearEdge)
        ++end;
      const double qu = u0_ + 0.5 * (i + end) / uScale_, qv = v0_ + (j + 0.5) / vScale_;
      GridAnswer answer = kNearEdge;
      if (const std::int32_t c = column(qu); c >= i && c < end && row(qv) == j) {
        answer = treeContains(v, n, uAxis, vAxis, qu, qv) ? kInside : kOutside;
        anyClassified = true;
      }
      std::fill(line + i, line + end, answer);
      i = end;
    }
  }
  if (!anyClassified) cells_.clear();
}

std::int32_t PolygonEdgeIndex::column(double qu) const {
  const double c = (qu - u0_) * uScale_;
  return c >= 0.0 && c < columns_ ? std::int32_t(c) : -1; // -1 for NaN too
}

std::int32_t PolygonEdgeIndex::row(double qv) const {
  const double c = (qv - v0_) * vScale_;
  return c >= 0.0 && c < rows_ ? std::int32_t(c) : -1;
}

PolygonEdgeIndex::GridAnswer PolygonEdgeIndex::gridAnswer(double qu, double qv) const {
  if (cells_.empty()) return kNearEdge;
  const std::int32_t i = column(qu), j = row(qv);
  if (i < 0 || j < 0) return kNearEdge;
  return cells_[std::size_t(j) * std::size_t(columns_) + std::size_t(i)];
}

bool PolygonEdgeIndex::contains(const Vec3* vertices, std::uint32_t vertexCount, int uAxis,
                                int vAxis, double qu, double qv) const {
  const GridAnswer answer = gridAnswer(qu, qv);
  if (answer != kNearEdge) return answer == kInside;
  return treeContains(vertices, vertexCount, uAxis, vAxis, qu, qv);
}

bool PolygonEdgeIndex::treeContains(const Vec3* vertices, std::uint32_t vertexCount, int uAxis,
                                    int vAxis, double qu, double qv) const {
  if (leaves_ == 0 || !(qv >= cuts_.front() && qv < cuts_.back())) return false;
  const auto leaf =
      std::uint32_t(std::upper_bound(cuts_.begin(), cuts_.end(), qv) - cuts_.begin() - 1);
  const auto rightOfPoint = [&](std::uint32_t edge) {
    return qu < crossingU(vertices, vertexCount, edge, uAxis, vAxis, qv);
  };
  bool inside = false;
  for (std::uint32_t i = leaves_ + leaf; i >= 1; i >>= 1) {
    const std::uint32_t* first = edges_.data() + begin_[i];
    const std::uint32_t* last = edges_.data() + begin_[i + 1];
    if (ordered_[i] != 0) {
      // Left to right, those right of the point are a suffix.
      const std::uint32_t* right =
          std::partition_point(first, last, [&](std::uint32_t e) { return !rightOfPoint(e); });
      inside ^= ((last - right) & 1) != 0;
    } else {
      for (const std::uint32_t* e = first; e < last; ++e)
        inside ^= rightOfPoint(*e);
    }
  }
  return inside;
}

std::size_t PolygonEdgeIndex::memoryBytes() const {
  return cuts_.size() * sizeof(double) + begin_.size() * sizeof(std::uint32_t) + ordered_.size() +
         edges_.size() * sizeof(std::uint32_t) + cells_.size() * sizeof(GridAnswer);
}

} // namespace prism

#include "core/shapes/polygon_edges.h"

#include <algorithm>

namespace prism {

namespace {

// Nodes with more edges than this are searched by bisection when ordered.
constexpr std::uint32_t kLinearScanEdges = 16;

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
}

bool PolygonEdgeIndex::contains(const Vec3* vertices, std::uint32_t vertexCount, int uAxis,
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
         edges_.size() * sizeof(std::uint32_t);
}

} // namespace prism

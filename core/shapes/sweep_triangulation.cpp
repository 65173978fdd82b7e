#include "core/shapes/sweep_triangulation.h"

#include <algorithm>
#include <iterator>
#include <memory_resource>
#include <set>

namespace prism {

namespace {

// The sweep line triangulation of a counterclockwise polygon without repeats
// of a vertex right after itself.
//
// The sweep visits the vertices from the top down (in the order of above())
// and keeps the edges it crosses in a balanced tree ordered left to right. At
// each vertex it first removes the edges ending there, then inserts those
// starting there, and checks each pair of edges that become neighbours in the
// tree for a meeting point (Shamos and Hoey: the first place where two edges
// meet is found this way, so none found means the polygon is simple).
//
// The same visit adds the diagonals that cut the polygon into y-monotone
// pieces (de Berg et al., ch. 3): a vertex whose edges both go down with the
// interior above (split) or both go up with the interior below (merge) is
// joined to the "helper" of the edge left of it, the lowest vertex seen so far
// in the part of the polygon right of that edge. The pieces are kept as
// circular lists of corners: a diagonal between corners a and b splits their
// list into two and gives a and b one copy each, so that every corner keeps
// the angle between its incoming and its outgoing edge. Which copy faces which
// part of the polygon follows from the vertex's kind (see processVertex), so no
// angle is ever compared. Each piece is then triangulated from the top down
// with a stack of the corners that cannot yet be cut off.
//
// With exact arithmetic a simple polygon gets n - 2 triangles tiling it. A
// polygon that is not simple can make the tree's order inconsistent (edges
// that cross swap places): the tree stays balanced, only its order is wrong,
// lookups that fail are skipped, and the sweep still ends in O(n log n).
// Whatever happened, the result says whether its triangles are certain to
// tile the polygon (see tiles()), which round-off on a nearly degenerate one
// can also prevent.
class SweepTriangulator {
public:
  // `polygon` counterclockwise; `original` the caller's index of each vertex.
  SweepTriangulator(std::vector<P2> polygon, std::vector<std::uint32_t> original)
      : p_(std::move(polygon)), original_(std::move(original)), m_(std::uint32_t(p_.size())) {}

  struct Result {
    std::vector<Triangle2> triangles;
    bool simple = true;    // no edges met, no vertex repeated
    bool certified = true; // the triangles provably tile the polygon
  };

  Result run() {
    orderVertices();
    classifyVertices();
    next_.reserve(3 * std::size_t(m_));
    prev_.reserve(3 * std::size_t(m_));
    vertexOf_.reserve(3 * std::size_t(m_));
    for (std::uint32_t v = 0; v < m_; ++v) {
      next_.push_back(after(v));
      prev_.push_back(before(v));
      vertexOf_.push_back(v);
    }
    where_.assign(m_, status_.end());
    for (const std::uint32_t v : order_)
      processVertex(v);

    Result result;
    result.triangles.reserve(m_ - 2);
    triangulatePieces(result.triangles);
    result.simple = simple_;
    result.certified = consistent_ && result.triangles.size() == m_ - 2 && tiles(result.triangles);
    for (Triangle2& t : result.triangles)
      for (std::uint32_t& corner : t)
        corner = original_[corner];
    return result;
  }

private:
  static constexpr std::uint32_t kNone = ~std::uint32_t(0);

  enum class Kind : std::uint8_t {
    Start,      // both edges go down, interior between them
    Split,      // both edges go down, interior around them
    End,        // both edges come from above, interior between them
    Merge,      // both edges come from above, interior around them
    LeftChain,  // goes down, interior to its right
    RightChain, // goes up, interior to its left
  };
  enum class Chain : std::uint8_t { Top, Left, Right, Bottom };

  // An edge as the tree keeps it: edge `index` runs from vertex `index` to the
  // next; its ends are copied in so that comparisons touch no other memory.
  struct SweepEdge {
    P2 upper, lower;
    std::uint32_t upperRank; // when the sweep reached it
    std::uint32_t index;
    // For an edge going down: its helper corner, and whether that is a merge
    // vertex's. Kept here, not in the order, so the tree's visits fetch it.
    mutable std::uint32_t helper = kNone;
    mutable bool helperIsMerge = false;
  };

  // Positive when q is left of edge e (seen going up it), zero when on its line.
  static double sideOf(const SweepEdge& e, const P2& q) { return cross2(e.lower, e.upper, q); }

  // Edges on the sweep line, left to right. Two edges are compared where the
  // later of them started: coexisting edges of a simple polygon never swap
  // places, so that is their order all along.
  struct EdgeOrder {
    using is_transparent = void;
    bool operator()(const SweepEdge& a, const SweepEdge& b) const {
      if (a.index == b.index) return false;
      // The later edge (by index when both start at one vertex) is placed by
      // its upper end, or by its lower end when the upper end is on the
      // other's line, or by index when the two are collinear.
      const bool bLater =
          b.upperRank > a.upperRank || (b.upperRank == a.upperRank && b.index > a.index);
      const SweepEdge& late = bLater ? b : a;
      const SweepEdge& early = bLater ? a : b;
      double side = sideOf(early, late.upper);
      if (side == 0.0) side = sideOf(early, late.lower);
      const bool lateIsLeft = side > 0.0 || (side == 0.0 && late.index < early.index);
      return bLater ? !lateIsLeft : lateIsLeft;
    }
    bool operator()(const SweepEdge& e, const P2& q) const { return sideOf(e, q) < 0.0; }
    bool operator()(const P2& q, const SweepEdge& e) const { return sideOf(e, q) > 0.0; }
  };
  // A multiset, so that an insertion never fails even if the order is
  // inconsistent; edges are always erased through their own iterator. Its
  // nodes come from a pool that reuses them.
  using Status = std::pmr::multiset<SweepEdge, EdgeOrder>;

  std::uint32_t after(std::uint32_t v) const { return v + 1 == m_ ? 0 : v + 1; }
  std::uint32_t before(std::uint32_t v) const { return v == 0 ? m_ - 1 : v - 1; }
  bool goesDown(std::uint32_t e) const { return rank_[e] < rank_[after(e)]; }

  void orderVertices() {
    // Sorting copies of the points, not indices into them, saves a cache miss
    // per comparison on large polygons.
    struct Key {
      P2 p;
      std::uint32_t vertex;
    };
    std::vector<Key> keys(m_);
    for (std::uint32_t v = 0; v < m_; ++v)
      keys[v] = {p_[v], v};
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
      if (a.p == b.p) return a.vertex < b.vertex;
      return above(a.p, b.p);
    });
    order_.resize(m_);
    rank_.resize(m_);
    for (std::uint32_t r = 0; r < m_; ++r) {
      order_[r] = keys[r].vertex;
      rank_[keys[r].vertex] = r;
      // A vertex repeated anywhere (the tree would not see two that touch
      // only there) comes right after itself in this order.
      if (r > 0 && keys[r].p == keys[r - 1].p) simple_ = false;
    }
  }

  void classifyVertices() {
    kind_.resize(m_);
    for (std::uint32_t v = 0; v < m_; ++v) {
      const std::uint32_t b = before(v), a = after(v);
      const bool fromAbove = rank_[b] < rank_[v];
      const bool toAbove = rank_[a] < rank_[v];
      // Reflex when the polygon turns right here. A straight corner with both
      // neighbours on one side is an edge doubling back, never simple; it is
      // taken as convex, which needs no diagonal.
      const bool reflex = cross2(p_[b], p_[v], p_[a]) < 0.0;
      if (fromAbove && toAbove)
        kind_[v] = reflex ? Kind::Merge : Kind::End;
      else if (!fromAbove && !toAbove)
        kind_[v] = reflex ? Kind::Split : Kind::Start;
      else
        kind_[v] = fromAbove ? Kind::LeftChain : Kind::RightChain;
    }
  }

  // Inserts edge e, which starts at the vertex being visited; `place` is
  // where it belongs or close to it.
  void insert(std::uint32_t e, Status::const_iterator place) {
    const std::uint32_t e1 = after(e);
    const bool down = goesDown(e);
    const SweepEdge edge{
        p_[down ? e : e1], p_[down ? e1 : e], rank_[down ? e : e1], e, kNone, false};
    const Status::iterator at = status_.insert(place, edge);
    where_[e] = at;
    if (!simple_) return;
    if (at != status_.begin()) checkMeeting(*std::prev(at), edge);
    if (const Status::iterator next = std::next(at); next != status_.end())
      checkMeeting(edge, *next);
  }

  // Erases edge e, which ends at the vertex being visited, and returns the
  // edge that followed it.
  Status::const_iterator erase(std::uint32_t e) {
    const Status::iterator at = where_[e];
    if (at == status_.end()) {
      consistent_ = false; // cannot happen: every edge starts above its end
      return at;
    }
    if (simple_ && at != status_.begin()) {
      if (const Status::iterator next = std::next(at); next != status_.end())
        checkMeeting(*std::prev(at), *next);
    }
    where_[e] = status_.end();
    return status_.erase(at);
  }

  // Edges a and b (distinct) share a point other than the vertex that
  // adjacent edges share.
  void checkMeeting(const SweepEdge& a, const SweepEdge& b) {
    const std::uint32_t a1 = after(a.index), b1 = after(b.index);
    bool meet = false;
    if (a1 == b.index)
      meet = doublesBack(a.index, a1, b1);
    else if (b1 == a.index)
      meet = doublesBack(b.index, b1, a1);
    else
      meet = segmentsMeet(a.upper, a.lower, b.upper, b.lower);
    if (meet) simple_ = false;
  }

  // Whether edges x s and s y overlap beyond s: collinear, y on the side of x.
  bool doublesBack(std::uint32_t x, std::uint32_t s, std::uint32_t y) const {
    return cross2(p_[x], p_[s], p_[y]) == 0.0 && dot2(p_[s], p_[x], p_[y]) > 0.0;
  }

  // The edge immediately left of the vertex at `place` (the first edge not
  // left of it), which in a simple polygon has the interior on its right (the
  // vertex being inside or on it).
  const SweepEdge* edgeLeftOf(Status::const_iterator place) {
    if (place != status_.begin()) {
      const SweepEdge& e = *std::prev(place);
      if (goesDown(e.index)) return &e; // interior on its right
    }
    consistent_ = false;
    return nullptr;
  }

  // Edge e in the tree, or null if it is not there (cannot happen).
  const SweepEdge* inTree(std::uint32_t e) {
    if (where_[e] != status_.end()) return &*where_[e];
    consistent_ = false;
    return nullptr;
  }

  // Makes v's `corner` the helper of `edge`.
  void setHelper(const SweepEdge& edge, std::uint32_t v, std::uint32_t corner) const {
    edge.helper = corner;
    edge.helperIsMerge = kind_[v] == Kind::Merge;
  }

  // Joins v's `corner` to the helper of edge `in` (coming down into v) if
  // that is a merge vertex's, and returns the copy of corner facing down.
  std::uint32_t joinMergeHelperOfIncoming(std::uint32_t in, std::uint32_t corner) {
    const SweepEdge* edge = inTree(in);
    return edge && edge->helperIsMerge ? connect(corner, edge->helper) : corner;
  }

  // Adds the diagonal between corners a and b, which splits their piece in
  // two. Corner a keeps its incoming edge and the angle between it and the
  // diagonal; the returned copy of a gets a's outgoing edge and the angle
  // between that and the diagonal. Likewise b keeps its outgoing edge. A
  // diagonal that cannot be right (it would repeat an edge, or one more than
  // a simple polygon can have) is skipped and a returned.
  std::uint32_t connect(std::uint32_t a, std::uint32_t b) {
    if (b == kNone || vertexOf_[a] == vertexOf_[b] || next_[a] == b || next_[b] == a ||
        diagonals_ + 3 >= m_) {
      consistent_ = false;
      return a;
    }
    ++diagonals_;
    const auto a2 = std::uint32_t(next_.size());
    const std::uint32_t b2 = a2 + 1;
    next_.resize(next_.size() + 2);
    prev_.resize(prev_.size() + 2);
    vertexOf_.push_back(vertexOf_[a]);
    vertexOf_.push_back(vertexOf_[b]);
    const std::uint32_t aNext = next_[a], bPrev = prev_[b];
    next_[a] = b;
    prev_[b] = a;
    next_[a2] = aNext;
    prev_[aNext] = a2;
    next_[bPrev] = b2;
    prev_[b2] = bPrev;
    next_[b2] = a2;
    prev_[a2] = b2;
    return a2;
  }

  // Visits vertex v: edge `in` comes into it, edge `out` leaves it. `corner`
  // is v's corner facing down into the part of the polygon below v; each
  // diagonal v gets splits it, and the comments say which half goes on. The
  // edges ending at v leave the tree first; v's place among the others (the
  // first edge not left of it) is then where they were, or else looked up.
  void processVertex(std::uint32_t v) {
    const std::uint32_t in = before(v), out = v;
    std::uint32_t corner = v;
    switch (kind_[v]) {
    case Kind::Start: {
      const Status::const_iterator place = status_.lower_bound(p_[v]);
      insert(in, place);
      insert(out, where_[in]); // `out` goes down left of `in`
      setHelper(*where_[out], v, corner);
      break;
    }
    case Kind::Split: {
      const Status::const_iterator place = status_.lower_bound(p_[v]);
      // The diagonal goes up. Left of it, corner faces the part right of the
      // edge on the left; right of it, the copy (with the outgoing edge) faces
      // the part right of `out`.
      std::uint32_t right = corner;
      if (const SweepEdge* left = edgeLeftOf(place)) {
        right = connect(corner, left->helper);
        setHelper(*left, v, corner);
      }
      insert(out, place);
      insert(in, where_[out]); // `in` comes up left of `out`
      setHelper(*where_[out], v, right);
      break;
    }
    case Kind::End:
      joinMergeHelperOfIncoming(in, corner);
      erase(out);
      erase(in);
      break;
    case Kind::Merge: {
      // The diagonal to the right goes up next to `in`: below it is the copy.
      corner = joinMergeHelperOfIncoming(in, corner);
      erase(out);
      const Status::const_iterator place = erase(in); // `out` was just left of it
      joinHelperOfEdgeLeft(place, v, corner);
      break;
    }
    case Kind::LeftChain: {
      // The diagonal goes up right, next to `in`: below it is the copy, with
      // the outgoing edge.
      corner = joinMergeHelperOfIncoming(in, corner);
      const Status::const_iterator place = erase(in);
      insert(out, place);
      setHelper(*where_[out], v, corner);
      break;
    }
    case Kind::RightChain: {
      const Status::const_iterator place = erase(out);
      joinHelperOfEdgeLeft(place, v, corner);
      insert(in, place);
      break;
    }
    }
  }

  // For a vertex v with the interior on its left (at `place`): joins it to the
  // helper of the edge left of it if that is a merge vertex, and becomes that
  // helper. The diagonal goes up left, next to v's outgoing edge, so `corner`
  // (with the incoming edge) stays below it.
  void joinHelperOfEdgeLeft(Status::const_iterator place, std::uint32_t v, std::uint32_t corner) {
    if (const SweepEdge* left = edgeLeftOf(place)) {
      if (left->helperIsMerge) connect(corner, left->helper);
      setHelper(*left, v, corner);
    }
  }

  void triangulatePieces(std::vector<Triangle2>& out) {
    std::vector<char> seen(next_.size(), 0);
    std::vector<std::uint32_t> piece;
    for (std::uint32_t start = 0; start < next_.size(); ++start) {
      if (seen[start]) continue;
      piece.clear();
      std::uint32_t c = start;
      do {
        seen[c] = 1;
        piece.push_back(c);
        c = next_[c];
      } while (!seen[c]);
      // next_ stays a permutation, so every walk closes on its start.
      if (c != start)
        consistent_ = false;
      else
        triangulateMonotone(piece, out);
    }
  }

  // One y-monotone piece (its corners in order): its two chains from the top
  // corner down, merged by height, then cut from the top down.
  void triangulateMonotone(const std::vector<std::uint32_t>& piece, std::vector<Triangle2>& out) {
    const std::size_t n = piece.size();
    auto rankAt = [&](std::size_t i) { return rank_[vertexOf_[piece[i]]]; };
    std::size_t top = 0, bottom = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (rankAt(i) < rankAt(top)) top = i;
      if (rankAt(i) > rankAt(bottom)) bottom = i;
    }
    if (n < 3 || top == bottom) {
      consistent_ = false;
      return;
    }
    // Counterclockwise, the left chain follows the list down from the top.
    sorted_.clear();
    sorted_.push_back({vertexOf_[piece[top]], Chain::Top});
    std::size_t l = (top + 1) % n, r = (top + n - 1) % n;
    while (l != bottom || r != bottom) {
      if (l != bottom && (r == bottom || rankAt(l) < rankAt(r))) {
        sorted_.push_back({vertexOf_[piece[l]], Chain::Left});
        l = (l + 1) % n;
      } else {
        sorted_.push_back({vertexOf_[piece[r]], Chain::Right});
        r = (r + n - 1) % n;
      }
    }
    sorted_.push_back({vertexOf_[piece[bottom]], Chain::Bottom});

    // The stack holds a chain of corners, top to bottom, none of which can be
    // cut off yet (each is reflex or straight); its bottom may be on the other
    // chain. Triangles are written counterclockwise: a corner on the left
    // chain comes before the ones below it.
    stack_.assign({0, 1});
    for (std::size_t j = 2; j + 1 < n; ++j) {
      const auto [vj, chain] = sorted_[j];
      if (chain != sorted_[stack_.back()].chain) {
        // vj sees every stacked corner: fan them out to it.
        for (std::size_t k = stack_.size() - 1; k > 0; --k) {
          const std::uint32_t lowerCorner = sorted_[stack_[k]].vertex;
          const std::uint32_t upperCorner = sorted_[stack_[k - 1]].vertex;
          out.push_back(chain == Chain::Left ? Triangle2{vj, lowerCorner, upperCorner}
                                             : Triangle2{vj, upperCorner, lowerCorner});
        }
        stack_.assign({j - 1, j});
        continue;
      }
      // Same chain: cut off stacked corners while they are convex seen from vj.
      std::size_t last = stack_.back();
      stack_.pop_back();
      while (!stack_.empty()) {
        const std::uint32_t mid = sorted_[last].vertex;
        const std::uint32_t up = sorted_[stack_.back()].vertex;
        const Triangle2 t = chain == Chain::Left ? Triangle2{up, mid, vj} : Triangle2{vj, mid, up};
        if (!(cross2(p_[t[0]], p_[t[1]], p_[t[2]]) > 0.0)) break;
        out.push_back(t);
        last = stack_.back();
        stack_.pop_back();
      }
      stack_.push_back(last);
      stack_.push_back(j);
    }
    const std::uint32_t bottomVertex = sorted_[n - 1].vertex;
    const Chain chain = sorted_[stack_.back()].chain;
    for (std::size_t k = stack_.size() - 1; k > 0; --k) {
      const std::uint32_t lowerCorner = sorted_[stack_[k]].vertex;
      const std::uint32_t upperCorner = sorted_[stack_[k - 1]].vertex;
      out.push_back(chain == Chain::Left ? Triangle2{bottomVertex, upperCorner, lowerCorner}
                                         : Triangle2{bottomVertex, lowerCorner, upperCorner});
    }
  }

  // Whether the triangles tile the polygon, given that every diagonal split a
  // piece in two (consistent_ and m - 2 triangles; a diagonal joining two
  // pieces would have added 4). Each piece's triangles are then written
  // along it, sharing each inner edge once each way, so with signs they sum
  // to the polygon's area whatever their shapes, and when none turns
  // clockwise beyond round-off they cover it exactly once.
  bool tiles(const std::vector<Triangle2>& triangles) const {
    double signedSum = 0.0, absoluteSum = 0.0;
    for (const Triangle2& t : triangles) {
      const double a = cross2(p_[t[0]], p_[t[1]], p_[t[2]]);
      signedSum += a;
      absoluteSum += std::abs(a);
    }
    return signedSum > 0.0 && absoluteSum <= signedSum * (1.0 + 1e-9);
  }

  struct Sorted {
    std::uint32_t vertex;
    Chain chain;
  };

  std::vector<P2> p_;
  std::vector<std::uint32_t> original_;
  std::uint32_t m_;
  std::vector<std::uint32_t> order_; // vertices from the top down
  std::vector<std::uint32_t> rank_;  // each vertex's place in order_
  std::vector<Kind> kind_;
  std::pmr::unsynchronized_pool_resource pool_;
  Status status_{&pool_};
  std::vector<Status::iterator> where_; // each edge's place in status_, or end()
  // The pieces: corners in circular lists. Corner v < m is vertex v's own;
  // diagonals add copies.
  std::vector<std::uint32_t> next_, prev_, vertexOf_;
  std::size_t diagonals_ = 0;
  bool simple_ = true;     // no two edges found meeting
  bool consistent_ = true; // no lookup failed, no diagonal skipped
  std::vector<Sorted> sorted_;
  std::vector<std::size_t> stack_;
};

} // namespace

SweepResult sweepTriangulate(std::vector<P2> polygon, std::vector<std::uint32_t> original) {
  SweepTriangulator::Result r = SweepTriangulator(std::move(polygon), std::move(original)).run();
  return {std::move(r.triangles), r.simple, r.certified};
}

} // namespace prism

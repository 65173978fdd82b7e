#include "core/shapes/csg.h"

#include "core/shapes/shape_kinds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

const char* csgOpName(CsgOp op) {
  switch (op) {
  case CsgOp::Union: return "union";
  case CsgOp::Intersection: return "intersection";
  case CsgOp::Difference: return "difference";
  }
  return "union";
}

std::span<const CsgOperand> operandsOf(const Csg& node, const ShapeArrays& arrays) {
  return arrays.csgOperands.subspan(node.firstOperand, node.operandCount);
}

namespace {

// A closed shape of a node's tree, and whether its surface is turned inside
// out in the combined solid (an odd number of times subtracted).
struct Leaf {
  const CsgOperand* operand;
  bool flipped;
};

struct LeafCrossing {
  double t;
  bool entering; // the leaf's own solid is entered
  std::uint32_t part;
  std::uint32_t leaf;
};

// The leaves of `node`, depth first in the order written.
void collectLeaves(const Csg& node, const ShapeArrays& arrays, bool flipped,
                   std::vector<Leaf>& out) {
  const std::span<const CsgOperand> operands = operandsOf(node, arrays);
  for (std::size_t i = 0; i < operands.size(); ++i) {
    const bool f = flipped != (node.op == CsgOp::Difference && i > 0);
    if (const auto* nested = std::get_if<CsgNodeIndex>(&operands[i].shape))
      collectLeaves(arrays.csgNodes[nested->index], arrays, f, out);
    else
      out.push_back({&operands[i], f});
  }
}

// Whether a point is inside `node`, given whether it is inside each leaf
// (in collectLeaves' order, from `next` on, which it advances past the
// node's leaves).
bool insideOf(const Csg& node, const ShapeArrays& arrays, const unsigned char* inside,
              std::size_t& next) {
  bool result = node.op != CsgOp::Union;
  const std::span<const CsgOperand> operands = operandsOf(node, arrays);
  for (std::size_t i = 0; i < operands.size(); ++i) {
    const auto* nested = std::get_if<CsgNodeIndex>(&operands[i].shape);
    const bool in = nested != nullptr
                        ? insideOf(arrays.csgNodes[nested->index], arrays, inside, next)
                        : inside[next++] != 0;
    switch (node.op) {
    case CsgOp::Union: result = result || in; break;
    case CsgOp::Intersection: result = result && in; break;
    case CsgOp::Difference: result = i == 0 ? in : result && !in; break;
    }
  }
  return result;
}

// Calls f(leaf shape) with the leaf's own type.
template <class F> decltype(auto) visitLeaf(const Leaf& leaf, F&& f) {
  return std::visit(
      [&](const auto& shape) -> decltype(auto) {
        if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>) {
          return f(Sphere{}); // never: nested nodes are not leaves
        } else {
          return f(shape);
        }
      },
      leaf.operand->shape);
}

// Scratch for the walk, one per thread: no allocation per ray once warm.
struct Walk {
  std::vector<Leaf> leaves;
  std::vector<LeafCrossing> crossings;
  std::vector<Crossing> one;
  std::vector<unsigned char> inside;
};

Walk& scratch() {
  thread_local Walk walk;
  return walk;
}

// The crossings of the combined solid along the whole line of `ray`, in
// increasing t: emit(crossing, entering) for each, until it returns true.
// (See csg.h for the rules; they are all here.)
template <class Emit>
void walkCrossings(const Csg& node, const ShapeArrays& arrays, const Ray& ray, Walk& w,
                   Emit&& emit) {
  w.leaves.clear();
  collectLeaves(node, arrays, false, w.leaves);
  w.crossings.clear();
  const Interval line{-std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity()};
  const Vec3 invDir = 1.0 / ray.dir;
  const double slack = boxSlack(ray);
  for (std::uint32_t i = 0; i < w.leaves.size(); ++i) {
    w.one.clear();
    visitLeaf(w.leaves[i], [&](const auto& shape) {
      Aabb box = boundsOf(shape, arrays);
      box.pad();
      if (box.hit(ray, invDir, line, slack)) appendCrossings(shape, arrays, ray, line, w.one);
    });
    for (const Crossing& c : w.one)
      w.crossings.push_back({c.t, c.entering, c.part, i});
  }
  std::stable_sort(w.crossings.begin(), w.crossings.end(),
                   [](const LeafCrossing& a, const LeafCrossing& b) {
                     return a.t < b.t || (a.t == b.t && a.leaf < b.leaf);
                   });
  w.inside.assign(w.leaves.size(), 0);
  bool state = false;
  const std::size_t n = w.crossings.size();
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    for (; j < n && w.crossings[j].t == w.crossings[i].t; ++j)
      w.inside[w.crossings[j].leaf] = w.crossings[j].entering ? 1 : 0;
    std::size_t next = 0;
    const bool after = insideOf(node, arrays, w.inside.data(), next);
    if (after != state) {
      // The face: the first crossing of the group that moves the combined
      // solid the way it went (a leaf entered, or a subtracted leaf left,
      // when it is entered). One exists: the node is monotone in each leaf.
      std::size_t k = i;
      while (k + 1 < j &&
             (w.crossings[k].entering != w.leaves[w.crossings[k].leaf].flipped) != after)
        ++k;
      state = after;
      if (emit(w.crossings[k], after)) return;
    }
    i = j;
  }
}

// A leaf's record (and coordinates, when asked) at `point`. Only a mesh needs
// the crossing's part, its triangle, when known: every other kind finds its
// face from the point.
template <class K>
SurfacePoint recordAt(const K& shape, const ShapeArrays& arrays, const Vec3& point,
                      const std::uint32_t*, SurfaceDetail detail) {
  SurfacePoint r = surfaceAt(shape, arrays, point);
  if (detail == SurfaceDetail::WithCoordinates) r.uv = uvAt(shape, arrays, point);
  return r;
}
SurfacePoint recordAt(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point,
                      const std::uint32_t* part, SurfaceDetail detail) {
  return surfaceAt(m, arrays, point, part != nullptr ? *part : nearestTriangle(m, arrays, point),
                   detail);
}

// The record of a leaf at `point` (on its face `part`, if known), turned
// inside out where it is subtracted.
SurfacePoint leafSurface(const Leaf& leaf, const ShapeArrays& arrays, const Vec3& point,
                         SurfaceDetail detail, const std::uint32_t* part = nullptr) {
  SurfacePoint s = visitLeaf(leaf, [&](const auto& shape) {
    SurfacePoint r = recordAt(shape, arrays, point, part, detail);
    r.material = shape.material;
    return r;
  });
  if (leaf.flipped) {
    s.outward = -s.outward;
    s.shading = -s.shading;
  }
  return s;
}

// The leaf whose surface passes nearest `point` (see surfaceAt in csg.h).
Leaf nearestLeaf(const Csg& node, const ShapeArrays& arrays, const Vec3& point) {
  Walk& w = scratch();
  w.leaves.clear();
  collectLeaves(node, arrays, false, w.leaves);
  Leaf best = w.leaves.front();
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const Leaf& leaf : w.leaves) {
    visitLeaf(leaf, [&](const auto& shape) {
      const Vec3 n = outwardNormal(shape, arrays, point);
      // A probe along the normal, from a little inside to a little outside.
      const double h = 0x1p-20 * (roundoffScale(shape, arrays) + maxAbsComponent(point));
      w.one.clear();
      appendCrossings(shape, arrays, Ray{point - h * n, n}, Interval{0.0, 2.0 * h}, w.one);
      for (const Crossing& c : w.one) {
        const double distance = std::abs(c.t - h);
        if (distance < bestDistance) {
          bestDistance = distance;
          best = leaf;
        }
      }
    });
  }
  return best;
}

} // namespace

void finishCsg(Csg& node, const ShapeArrays& arrays) {
  Aabb bounds;
  double roundoff = 0.0;
  const std::span<const CsgOperand> operands = operandsOf(node, arrays);
  for (std::size_t i = 0; i < operands.size(); ++i) {
    Aabb box;
    std::visit(
        [&](const auto& shape) {
          if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, CsgNodeIndex>) {
            const Csg& nested = arrays.csgNodes[shape.index];
            box = nested.bounds;
            roundoff = std::max(roundoff, nested.roundoff);
          } else {
            box = boundsOf(shape, arrays);
            roundoff = std::max(roundoff, roundoffScale(shape, arrays));
          }
        },
        operands[i].shape);
    if (i == 0) {
      bounds = box;
    } else if (node.op == CsgOp::Union) {
      bounds.extend(box);
    } else if (node.op == CsgOp::Intersection) {
      bounds.lo = glm::max(bounds.lo, box.lo);
      bounds.hi = glm::min(bounds.hi, box.hi);
    } // a difference covers no more than its first operand
  }
  // An intersection of disjoint boxes covers nothing: a point stands for it
  // (the hierarchies need a place; the walk finds no crossing).
  if (bounds.empty()) {
    const Vec3 p = bounds.lo;
    bounds = Aabb{};
    bounds.extend(glm::min(p, Vec3(std::numeric_limits<double>::max())));
  }
  node.bounds = bounds;
  node.roundoff = roundoff;
}

bool intersect(const Csg& node, const ShapeArrays& arrays, const Ray& ray, Interval range,
               double& t) {
  bool found = false;
  walkCrossings(node, arrays, ray, scratch(), [&](const LeafCrossing& c, bool) {
    if (!(c.t < range.max)) return true;
    if (!range.contains(c.t)) return false;
    t = c.t;
    found = true;
    return true;
  });
  return found;
}

void appendCrossings(const Csg& node, const ShapeArrays& arrays, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  walkCrossings(node, arrays, ray, scratch(), [&](const LeafCrossing& c, bool entering) {
    if (!(c.t < range.max)) return true;
    if (range.contains(c.t)) out.push_back({c.t, entering, c.part});
    return false;
  });
}

namespace {

// The crossing of the node's surface nearest `t` along `ray`: its leaf (in
// w.leaves) and part.
struct Along {
  std::size_t leaf = 0;
  std::uint32_t part = 0;
};
Along crossingAlong(const Csg& node, const ShapeArrays& arrays, const Ray& ray, double t, Walk& w) {
  Along found;
  double nearest = std::numeric_limits<double>::infinity();
  walkCrossings(node, arrays, ray, w, [&](const LeafCrossing& c, bool) {
    const double distance = std::abs(c.t - t);
    if (distance < nearest) {
      nearest = distance;
      found = {c.leaf, c.part};
    }
    return c.t >= t;
  });
  return found;
}

} // namespace

SurfacePoint surfaceAlong(const Csg& node, const ShapeArrays& arrays, const Ray& ray, double t,
                          SurfaceDetail detail) {
  Walk& w = scratch();
  const Along along = crossingAlong(node, arrays, ray, t, w);
  const Vec3 point = ray.at(t);
  if (w.leaves.empty()) {
    SurfacePoint none;
    none.point = point;
    return none;
  }
  return leafSurface(w.leaves[along.leaf], arrays, point, detail, &along.part);
}

const CsgOperand* operandAlong(const Csg& node, const ShapeArrays& arrays, const Ray& ray,
                               double t) {
  Walk& w = scratch();
  const Along along = crossingAlong(node, arrays, ray, t, w);
  return w.leaves.empty() ? nullptr : w.leaves[along.leaf].operand;
}

SurfacePoint surfaceAt(const Csg& node, const ShapeArrays& arrays, const Vec3& point) {
  return leafSurface(nearestLeaf(node, arrays, point), arrays, point, SurfaceDetail::Shading);
}

Vec3 outwardNormal(const Csg& node, const ShapeArrays& arrays, const Vec3& point) {
  return surfaceAt(node, arrays, point).outward;
}

Vec2 uvAt(const Csg& node, const ShapeArrays& arrays, const Vec3& point) {
  return leafSurface(nearestLeaf(node, arrays, point), arrays, point,
                     SurfaceDetail::WithCoordinates)
      .uv;
}

} // namespace prism

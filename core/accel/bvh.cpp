#include "core/accel/bvh.h"

#include "core/accel/lanes.h"
#include "core/accel/packets.h"
#include "core/accel/primitive_boxes.h"
#include "core/accel/sah_builder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>

namespace prism {

namespace {

using namespace lanes;

#if defined(__SSE2__)
// Four float lanes, one per child box: the one-ray node test.
using LanesF = __m128;
inline LanesF broadcastF(float x) { return _mm_set1_ps(x); }
inline LanesF loadF(const float* p) { return _mm_loadu_ps(p); }
inline LanesF subF(LanesF a, LanesF b) { return _mm_sub_ps(a, b); }
inline LanesF addF(LanesF a, LanesF b) { return _mm_add_ps(a, b); }
inline LanesF mulF(LanesF a, LanesF b) { return _mm_mul_ps(a, b); }
inline LanesF maxOrF(LanesF a, LanesF b) { return _mm_max_ps(a, b); }
inline LanesF minOrF(LanesF a, LanesF b) { return _mm_min_ps(a, b); }
inline unsigned lessEqualMaskF(LanesF a, LanesF b) {
  return unsigned(_mm_movemask_ps(_mm_cmple_ps(a, b)));
}
inline void storeF(float* out, LanesF a) { _mm_storeu_ps(out, a); }
#else
using LanesF = float __attribute__((vector_size(16)));
inline LanesF broadcastF(float x) { return LanesF{x, x, x, x}; }
inline LanesF loadF(const float* p) { return loadLanes<LanesF>(p); }
inline LanesF subF(LanesF a, LanesF b) { return a - b; }
inline LanesF addF(LanesF a, LanesF b) { return a + b; }
inline LanesF mulF(LanesF a, LanesF b) { return a * b; }
inline LanesF maxOrF(LanesF a, LanesF b) { return a > b ? a : b; }
inline LanesF minOrF(LanesF a, LanesF b) { return a < b ? a : b; }
inline unsigned lessEqualMaskF(LanesF a, LanesF b) { return maskBits(a <= b); }
inline void storeF(float* out, LanesF a) { std::memcpy(out, &a, sizeof a); }
#endif

constexpr std::uint32_t kKindShift = 28; // 4 bits of PrimitiveKind (16 kinds), 28 of index
constexpr std::uint32_t kIndexMask = (1u << kKindShift) - 1;
static_assert(kShapeKindCount <= (1u << (32 - kKindShift)),
              "more shape kinds than the packed reference's kind bits hold");
// Every index fits its bits: the constructor refuses more primitives in all
// than a leaf can address (Bvh::kFirstMask), fewer than the index bits hold.
static_assert(Bvh::kFirstMask <= kIndexMask, "a primitive's index must fit the packed reference");

// The most references a hierarchy holds, each with the most data a packet's
// lane takes (a polygon of kPacketPolygonVertices), fit PacketRun::data.
static_assert((std::uint64_t(Bvh::kFirstMask) + 1) * (4 + 3 * kPacketPolygonVertices) +
                      kPacketPadding <=
                  std::uint64_t(UINT32_MAX),
              "packet data offsets must fit 32 bits");

inline PrimitiveRef decodeRef(std::uint32_t code) {
  return {PrimitiveKind(code >> kKindShift), code & kIndexMask};
}
inline std::uint32_t encodeRef(PrimitiveRef p) {
  return std::uint32_t(p.kind) << kKindShift | p.index;
}

// Where the origin is taken to be when the near and the far bound of an
// axis are tested: moved by boxSlack toward the far side for the near bound
// and toward the near side for the far one, which widens every box by the
// slack at no cost per node.
struct SlackOrigin {
  double near, far;
};
SlackOrigin slackOrigin(double origin, double inverseDirection, double slack) {
  const double toward = inverseDirection < 0.0 ? -slack : slack;
  return {origin + toward, origin - toward};
}

// The node test of one ray in double precision: the reference the float test
// below is built to contain, and the test of the rays that one cannot take.
// Holds the origin and reciprocal direction in every lane, and which bound of
// each axis the ray meets first (the lower one when travelling toward +axis).
class DoubleNodeTest {
public:
  using Time = double;       // of the entries into boxes that meet reports
  using PacketLanes = Lanes; // of the leaves' packets (packets.h)
  explicit DoubleNodeTest(const Ray& ray) {
    const Vec3 invDir = 1.0 / ray.dir;
    const double slack = boxSlack(ray);
    for (int a = 0; a < 3; ++a) {
      const SlackOrigin o = slackOrigin(ray.origin[a], invDir[a], slack);
      nearOrigin_[a] = Lanes::splat(o.near);
      farOrigin_[a] = Lanes::splat(o.far);
      inv_[a] = Lanes::splat(invDir[a]);
      nearRow_[a] = 2 * a + (invDir[a] < 0.0 ? 1 : 0);
      farRow_[a] = 2 * a + (invDir[a] < 0.0 ? 0 : 1);
    }
  }

  // The range of t the children must be entered in; narrowed as hits are found.
  void setRange(Interval range) { range_ = range; }
  void setRangeMax(double max) { range_.max = max; }

  // Which of the node's eight child boxes the ray meets inside the range
  // (bit i: child i), and where it enters each (tEnter, clipped to the
  // range). Four at a time.
  unsigned meet(const Bvh::Node& node, double (&tEnter)[Bvh::kWidth]) const {
    unsigned mask = 0;
    for (int h = 0; h < Bvh::kWidth; h += 4) {
      Lanes tNear = Lanes::splat(range_.min);
      Lanes tFar = Lanes::splat(range_.max);
      for (int a = 0; a < 3; ++a) {
        const Lanes t0 = (loadBounds(node.bounds[nearRow_[a]] + h) - nearOrigin_[a]) * inv_[a];
        const Lanes t1 = (loadBounds(node.bounds[farRow_[a]] + h) - farOrigin_[a]) * inv_[a];
        // Written so a NaN (0 * inf, for a ray lying in a box's face plane)
        // leaves the range unchanged: that axis does not cull.
        tNear = maxOr(t0, tNear);
        tFar = minOr(t1, tFar);
      }
      store(tEnter + h, tNear);
      mask |= lessEqualMask(tNear, tFar) << h;
    }
    return mask;
  }

private:
  Lanes nearOrigin_[3]; // the origin for the near bounds (see slackOrigin)
  Lanes farOrigin_[3];
  Lanes inv_[3];
  int nearRow_[3];
  int farRow_[3];
  Interval range_;
};

// The same test in single precision: four boxes in one SSE register instead
// of two (eight in one AVX register: AvxFloatNodeTest), and no conversion of
// the stored bounds. It meets every box the double test meets, so the walk
// still finds exactly brute force's nearest hit:
//  - each origin is moved by the double test's slack plus 2^-22 of the
//    largest coordinate (and 2^-140), then rounded to the nearest float:
//    rounding moves it by at most 2^-24 of that, so it stays on the side of
//    the double test's origin that makes the box wider;
//  - what remains is relative: the rounding of the subtraction, of 1/d and
//    of the product, about 4 float ulps of t against 2 double ulps, and of
//    the range's ends, half a float ulp; below float's normal range, an
//    absolute 2^-150;
//  - so every entry is made smaller and every exit larger by 2^-20 of its
//    size (16 float ulps), which holds the double test's interval: the near
//    bounds' times are taken with 1/d times 1 - 2^-20 and the far bounds'
//    with 1/d times 1 + 2^-20 (each rounded to float: one ulp more), the
//    range's start is taken times 1 - 2^-20 and its end times 1 + 2^-20.
//    Scaled so, a time of either sign moves toward 0 or away from it, whole:
//    a negative entry (the origin inside the slab) may move up toward 0 but
//    stays below the range's start, which is 0 or later, so the entry is
//    still the range's; a negative exit misses either way. Then the entry is
//    lowered by 2^-140, for the absolute errors below float's normal range.
//    An exit beyond float's range is infinite, or FLT_MAX where the entry is
//    smaller still. The widening is thus folded into per-ray values, off a
//    node's path from its bounds to its answer.
// Rays that it cannot take (suits) use DoubleNodeTest.
// The per-ray values of the float tests: the origins moved by the slack
// (above) and rounded, 1/d widened (above) and rounded, and where in a node
// each axis's near and far bounds are (byte offsets of rows of
// Node::bounds).
struct FloatRay {
  float nearOrigin[3], farOrigin[3], nearInv[3], farInv[3];
  std::size_t nearOffset[3], farOffset[3];

  // Whether the float tests can take `ray` over `range`: the range starts at
  // 0 or later; the origin's coordinates are within 2^100 and each direction
  // component is 0 or of a size from 2^-100 to 2^100, so that 1/d is finite
  // and not 0 in float (or infinite, exactly where double's is).
  // Such a ray is finite: a NaN fails every comparison here.
  static bool suits(const Ray& ray, Interval range);
  explicit FloatRay(const Ray& ray);
};

// Row `offset` bytes into a node's bounds.
inline const float* boundsRow(const Bvh::Node& node, std::size_t offset) {
  return reinterpret_cast<const float*>(reinterpret_cast<const unsigned char*>(node.bounds) +
                                        offset);
}

// The widening of entries and exits (above).
constexpr double kWidenDown = 1.0 - 0x1p-20;
constexpr double kWidenUp = 1.0 + 0x1p-20;
constexpr float kWidenTiny = 0x1p-140f;
// The range's ends in float, widened (an end of 0 or infinity stays so; a
// tiny end gains the 2^-140 too).
inline float floatRangeMin(double min) { return float(min) * float(kWidenDown); }
inline float floatRangeMax(double max) { return float(max) * float(kWidenUp) + kWidenTiny; }

class FloatNodeTest {
public:
  using Time = float;
  using PacketLanes = Lanes;
  static bool suits(const Ray& ray, Interval range) { return FloatRay::suits(ray, range); }

  explicit FloatNodeTest(const Ray& ray) {
    const FloatRay f(ray);
    for (int a = 0; a < 3; ++a) {
      nearOrigin_[a] = broadcastF(f.nearOrigin[a]);
      farOrigin_[a] = broadcastF(f.farOrigin[a]);
      nearInv_[a] = broadcastF(f.nearInv[a]);
      farInv_[a] = broadcastF(f.farInv[a]);
      nearOffset_[a] = f.nearOffset[a];
      farOffset_[a] = f.farOffset[a];
    }
    asm("" : "+x"(widenTiny_));
  }

  void setRange(Interval range) {
    rangeMin_ = broadcastF(floatRangeMin(range.min));
    setRangeMax(range.max);
  }
  void setRangeMax(double max) { rangeMax_ = broadcastF(floatRangeMax(max)); }

  // As DoubleNodeTest::meet.
  unsigned meet(const Bvh::Node& node, float (&tEnter)[Bvh::kWidth]) const {
    unsigned mask = 0;
    for (int h = 0; h < Bvh::kWidth; h += 4) {
      LanesF tNear = rangeMin_;
      LanesF tFar = rangeMax_;
      for (int a = 0; a < 3; ++a) {
        const LanesF t0 =
            mulF(subF(loadF(boundsRow(node, nearOffset_[a]) + h), nearOrigin_[a]), nearInv_[a]);
        const LanesF t1 =
            mulF(subF(loadF(boundsRow(node, farOffset_[a]) + h), farOrigin_[a]), farInv_[a]);
        tNear = maxOrF(t0, tNear); // a NaN leaves the range unchanged, as above
        tFar = minOrF(t1, tFar);
      }
      tNear = subF(tNear, widenTiny_);
      storeF(tEnter + h, tNear);
      mask |= lessEqualMaskF(tNear, tFar) << h;
    }
    return mask;
  }

private:
  LanesF nearOrigin_[3]; // see slackOrigin
  LanesF farOrigin_[3];
  LanesF nearInv_[3], farInv_[3];
  LanesF rangeMin_, rangeMax_;
  // Hidden from the optimiser (ctor), which would otherwise splat the
  // constant anew at every node.
  LanesF widenTiny_ = broadcastF(kWidenTiny);
  std::size_t nearOffset_[3], farOffset_[3];
};

constexpr double kFloatTestLimit = 0x1p100; // of FloatNodeTest::suits
// boxSlack and FloatNodeTest's 2^-22 of the largest coordinate, in one product
// (its rounding is far below either), and the 2^-140.
constexpr double kFloatSlackPerCoordinate = kBoxSlackPerCoordinate + 0x1p-22;
constexpr double kFloatSlackFloor = 0x1p-140;

#if defined(__SSE2__)
// One ray's setup with its coordinates two to a register: fewer
// instructions than the scalar loop of other machines below, which matters
// where a ray visits only a few nodes.

// A Vec3 as two registers: (x, y) and (z, 0).
struct Pair {
  __m128d xy, z0;
};
Pair loadPair(const Vec3& v) { return {_mm_loadu_pd(&v.x), _mm_load_sd(&v.z)}; }
Pair absPair(Pair v) {
  const __m128d sign = _mm_set1_pd(-0.0);
  return {_mm_andnot_pd(sign, v.xy), _mm_andnot_pd(sign, v.z0)};
}
// Bits 0..2 of the comparison's lanes x, y, z (and bit 3 of the unused lane, 0).
unsigned maskPair(__m128d xy, __m128d z0) {
  return unsigned(_mm_movemask_pd(xy)) | unsigned(_mm_movemask_pd(z0)) << 2;
}

inline bool FloatRay::suits(const Ray& ray, Interval range) {
  const Pair o = absPair(loadPair(ray.origin)), d = absPair(loadPair(ray.dir));
  const __m128d limit = _mm_set1_pd(kFloatTestLimit), least = _mm_set1_pd(1.0 / kFloatTestLimit);
  const __m128d zero = _mm_setzero_pd();
  // The unused lane is 0 in both and passes.
  auto fits = [&](__m128d oLanes, __m128d dLanes) {
    const __m128d dInRange = _mm_and_pd(_mm_cmpge_pd(dLanes, least), _mm_cmple_pd(dLanes, limit));
    return _mm_and_pd(_mm_cmple_pd(oLanes, limit), _mm_or_pd(_mm_cmpeq_pd(dLanes, zero), dInRange));
  };
  return range.min >= 0.0 && maskPair(fits(o.xy, d.xy), fits(o.z0, d.z0)) == 0xf;
}

inline FloatRay::FloatRay(const Ray& ray) {
  const Pair o = loadPair(ray.origin), d = loadPair(ray.dir);
  const Pair absO = absPair(o);
  const __m128d largest2 = _mm_max_pd(absO.xy, absO.z0); // (max |x|,|z|; |y|)
  const __m128d largest = _mm_max_sd(largest2, _mm_unpackhi_pd(largest2, largest2));
  __m128d slack = _mm_add_sd(_mm_mul_sd(largest, _mm_set_sd(kFloatSlackPerCoordinate)),
                             _mm_set_sd(kFloatSlackFloor));
  slack = _mm_unpacklo_pd(slack, slack);
  // slackOrigin: the slack takes d's sign (a zero's too: its 1/d is an
  // infinity of that sign).
  const __m128d sign = _mm_set1_pd(-0.0);
  auto toward = [&](__m128d dLanes) { return _mm_or_pd(_mm_and_pd(dLanes, sign), slack); };
  const __m128d one = _mm_set1_pd(1.0);
  // x and y as a pair of floats (_mm_storel_pi), z alone.
  auto storeXY = [](float* out, __m128d xy) {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), _mm_cvtpd_ps(xy));
  };
  auto storeZ = [](float* out, __m128d z) { _mm_store_ss(out + 2, _mm_cvtpd_ps(z)); };
  storeXY(nearOrigin, _mm_add_pd(o.xy, toward(d.xy)));
  storeXY(farOrigin, _mm_sub_pd(o.xy, toward(d.xy)));
  const __m128d invXY = _mm_div_pd(one, d.xy), invZ = _mm_div_sd(one, d.z0);
  storeXY(nearInv, _mm_mul_pd(invXY, _mm_set1_pd(kWidenDown)));
  storeXY(farInv, _mm_mul_pd(invXY, _mm_set1_pd(kWidenUp)));
  storeZ(nearOrigin, _mm_add_sd(o.z0, toward(d.z0)));
  storeZ(farOrigin, _mm_sub_sd(o.z0, toward(d.z0)));
  storeZ(nearInv, _mm_mul_sd(invZ, _mm_set_sd(kWidenDown)));
  storeZ(farInv, _mm_mul_sd(invZ, _mm_set_sd(kWidenUp)));
  const unsigned negative = maskPair(d.xy, d.z0);
  for (int a = 0; a < 3; ++a) {
    const std::size_t bit = negative >> a & 1u;
    nearOffset[a] = (2 * std::size_t(a) + bit) * sizeof(Bvh::Node::bounds[0]);
    farOffset[a] = (2 * std::size_t(a) + 1 - bit) * sizeof(Bvh::Node::bounds[0]);
  }
}
#else
inline bool FloatRay::suits(const Ray& ray, Interval range) {
  bool fits = range.min >= 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::abs(ray.dir[a]);
    fits &= std::abs(ray.origin[a]) <= kFloatTestLimit &&
            (d == 0.0 || (d >= 1.0 / kFloatTestLimit && d <= kFloatTestLimit));
  }
  return fits;
}

inline FloatRay::FloatRay(const Ray& ray) {
  const double slack = kFloatSlackPerCoordinate * maxAbsComponent(ray.origin) + kFloatSlackFloor;
  for (int a = 0; a < 3; ++a) {
    // (signbit: a zero component's 1/d is an infinity of its sign.)
    const bool negative = std::signbit(ray.dir[a]);
    const SlackOrigin o = slackOrigin(ray.origin[a], negative ? -1.0 : 1.0, slack);
    nearOrigin[a] = float(o.near);
    farOrigin[a] = float(o.far);
    nearInv[a] = float(1.0 / ray.dir[a] * kWidenDown);
    farInv[a] = float(1.0 / ray.dir[a] * kWidenUp);
    const std::size_t bit = negative ? 1 : 0;
    nearOffset[a] = (2 * std::size_t(a) + bit) * sizeof(Bvh::Node::bounds[0]);
    farOffset[a] = (2 * std::size_t(a) + 1 - bit) * sizeof(Bvh::Node::bounds[0]);
  }
}
#endif

#if PRISM_BVH_AVX
// FloatNodeTest's arithmetic on all eight boxes in one AVX register: the
// same per-ray values (FloatRay) and the same operations in the same order on
// each box, so the same answers. Only code compiled for AVX may use it
// (Bvh::walkAvx).
class AvxFloatNodeTest {
public:
  using Time = float;
  using PacketLanes = AvxLanes; // the walk is compiled for AVX

  [[gnu::target("avx")]] explicit AvxFloatNodeTest(const Ray& ray) {
    const FloatRay f(ray);
    for (int a = 0; a < 3; ++a) {
      nearOrigin_[a] = _mm256_broadcast_ss(&f.nearOrigin[a]);
      farOrigin_[a] = _mm256_broadcast_ss(&f.farOrigin[a]);
      nearInv_[a] = _mm256_broadcast_ss(&f.nearInv[a]);
      farInv_[a] = _mm256_broadcast_ss(&f.farInv[a]);
      nearOffset_[a] = f.nearOffset[a];
      farOffset_[a] = f.farOffset[a];
    }
    widenTiny_ = _mm256_set1_ps(kWidenTiny);
    asm("" : "+x"(widenTiny_));
  }

  [[gnu::target("avx")]] void setRange(Interval range) {
    rangeMinWide_ = _mm256_set1_ps(floatRangeMin(range.min));
    setRangeMax(range.max);
  }
  [[gnu::target("avx")]] void setRangeMax(double max) {
    rangeMaxWide_ = _mm256_set1_ps(floatRangeMax(max));
  }

  [[gnu::target("avx")]] unsigned meet(const Bvh::Node& node, float (&tEnter)[Bvh::kWidth]) const {
    __m256 tNear = rangeMinWide_;
    __m256 tFar = rangeMaxWide_;
    for (int a = 0; a < 3; ++a) {
      const __m256 t0 = _mm256_mul_ps(
          _mm256_sub_ps(_mm256_load_ps(boundsRow(node, nearOffset_[a])), nearOrigin_[a]),
          nearInv_[a]);
      const __m256 t1 = _mm256_mul_ps(
          _mm256_sub_ps(_mm256_load_ps(boundsRow(node, farOffset_[a])), farOrigin_[a]), farInv_[a]);
      tNear = _mm256_max_ps(t0, tNear); // maxps and minps as in the SSE test
      tFar = _mm256_min_ps(t1, tFar);
    }
    tNear = _mm256_sub_ps(tNear, widenTiny_);
    _mm256_storeu_ps(tEnter, tNear);
    return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(tNear, tFar, _CMP_LE_OQ)));
  }

private:
  __m256 nearOrigin_[3], farOrigin_[3], nearInv_[3], farInv_[3];
  __m256 rangeMinWide_, rangeMaxWide_;
  // Kept beside the ray's values so that the node test reads it as a memory
  // operand, not broadcast anew from a constant at every node.
  __m256 widenTiny_;
  std::size_t nearOffset_[3], farOffset_[3];
};
#endif

// Leaves' runs of up to four triangles, or of up to four polygons of up to
// kPacketPolygonVertices vertices tested in the ray's frame, are tested at once
// (core/accel/packets.h); a run of one too, since the packet test, with its
// data stored in leaf order, costs less than the scalar one. A run's length,
// from refs[0] on (at most `left`): up to 4 references of one such kind.
bool packsTriangle(const Scene&, std::uint32_t code) {
  return code >> kKindShift == std::uint32_t(kindOf<Triangle>);
}
bool packsPolygon(const Scene& scene, std::uint32_t code) {
  if (code >> kKindShift != std::uint32_t(kindOf<Polygon>)) return false;
  const Polygon& p = scene.shapes<Polygon>()[code & kIndexMask];
  return p.rayFrameTest && p.vertexCount <= kPacketPolygonVertices;
}
template <class Packs>
int runOf(const Scene& scene, const std::uint32_t* refs, std::uint32_t left, Packs packs) {
  int run = 0;
  while (run < 4 && std::uint32_t(run) < left && packs(scene, refs[run]))
    ++run;
  return run;
}

// What testLeafPrimitive does with each of a packet's primitives in turn,
// done with their hits (bits of `hits`, at t) in the same order. Testing all
// against the range they started with finds the same: a closest-hit walk's
// keepNearest refuses a later hit beyond an earlier one, as the narrowed
// range would have.
template <bool AnyHit>
bool offerPacketHits(const std::uint32_t* refs, unsigned hits, const double (&t)[4],
                     Interval& range, const PrimitiveRef* skip, bool& found, Hit* hit) {
  for (unsigned m = hits; m != 0; m &= m - 1) {
    const int lane = std::countr_zero(m);
    const PrimitiveRef prim = decodeRef(refs[lane]);
    if (skip != nullptr && prim == *skip) continue;
    if constexpr (AnyHit) {
      if (hit != nullptr) *hit = {t[lane], prim};
      return true;
    } else {
      keepNearest({t[lane], prim}, found, *hit, range);
    }
  }
  return false;
}

constexpr std::size_t kLocalStack = 256; // traversal stack entries kept on the machine stack

// The children waiting to be visited, each with where it is first entered
// (Entry::t). On the machine stack unless the tree is deeper than that allows.
template <class Entry> class TraversalStack {
public:
  explicit TraversalStack(int treeDepth) {
    if (const std::size_t need = std::size_t(Bvh::kWidth - 1) * std::size_t(treeDepth) + 1;
        need > kLocalStack) [[unlikely]] {
      heap_ = std::make_unique<Entry[]>(need);
      entries_ = heap_.get();
    }
  }

  // Sorts the n (at most 8) children just met nearest first, keeps all but the
  // nearest, farthest deepest, and returns the nearest, to descend into at once.
  Entry pushAllButNearest(Entry* children, int n) {
    for (int i = 1; i < n; ++i)
      for (int j = i; j > 0 && children[j].t < children[j - 1].t; --j)
        std::swap(children[j], children[j - 1]);
    for (int i = n - 1; i > 0; --i)
      entries_[top_++] = children[i];
    return children[0];
  }

  void push(const Entry& entry) { entries_[top_++] = entry; }

  // The nearest waiting child that starts at or before `limit` (at exactly it
  // too, for the tie-break of keepNearest); the others are dropped on the way.
  bool pop(double limit, Entry& next) {
    while (top_ > 0) {
      next = entries_[--top_];
      if (next.t <= limit) return true;
    }
    return false;
  }

private:
  Entry local_[kLocalStack];
  std::unique_ptr<Entry[]> heap_; // only for trees deeper than the local stack allows
  Entry* entries_ = local_;
  std::size_t top_ = 0;
};

// Single-precision bounds that contain the double-precision ones.
float roundDown(double x) {
  float f = float(x);
  if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}
float roundUp(double x) {
  float f = float(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

} // namespace

struct Bvh::BuildContext {
  const SahTree& tree;
  const std::vector<BoxedPrimitive>& boxed;
  std::size_t leaves = 0, leavesWithRuns = 0;
};

// A scene takes the walk with packets where at least this share of its
// leaves hold runs: with fewer (spheres on one floor polygon) the few runs do
// not pay for the walk's dearer leaves, which cost such a scene of
// spheres 5% more instructions.
constexpr std::size_t kLeavesPerLeafWithRuns = 16;

Bvh::Bvh(const Scene& scene, Options options) : scene_(scene) {
#if PRISM_BVH_AVX
  avx_ = options.avx && __builtin_cpu_supports("avx");
#endif
  const std::size_t primitiveCount = scene.primitiveCount();
  if (primitiveCount == 0) return;
  if (primitiveCount > kFirstMask) throw std::length_error("too many primitives for the BVH");
  // Slices of long cones (primitive_boxes.h): at most half as many again as
  // there are primitives, and within the memory bound (see Options).
  build(hierarchyBoxes(scene, std::min(primitiveCount / 2, kFirstMask - primitiveCount)));
  if (options.maxBytesPerPrimitive > 0 && referenceCount() > primitiveCount &&
      hierarchyBytes() > options.maxBytesPerPrimitive * primitiveCount) {
    nodes_.clear();
    refs_.clear();
    runs_.clear();
    packetData_.clear();
    depth_ = 0;
    packetRuns_ = false;
    build(hierarchyBoxes(scene, 0));
  }
}

void Bvh::build(const std::vector<BoxedPrimitive>& boxed) {
  std::vector<Aabb> boxes;
  boxes.reserve(boxed.size());
  for (const BoxedPrimitive& b : boxed)
    boxes.push_back(b.box);
  SahOptions options;
  options.maxLeaf = std::min<std::uint32_t>(options.maxLeaf, kMaxLeaf);
  // The triangles, which a leaf tests four at a time (emitLeaf), count four
  // to a packet, and a packet of one to four about one and a half single
  // tests (packets.h): of 1.0, 1.5 and 2.0, 1.5 made the one-ray walk
  // fastest on the teapot and the height field (docs/performance.md).
  // Polygons, packed too, still count one by one: so counted, the small
  // ones made the leaves of tree.sc, glass.sc and table.sc larger and their
  // bundled eye rays up to 30% slower. (Where the walk then packs no runs,
  // packetRuns_ below, the scene has few triangles, whose cost was a little
  // off.)
  std::vector<bool> packed(boxed.size());
  for (std::size_t i = 0; i < boxed.size(); ++i)
    packed[i] = packsTriangle(scene_, encodeRef(boxed[i].primitive));
  options.packetSize = 4;
  options.packetCost = 1.5;
  const SahTree tree = buildSahTree(boxes, options, packed);

  refs_.reserve(boxed.size());
  // An 8-wide tree has about a seventh as many nodes as the binary one has
  // leaves (and it has about half as many leaves as nodes).
  nodes_.reserve(tree.nodes.size() / 14 + 1);
  BuildContext context{tree, boxed};
  collapse(context, 0, 1);
  packetRuns_ = context.leavesWithRuns > 0 &&
                context.leavesWithRuns * kLeavesPerLeafWithRuns >= context.leaves;
  if (packetRuns_) {
    packetData_.resize(packetData_.size() + kPacketPadding, 0.0);
  } else {
    runs_ = {};
    packetData_ = {};
  }
}

// Appends binary leaf `n`'s primitives to refs_, each once (two slices of one
// cone may share a leaf), and returns the child reference that names them.
std::uint32_t Bvh::emitLeaf(BuildContext& context, const SahTree::Node& n) {
  const auto first = std::uint32_t(refs_.size());
  for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
    const std::uint32_t code = encodeRef(context.boxed[context.tree.order[i]].primitive);
    if (std::find(refs_.begin() + first, refs_.end(), code) == refs_.end()) refs_.push_back(code);
  }
  const auto count = std::uint32_t(refs_.size()) - first;
  std::uint32_t leaf = kLeafBit | (count - 1) << kCountShift | first;
  // The runs, greedily from the first reference on: triangles before polygons.
  runs_.resize(refs_.size());
  const std::uint32_t end = first + count;
  for (std::uint32_t i = first; i < end;) {
    const std::uint32_t* at = &refs_[i];
    int run = runOf(scene_, at, end - i, packsTriangle);
    const bool triangles = run >= 1;
    if (!triangles) run = runOf(scene_, at, end - i, packsPolygon);
    if (run == 0) {
      ++i;
      continue;
    }
    PacketRun& r = runs_[i];
    r.data = std::uint32_t(packetData_.size()); // (fits: see the static_assert)
    r.length = std::uint8_t(run);
    if (triangles) {
      const Triangle* shapes[4];
      for (int k = 0; k < run; ++k)
        shapes[k] = &scene_.shapes<Triangle>()[at[k] & kIndexMask];
      appendPacket(std::span(shapes, std::size_t(run)), scene_.arrays(), packetData_);
    } else {
      const Polygon* shapes[4];
      for (int k = 0; k < run; ++k)
        shapes[k] = &scene_.shapes<Polygon>()[at[k] & kIndexMask];
      r.polygonVertices = std::uint8_t(
          appendPacket(std::span(shapes, std::size_t(run)), scene_.arrays(), packetData_));
    }
    leaf |= kPacketsBit;
    i += std::uint32_t(run);
  }
  ++context.leaves;
  if ((leaf & kPacketsBit) != 0) ++context.leavesWithRuns;
  return leaf;
}

// Makes the node for binary node `b` and its descendants: the node's children
// are the (up to eight) binary descendants left after repeatedly opening the
// largest inner one. Returns the new node's index.
std::uint32_t Bvh::collapse(BuildContext& context, std::uint32_t b, int depth) {
  const SahTree& tree = context.tree;
  std::uint32_t kids[kWidth];
  int count = 0;
  if (tree.nodes[b].leaf()) {
    kids[count++] = b; // only for a root that is a leaf
  } else {
    kids[count++] = tree.nodes[b].left;
    kids[count++] = tree.nodes[b].right;
    while (count < kWidth) {
      int open = -1;
      double largest = -1.0;
      for (int i = 0; i < count; ++i) {
        const SahTree::Node& n = tree.nodes[kids[i]];
        if (!n.leaf() && n.box.halfArea() > largest) {
          largest = n.box.halfArea();
          open = i;
        }
      }
      if (open < 0) break;
      const SahTree::Node& n = tree.nodes[kids[open]];
      kids[open] = n.left;
      kids[count++] = n.right;
    }
  }

  const auto index = std::uint32_t(nodes_.size());
  nodes_.emplace_back();
  depth_ = std::max(depth_, depth);
  Node node;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < kWidth; ++i) {
      node.bounds[2 * axis][i] = std::numeric_limits<float>::infinity();
      node.bounds[2 * axis + 1][i] = -std::numeric_limits<float>::infinity();
    }
  for (int i = 0; i < kWidth; ++i)
    node.child[i] = 0;
  for (int i = 0; i < count; ++i) {
    const SahTree::Node& n = tree.nodes[kids[i]];
    Aabb box = n.box;
    // The same relative margin as every hierarchy here: round-off in a hit's t
    // must never put a primitive's hit outside its box.
    box.pad();
    for (int axis = 0; axis < 3; ++axis) {
      node.bounds[2 * axis][i] = roundDown(box.lo[axis]);
      node.bounds[2 * axis + 1][i] = roundUp(box.hi[axis]);
    }
    node.child[i] = n.leaf() ? emitLeaf(context, n) : collapse(context, kids[i], depth + 1);
  }
  nodes_[index] = node;
  return index;
}

template <bool AnyHit>
bool Bvh::traverse(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const {
  if (nodes_.empty()) return false;
  if (FloatNodeTest::suits(ray, range)) { // and so finite
    // Scenes without runs to pack in their leaves take a walk without the
    // packet tests, so they cost them nothing.
    if (avx_)
      return packetRuns_ ? walkAvx<AnyHit, true>(ray, range, skip, hit)
                         : walkAvx<AnyHit, false>(ray, range, skip, hit);
    return packetRuns_ ? walk<AnyHit, FloatNodeTest, true>(ray, range, skip, hit)
                       : walk<AnyHit, FloatNodeTest, false>(ray, range, skip, hit);
  }
  if (!isFinite(ray)) return false;
  // The rare rays that float cannot take test their primitives one by one:
  // the same answers, and fewer copies of the walk.
  return walk<AnyHit, DoubleNodeTest, false>(ray, range, skip, hit);
}

// What a walk does in a leaf: its primitives tested in order, runs of them
// together where the walk packs them.
template <bool AnyHit, bool Packets, class L>
bool Bvh::testLeaf(std::uint32_t leaf, const Ray& ray, Interval& range, const PrimitiveRef* skip,
                   bool& found, Hit* hit, std::optional<PacketTest<L>>& packets) const {
  const std::uint32_t first = leaf & kFirstMask;
  const std::uint32_t end = first + ((leaf >> kCountShift) & 0xf) + 1;
  // (A leaf without runs, in a scene with some, goes as in a scene without:
  // a sphere's leaf need not look its runs up.)
  if (!Packets || (leaf & kPacketsBit) == 0) {
    for (std::uint32_t i = first; i < end; ++i)
      if (testLeafPrimitive<AnyHit>(scene_, decodeRef(refs_[i]), ray, range, skip, found, hit))
        return true;
    return false;
  }
  for (std::uint32_t i = first; i < end;) {
    const PacketRun run = runs_[i];
    if (run.length == 0) {
      if (testLeafPrimitive<AnyHit>(scene_, decodeRef(refs_[i]), ray, range, skip, found, hit))
        return true;
      ++i;
      continue;
    }
    if (!packets) packets.emplace(ray);
    const double* data = &packetData_[run.data];
    const unsigned used = (1u << run.length) - 1;
    double t[4];
    const unsigned hits =
        run.polygonVertices == 0
            ? packets->hits(TriangleCorners{data, run.length}, used, range, t)
            : packets->hits(PolygonCorners{data, run.length, run.polygonVertices}, used, range, t);
    if (offerPacketHits<AnyHit>(&refs_[i], hits, t, range, skip, found, hit)) return true;
    i += run.length;
  }
  return false;
}

template <bool AnyHit, class NodeTest, bool Packets>
bool Bvh::walk(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const {
  NodeTest test(ray);
  struct Entry {
    std::uint32_t ref;
    typename NodeTest::Time t; // where the ray enters the child's box
  };
  TraversalStack<Entry> stack(depth_);
  test.setRange(range);
  // Set up at the first run to pack.
  std::optional<PacketTest<typename NodeTest::PacketLanes>> packets;
  bool found = false;
  Entry current{0, 0};
  for (;;) {
    const std::uint32_t ref = current.ref;
    if ((ref & kLeafBit) == 0) {
      const Node& node = nodes_[ref];
      typename NodeTest::Time tEnter[kWidth];
      unsigned hitMask = test.meet(node, tEnter);
      if (hitMask != 0) {
        // Most nodes are met in one or two children: those go without the
        // sort, in the order it would give (the lower index first on a tie).
        const int a = std::countr_zero(hitMask);
        hitMask &= hitMask - 1;
        if (hitMask == 0) {
          current = {node.child[a], tEnter[a]};
          continue;
        }
        if constexpr (AnyHit) {
          // Any blocker ends the walk, so there is no order to keep: the
          // children go in index order, unsorted (the range never narrows,
          // so none is dropped before it is visited).
          for (; hitMask != 0; hitMask &= hitMask - 1) {
            const int i = std::countr_zero(hitMask);
            stack.push({node.child[i], tEnter[i]});
          }
          current = {node.child[a], tEnter[a]};
          continue;
        }
        const int b = std::countr_zero(hitMask);
        hitMask &= hitMask - 1;
        if (hitMask == 0) {
          const bool bFirst = tEnter[b] < tEnter[a];
          const int nearer = bFirst ? b : a, farther = bFirst ? a : b;
          stack.push({node.child[farther], tEnter[farther]});
          current = {node.child[nearer], tEnter[nearer]};
          continue;
        }
        Entry hits[kWidth] = {{node.child[a], tEnter[a]}, {node.child[b], tEnter[b]}};
        int n = 2;
        for (; hitMask != 0; hitMask &= hitMask - 1) {
          const int i = std::countr_zero(hitMask);
          hits[n++] = {node.child[i], tEnter[i]};
        }
        current = stack.pushAllButNearest(hits, n);
        continue;
      }
    } else {
      const double rangeMax = range.max;
      if (testLeaf<AnyHit, Packets>(ref, ray, range, skip, found, hit, packets)) return true;
      // A nearer hit narrows the range (an any-hit walk has returned at its first).
      if constexpr (!AnyHit)
        if (range.max != rangeMax) test.setRangeMax(range.max);
    }
    // Next: the nearest waiting child that still starts before the nearest hit.
    if (!stack.pop(range.max, current)) return found;
  }
}

// The walk and everything it inlines compiled for AVX (flatten), so that the
// AVX test's meet may be inlined into it; the rest of the program keeps the
// baseline instruction set, and the constructor takes this path only where
// the processor (and the system, for the wide registers' state) has AVX. AVX
// brings no fused multiply-add, so the arithmetic is the same.
template <bool AnyHit, bool Packets>
#if PRISM_BVH_AVX
[[gnu::target("avx"), gnu::flatten]]
#endif
bool Bvh::walkAvx(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit* hit) const {
#if PRISM_BVH_AVX
  return walk<AnyHit, AvxFloatNodeTest, Packets>(ray, range, skip, hit);
#else
  return walk<AnyHit, FloatNodeTest, Packets>(ray, range, skip, hit); // never taken
#endif
}

// A bundle of rays from one origin walks the tree together. Each node's eight
// boxes are tested once for the whole bundle with interval arithmetic: on each
// axis the rays' reciprocal directions lie between the least and the greatest
// of them (all of one sign), so with c = bound - origin, c * inv lies between
// c * invLo and c * invHi, and rounding keeps that order. The bundle's entry
// (the smallest of those) is thus at or before every ray's own computed entry
// and its exit at or after every ray's exit: a box any ray of the bundle would
// enter is entered, exactly as the one-ray test decides. The boxes of leaves
// are then tested ray by ray with the one-ray test, and only the rays that
// enter a leaf test its primitives, so every ray gets closestHit's answer.
// Each waiting child carries the rays that may still enter it: where the
// scene's boxes grow smaller than the gaps between the rays, the rays are
// sorted out ray by ray there too, and the subtree is walked for those alone.
namespace {

// The largest extent of child c's box.
double boxWidth(const Bvh::Node& node, int c) {
  double width = 0.0;
  for (int a = 0; a < 3; ++a)
    width = std::max(width, double(node.bounds[2 * a + 1][c]) - double(node.bounds[2 * a][c]));
  return width;
}

} // namespace

std::uint64_t Bvh::traverseBundle(std::span<const Ray> rays, std::span<Hit> hits) const {
  const std::size_t count = rays.size();
  // Per ray, four at a time: 1/d on each axis and the end of the ray's range
  // (range.min is 0 for every ray). Lanes past `count` never enter a box.
  constexpr std::size_t kSlots = kMaxBundle + 4;
  double inv[3][kSlots], rangeMax[kSlots];
  const double slack = boxSlack(rays[0]); // the rays share their origin
  double nearOrigin[3], farOrigin[3];     // see slackOrigin
  Lanes bundleNear[3], bundleFar[3], invLo[3], invHi[3];
  int nearRow[3], farRow[3];
  // How far apart the rays are at distance t: about t * spread.
  double spread = 0.0;
  for (int a = 0; a < 3; ++a) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < count; ++i) {
      inv[a][i] = 1.0 / rays[i].dir[a];
      lo = std::min(lo, inv[a][i]);
      hi = std::max(hi, inv[a][i]);
    }
    std::fill(&inv[a][count], &inv[a][kSlots], 1.0);
    // Every ray of the bundle has lo's sign on this axis.
    const SlackOrigin o = slackOrigin(rays[0].origin[a], lo, slack);
    nearOrigin[a] = o.near;
    farOrigin[a] = o.far;
    bundleNear[a] = Lanes::splat(o.near);
    bundleFar[a] = Lanes::splat(o.far);
    invLo[a] = Lanes::splat(lo);
    invHi[a] = Lanes::splat(hi);
    nearRow[a] = 2 * a + (lo < 0.0 ? 1 : 0); // every ray has the sign of lo
    farRow[a] = 2 * a + (lo < 0.0 ? 0 : 1);
    // 1/d is monotonic on d's sign: the directions' range is 1/hi .. 1/lo.
    spread = std::max(spread, std::abs(1.0 / lo - 1.0 / hi));
  }
  std::fill(&rangeMax[0], &rangeMax[count], std::numeric_limits<double>::infinity());
  std::fill(&rangeMax[count], &rangeMax[kSlots], -std::numeric_limits<double>::infinity());
  std::uint64_t found = 0;
  double bundleMax = std::numeric_limits<double>::infinity(); // the largest rangeMax

  // The rays of `active` (a bit mask) that enter child c of `node`: the
  // one-ray test of DoubleNodeTest::meet, term for term, four rays at a time.
  auto raysEntering = [&](const Node& node, int c, std::uint64_t active) {
    double toNear[3], toFar[3];
    for (int a = 0; a < 3; ++a) {
      toNear[a] = double(node.bounds[nearRow[a]][c]) - nearOrigin[a];
      toFar[a] = double(node.bounds[farRow[a]][c]) - farOrigin[a];
    }
    std::uint64_t entering = 0;
    for (std::size_t i = 0; i < count; i += 4) {
      if ((active >> i & 0xf) == 0) continue;
      Lanes tNear = Lanes::splat(0.0), tFar = load(&rangeMax[i]);
      for (int a = 0; a < 3; ++a) {
        const Lanes invA = load(&inv[a][i]);
        tNear = maxOr(Lanes::splat(toNear[a]) * invA, tNear);
        tFar = minOr(Lanes::splat(toFar[a]) * invA, tFar);
      }
      entering |= std::uint64_t(lessEqualMask(tNear, tFar)) << i;
    }
    return entering & active;
  };

  struct Entry {
    std::uint32_t ref;
    double t;           // where the bundle may first enter the child's box
    std::uint64_t rays; // the rays that may enter it (for a leaf: that do)
  };
  TraversalStack<Entry> stack(depth_);
  Entry current{0, 0.0, count == kMaxBundle ? ~std::uint64_t(0) : (std::uint64_t(1) << count) - 1};
  for (;;) {
    if ((current.ref & kLeafBit) == 0) {
      const Node& node = nodes_[current.ref];
      unsigned mask = 0;
      double tEnter[kWidth];
      for (int h = 0; h < kWidth; h += 4) {
        Lanes tNear = Lanes::splat(0.0), tFar = Lanes::splat(bundleMax);
        for (int a = 0; a < 3; ++a) {
          const Lanes toNear = loadBounds(node.bounds[nearRow[a]] + h) - bundleNear[a];
          const Lanes toFar = loadBounds(node.bounds[farRow[a]] + h) - bundleFar[a];
          tNear = maxOr(minOr(toNear * invLo[a], toNear * invHi[a]), tNear);
          tFar = minOr(maxOr(toFar * invLo[a], toFar * invHi[a]), tFar);
        }
        mask |= lessEqualMask(tNear, tFar) << h;
        store(tEnter + h, tNear);
      }
      Entry next[kWidth];
      int n = 0;
      for (int c = 0; c < kWidth; ++c) {
        if ((mask >> c & 1u) == 0) continue;
        // A leaf's rays are found ray by ray; so are those of a box narrower
        // than the bundle where the bundle meets it, which most rays miss
        // (a wider box keeps its parent's rays, unchecked, as the test of
        // every ray there would cost more than it saves).
        std::uint64_t active = current.rays;
        const bool leaf = (node.child[c] & kLeafBit) != 0;
        if (leaf || boxWidth(node, c) < spread * tEnter[c]) {
          active = raysEntering(node, c, active);
          if (active == 0) continue;
        }
        next[n++] = {node.child[c], tEnter[c], active};
      }
      if (n > 0) {
        current = stack.pushAllButNearest(next, n);
        continue;
      }
    } else {
      const std::uint32_t begin = current.ref & kFirstMask;
      const std::uint32_t end = begin + ((current.ref >> kCountShift) & 0xf) + 1;
      if (packetRuns_ && (current.ref & kPacketsBit) != 0 && runs_[begin].length > 0 &&
          runs_[begin].polygonVertices == 0) {
        // A leaf of triangles: ray by ray with the walk's packets. The
        // hierarchy counts triangles four to a packet (build), so their
        // leaves hold more than the rest, and primitive by primitive, as
        // below, the teapot's and the height field's bundled eye rays ran
        // 20% to 30% slower (docs/performance.md). (A leaf whose first
        // reference is no triangle goes below: a leaf of several kinds is
        // rare where triangles are.)
        for (std::uint64_t m = current.rays; m != 0; m &= m - 1) {
          const auto i = std::size_t(std::countr_zero(m));
          Interval range{0.0, rangeMax[i]};
          bool rayFound = (found >> i & 1u) != 0;
          std::optional<PacketTest<Lanes>> packets;
          testLeaf<false, true>(current.ref, rays[i], range, nullptr, rayFound, &hits[i], packets);
          rangeMax[i] = range.max;
          if (rayFound) found |= std::uint64_t(1) << i;
        }
      } else {
        for (std::uint32_t p = begin; p < end; ++p) {
          const PrimitiveRef prim = decodeRef(refs_[p]);
          for (std::uint64_t m = current.rays; m != 0; m &= m - 1) {
            const auto i = std::size_t(std::countr_zero(m));
            Interval range{0.0, rangeMax[i]};
            double t;
            if (intersectPrimitive(scene_, prim, rays[i], range, t)) {
              bool rayFound = (found >> i & 1u) != 0;
              keepNearest({t, prim}, rayFound, hits[i], range);
              rangeMax[i] = range.max;
              found |= std::uint64_t(1) << i;
            }
          }
        }
      }
      bundleMax = *std::max_element(&rangeMax[0], &rangeMax[count]);
    }
    if (!stack.pop(bundleMax, current)) return found;
  }
}

bool walksTogether(std::span<const Ray> rays) {
  if (rays.size() < 2 || rays.size() > Accel::kMaxBundle) return false;
  for (const Ray& ray : rays) {
    for (int a = 0; a < 3; ++a) {
      const bool sameOrigin = ray.origin[a] == rays[0].origin[a];
      const bool sameSign = (ray.dir[a] < 0.0) == (rays[0].dir[a] < 0.0);
      // 1/d must be finite and not 0, or c * inv is a NaN where c is 0 (or
      // infinite): d finite and at least the smallest normal double (a
      // subnormal d, possibly fine, goes ray by ray too). A non-finite origin
      // goes ray by ray, where it hits nothing.
      const double d = std::abs(ray.dir[a]);
      if (!sameOrigin || !sameSign || !(d >= std::numeric_limits<double>::min()) || std::isinf(d) ||
          !std::isfinite(ray.origin[a]))
        return false;
    }
  }
  return true;
}

std::uint64_t Bvh::closestHits(std::span<const Ray> rays, std::span<Hit> hits) const {
  if (nodes_.empty() || !walksTogether(rays)) return Accel::closestHits(rays, hits);
  return traverseBundle(rays, hits);
}

// Every caller of closestHit and anyHit reaches the walk through these.
template bool Bvh::traverse<false>(const Ray&, Interval, const PrimitiveRef*, Hit*) const;
template bool Bvh::traverse<true>(const Ray&, Interval, const PrimitiveRef*, Hit*) const;

std::size_t Bvh::hierarchyBytes() const {
  return nodes_.size() * sizeof(Node) + refs_.size() * sizeof(std::uint32_t);
}

std::size_t Bvh::memoryBytes() const {
  return hierarchyBytes() + runs_.size() * sizeof(PacketRun) + packetData_.size() * sizeof(double);
}

} // namespace prism

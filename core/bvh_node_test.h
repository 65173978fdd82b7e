// The ray-box test of a BVH4 node and the packing of primitive references:
// internal to core/bvh.cpp.
#pragma once

#include "core/bvh.h"

#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prism::bvh_detail {

// Four double lanes, one per child box. With SSE2 (every x86-64) they are two
// register pairs written out, because GCC lowers 32-byte vector extensions
// poorly without AVX; elsewhere, GCC/Clang vector extensions.
#if defined(__SSE2__)
struct Lanes {
  __m128d lo, hi;
};
inline Lanes broadcast(double x) { return {_mm_set1_pd(x), _mm_set1_pd(x)}; }
inline Lanes loadBounds(const float* p) {
  const __m128 f = _mm_loadu_ps(p);
  return {_mm_cvtps_pd(f), _mm_cvtps_pd(_mm_movehl_ps(f, f))};
}
inline Lanes operator-(Lanes a, Lanes b) {
  return {_mm_sub_pd(a.lo, b.lo), _mm_sub_pd(a.hi, b.hi)};
}
inline Lanes operator*(Lanes a, Lanes b) {
  return {_mm_mul_pd(a.lo, b.lo), _mm_mul_pd(a.hi, b.hi)};
}
// a > b ? a : b and a < b ? a : b lane by lane: b wherever either is a NaN.
inline Lanes maxOr(Lanes a, Lanes b) { return {_mm_max_pd(a.lo, b.lo), _mm_max_pd(a.hi, b.hi)}; }
inline Lanes minOr(Lanes a, Lanes b) { return {_mm_min_pd(a.lo, b.lo), _mm_min_pd(a.hi, b.hi)}; }
// Bit i set where lane i of a <= b.
inline unsigned lessEqualMask(Lanes a, Lanes b) {
  return unsigned(_mm_movemask_pd(_mm_cmple_pd(a.lo, b.lo))) |
         unsigned(_mm_movemask_pd(_mm_cmple_pd(a.hi, b.hi))) << 2;
}
inline void store(double* out, Lanes a) {
  _mm_storeu_pd(out, a.lo);
  _mm_storeu_pd(out + 2, a.hi);
}
#else
// Internal and inlined, so GCC's note that such values are passed differently
// with AVX is moot.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
using Lanes = double __attribute__((vector_size(32)));
using LanesF = float __attribute__((vector_size(16)));
inline Lanes broadcast(double x) { return Lanes{x, x, x, x}; }
inline Lanes loadBounds(const float* p) {
  LanesF f;
  std::memcpy(&f, p, sizeof f);
  return __builtin_convertvector(f, Lanes);
}
inline Lanes maxOr(Lanes a, Lanes b) { return a > b ? a : b; }
inline Lanes minOr(Lanes a, Lanes b) { return a < b ? a : b; }
inline unsigned lessEqualMask(Lanes a, Lanes b) {
  const auto m = a <= b;
  unsigned mask = 0;
  for (int i = 0; i < 4; ++i)
    mask |= unsigned(m[i] != 0) << i;
  return mask;
}
inline void store(double* out, Lanes a) { std::memcpy(out, &a, sizeof a); }
#endif

constexpr std::uint32_t kKindShift = 29; // 3 bits of PrimitiveKind, 29 of index
constexpr std::uint32_t kIndexMask = (1u << kKindShift) - 1;

inline PrimitiveRef decodeRef(std::uint32_t code) {
  return {PrimitiveKind(code >> kKindShift), code & kIndexMask};
}

// One ray as the node test needs it: origin and reciprocal direction in every
// lane, and which bound of each axis the ray meets first (the lower one when
// travelling toward +axis).
struct NodeRay {
  Lanes origin[3];
  Lanes inv[3];
  int nearRow[3];
  int farRow[3];

  explicit NodeRay(const Ray& ray) {
    const Vec3 invDir = 1.0 / ray.dir;
    for (int a = 0; a < 3; ++a) {
      origin[a] = broadcast(ray.origin[a]);
      inv[a] = broadcast(invDir[a]);
      nearRow[a] = 2 * a + (invDir[a] < 0.0 ? 1 : 0);
      farRow[a] = 2 * a + (invDir[a] < 0.0 ? 0 : 1);
    }
  }

  // Where the ray enters each of the node's four child boxes (tNear), clipped
  // to `range`, and which children it meets inside `range` (tNear <= tFar).
  Lanes enter(const Bvh::Node& node, Interval range, Lanes& tFar) const {
    Lanes tNear = broadcast(range.min);
    tFar = broadcast(range.max);
    for (int a = 0; a < 3; ++a) {
      const Lanes t0 = (loadBounds(node.bounds[nearRow[a]]) - origin[a]) * inv[a];
      const Lanes t1 = (loadBounds(node.bounds[farRow[a]]) - origin[a]) * inv[a];
      // Written so a NaN (0 * inf, for a ray lying in a box's face plane)
      // leaves the range unchanged: that axis does not cull.
      tNear = maxOr(t0, tNear);
      tFar = minOr(t1, tFar);
    }
    return tNear;
  }
};

} // namespace prism::bvh_detail

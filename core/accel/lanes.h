// Four doubles worked on lane by lane: the hierarchy's tests of several boxes
// (or several triangles or polygons, core/accel/packets.h) at once. Each lane
// sees exactly the IEEE operation a scalar line would do on it (there is no
// fused multiply-add here), so a test written on lanes answers bit for bit as
// its scalar form.
//  - Lanes: two SSE2 registers (every x86-64), or GCC/Clang vector
//    extensions elsewhere;
//  - AvxLanes: one AVX register, for code compiled for AVX alone
//    ([[gnu::target("avx")]], chosen at run time: Bvh::walkAvx).
// A comparison gives a mask: lanes of all ones where it holds, else zeros;
// bits() turns one into bit i for lane i.
#pragma once

#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
// The one-ray walk compiled for AVX, chosen at run time (Bvh::walkAvx).
#if defined(__x86_64__) && defined(__SSE2__) && defined(__GNUC__)
#define PRISM_BVH_AVX 1
#include <immintrin.h>
#endif

namespace prism::lanes {

#if defined(__SSE2__)
// Written out as register pairs because GCC lowers 32-byte vector
// extensions poorly without AVX.
struct Lanes {
  __m128d lo, hi;

  static Lanes splat(double x) { return {_mm_set1_pd(x), _mm_set1_pd(x)}; }
  // Lane i is xi.
  static Lanes set(double x0, double x1, double x2, double x3) {
    return {_mm_set_pd(x1, x0), _mm_set_pd(x3, x2)};
  }
  // Lane i is p[i].
  static Lanes load(const double* p) { return {_mm_loadu_pd(p), _mm_loadu_pd(p + 2)}; }
};
inline Lanes loadBounds(const float* p) {
  const __m128 f = _mm_loadu_ps(p);
  return {_mm_cvtps_pd(f), _mm_cvtps_pd(_mm_movehl_ps(f, f))};
}
inline Lanes operator+(Lanes a, Lanes b) {
  return {_mm_add_pd(a.lo, b.lo), _mm_add_pd(a.hi, b.hi)};
}
inline Lanes operator-(Lanes a, Lanes b) {
  return {_mm_sub_pd(a.lo, b.lo), _mm_sub_pd(a.hi, b.hi)};
}
inline Lanes operator*(Lanes a, Lanes b) {
  return {_mm_mul_pd(a.lo, b.lo), _mm_mul_pd(a.hi, b.hi)};
}
inline Lanes operator/(Lanes a, Lanes b) {
  return {_mm_div_pd(a.lo, b.lo), _mm_div_pd(a.hi, b.hi)};
}
// a > b ? a : b and a < b ? a : b lane by lane: b wherever either is a NaN.
inline Lanes maxOr(Lanes a, Lanes b) { return {_mm_max_pd(a.lo, b.lo), _mm_max_pd(a.hi, b.hi)}; }
inline Lanes minOr(Lanes a, Lanes b) { return {_mm_min_pd(a.lo, b.lo), _mm_min_pd(a.hi, b.hi)}; }
// Comparisons, false where either is a NaN (notEqual: true there).
inline Lanes lessEqual(Lanes a, Lanes b) {
  return {_mm_cmple_pd(a.lo, b.lo), _mm_cmple_pd(a.hi, b.hi)};
}
inline Lanes less(Lanes a, Lanes b) { return {_mm_cmplt_pd(a.lo, b.lo), _mm_cmplt_pd(a.hi, b.hi)}; }
inline Lanes notEqual(Lanes a, Lanes b) {
  return {_mm_cmpneq_pd(a.lo, b.lo), _mm_cmpneq_pd(a.hi, b.hi)};
}
inline Lanes operator&(Lanes a, Lanes b) {
  return {_mm_and_pd(a.lo, b.lo), _mm_and_pd(a.hi, b.hi)};
}
inline Lanes operator|(Lanes a, Lanes b) { return {_mm_or_pd(a.lo, b.lo), _mm_or_pd(a.hi, b.hi)}; }
inline Lanes operator^(Lanes a, Lanes b) {
  return {_mm_xor_pd(a.lo, b.lo), _mm_xor_pd(a.hi, b.hi)};
}
inline Lanes equal(Lanes a, Lanes b) {
  return {_mm_cmpeq_pd(a.lo, b.lo), _mm_cmpeq_pd(a.hi, b.hi)};
}
// ~a & b.
inline Lanes andNot(Lanes a, Lanes b) {
  return {_mm_andnot_pd(a.lo, b.lo), _mm_andnot_pd(a.hi, b.hi)};
}
inline unsigned bits(Lanes mask) {
  return unsigned(_mm_movemask_pd(mask.lo)) | unsigned(_mm_movemask_pd(mask.hi)) << 2;
}
inline void store(double* out, Lanes a) {
  _mm_storeu_pd(out, a.lo);
  _mm_storeu_pd(out + 2, a.hi);
}
inline Lanes load(const double* p) { return {_mm_loadu_pd(p), _mm_loadu_pd(p + 2)}; }
#else
// Internal and inlined, so GCC's note that such values are passed differently
// with AVX is moot.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
using Vec4d = double __attribute__((vector_size(32)));
using Mask4 = long long __attribute__((vector_size(32)));
struct Lanes {
  Vec4d v;

  static Lanes splat(double x) { return {Vec4d{x, x, x, x}}; }
  static Lanes set(double x0, double x1, double x2, double x3) { return {Vec4d{x0, x1, x2, x3}}; }
  static Lanes load(const double* p) {
    Lanes r;
    std::memcpy(&r.v, p, sizeof r.v);
    return r;
  }
};
// A mask's lanes (0 or -1) kept in a Lanes, bit for bit.
inline Lanes fromMask(Mask4 m) { return {reinterpret_cast<Vec4d>(m)}; }
inline Mask4 toMask(Lanes a) { return reinterpret_cast<Mask4>(a.v); }
// What both widths share (bvh.cpp's float lanes too): a load from memory and
// a comparison's bits.
template <class V, class T> inline V loadLanes(const T* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class M> inline unsigned maskBits(M m) {
  unsigned mask = 0;
  for (int i = 0; i < 4; ++i)
    mask |= unsigned(m[i] != 0) << i;
  return mask;
}
inline Lanes loadBounds(const float* p) {
  using Vec4f = float __attribute__((vector_size(16)));
  return {__builtin_convertvector(loadLanes<Vec4f>(p), Vec4d)};
}
inline Lanes operator+(Lanes a, Lanes b) { return {a.v + b.v}; }
inline Lanes operator-(Lanes a, Lanes b) { return {a.v - b.v}; }
inline Lanes operator*(Lanes a, Lanes b) { return {a.v * b.v}; }
inline Lanes operator/(Lanes a, Lanes b) { return {a.v / b.v}; }
inline Lanes maxOr(Lanes a, Lanes b) { return {a.v > b.v ? a.v : b.v}; }
inline Lanes minOr(Lanes a, Lanes b) { return {a.v < b.v ? a.v : b.v}; }
inline Lanes lessEqual(Lanes a, Lanes b) { return fromMask(a.v <= b.v); }
inline Lanes less(Lanes a, Lanes b) { return fromMask(a.v < b.v); }
inline Lanes notEqual(Lanes a, Lanes b) { return fromMask(a.v != b.v); }
inline Lanes operator&(Lanes a, Lanes b) { return fromMask(toMask(a) & toMask(b)); }
inline Lanes operator|(Lanes a, Lanes b) { return fromMask(toMask(a) | toMask(b)); }
inline Lanes operator^(Lanes a, Lanes b) { return fromMask(toMask(a) ^ toMask(b)); }
inline Lanes equal(Lanes a, Lanes b) { return fromMask(a.v == b.v); }
inline Lanes andNot(Lanes a, Lanes b) { return fromMask(~toMask(a) & toMask(b)); }
inline unsigned bits(Lanes mask) { return maskBits(toMask(mask)); }
inline void store(double* out, Lanes a) { std::memcpy(out, &a.v, sizeof a.v); }
inline Lanes load(const double* p) { return {loadLanes<Vec4d>(p)}; }
#endif

// a <= b lane by lane, as bits.
inline unsigned lessEqualMask(Lanes a, Lanes b) { return bits(lessEqual(a, b)); }

#if PRISM_BVH_AVX
// The same four lanes in one AVX register, for code compiled for AVX. The
// operations are compiled for AVX and meant to be inlined into such code
// (Bvh::walkAvx, flatten); where a compiler leaves one out of line, the
// lanes still pass safely: they are held as four doubles, which every
// caller passes in memory, where an AVX register itself is passed one way
// by code compiled for AVX and another by code compiled without.
struct AvxLanes {
  double x[4];

  [[gnu::target("avx")]] static AvxLanes splat(double a) { return of(_mm256_set1_pd(a)); }
  [[gnu::target("avx")]] static AvxLanes set(double x0, double x1, double x2, double x3) {
    return of(_mm256_set_pd(x3, x2, x1, x0));
  }
  // Lane i is p[i].
  [[gnu::target("avx")]] static AvxLanes load(const double* p) { return of(_mm256_loadu_pd(p)); }
  [[gnu::target("avx")]] static AvxLanes of(__m256d v) {
    AvxLanes r;
    _mm256_storeu_pd(r.x, v);
    return r;
  }
  [[gnu::target("avx")]] __m256d v() const { return _mm256_loadu_pd(x); }
};
[[gnu::target("avx")]] inline AvxLanes operator+(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_add_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes operator-(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_sub_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes operator*(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_mul_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes operator/(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_div_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes lessEqual(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_cmp_pd(a.v(), b.v(), _CMP_LE_OQ));
}
[[gnu::target("avx")]] inline AvxLanes less(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_cmp_pd(a.v(), b.v(), _CMP_LT_OQ));
}
[[gnu::target("avx")]] inline AvxLanes notEqual(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_cmp_pd(a.v(), b.v(), _CMP_NEQ_UQ));
}
[[gnu::target("avx")]] inline AvxLanes operator&(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_and_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes operator|(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_or_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes operator^(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_xor_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline AvxLanes equal(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_cmp_pd(a.v(), b.v(), _CMP_EQ_OQ));
}
[[gnu::target("avx")]] inline AvxLanes andNot(AvxLanes a, AvxLanes b) {
  return AvxLanes::of(_mm256_andnot_pd(a.v(), b.v()));
}
[[gnu::target("avx")]] inline unsigned bits(AvxLanes mask) {
  return unsigned(_mm256_movemask_pd(mask.v()));
}
[[gnu::target("avx")]] inline void store(double* out, AvxLanes a) { _mm256_storeu_pd(out, a.v()); }
#endif

} // namespace prism::lanes

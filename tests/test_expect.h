// Checks shared by the tests: vectors within a tolerance, the errors of a
// scene text that must not parse, and the hierarchies against brute force.
#pragma once

#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/math/math.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <string_view>

namespace prism::test {

// A direction drawn uniformly from the unit sphere.
inline Vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 d;
  do
    d = Vec3(n(rng), n(rng), n(rng));
  while (glm::dot(d, d) < 1e-6);
  return glm::normalize(d);
}

// Each component of `got` within `tolerance` of `want`.
inline void expectVecNear(const Vec3& got, const Vec3& want, double tolerance) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

// `got` within `tolerance` of `want` in Euclidean distance.
inline void expectCloseTo(const Vec3& got, const Vec3& want, double tolerance = 1e-12) {
  EXPECT_NEAR(glm::length(got - want), 0.0, tolerance)
      << "(" << got.x << ", " << got.y << ", " << got.z << ") vs (" << want.x << ", " << want.y
      << ", " << want.z << ")";
}

// All diagnostics of a scene text that must fail, formatted and joined by
// '\n'; "" when it parses.
inline std::string sceneErrorsOf(std::string_view text, const std::string& name = "t.sc") {
  try {
    parseScene(text, name);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// The hierarchies report exactly the hits brute force does (the primitive and
// t of the nearest, and whether any), for `count` rays from points within
// +-2 `span` of the origin in random directions. Returns how many hit.
inline int expectAccelsAgreeWithBruteForce(const Scene& s, double span, int count) {
  const auto none = makeAccel(s, AccelKind::None);
  std::uniform_real_distribution<double> u(-span, span);
  int hits = 0;
  for (const AccelKind kind : {AccelKind::Bvh, AccelKind::Groups}) {
    const auto accel = makeAccel(s, kind);
    std::mt19937 rays(11);
    for (int i = 0; i < count; ++i) {
      const Ray q{Vec3(u(rays), u(rays), u(rays)) * 2.0,
                  glm::normalize(Vec3(u(rays), u(rays), u(rays)))};
      Hit a, b;
      const bool ha = none->closestHit(q, Interval{}, nullptr, a);
      const bool hb = accel->closestHit(q, Interval{}, nullptr, b);
      EXPECT_EQ(ha, hb) << accelKindName(kind) << " ray " << i;
      if (ha != hb) return hits;
      if (ha) {
        ++hits;
        EXPECT_EQ(a.primitive, b.primitive);
        EXPECT_EQ(a.t, b.t);
      }
      EXPECT_EQ(none->anyHit(q, Interval{}, nullptr), accel->anyHit(q, Interval{}, nullptr));
    }
  }
  return hits;
}

} // namespace prism::test

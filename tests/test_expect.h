// Checks shared by the tests: vectors within a tolerance, and the errors of a
// scene text that must not parse.
#pragma once

#include "core/io/scene_parser.h"
#include "core/math/math.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace prism::test {

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

} // namespace prism::test

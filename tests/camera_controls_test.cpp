// Camera navigation of the previewer: orbit, pan and zoom keep the properties a
// user relies on, and projectToScreen is the inverse of Camera::eyeRay (so the
// light markers sit where the lights are drawn).
#include "viewer/camera_controls.h"

#include "tests/test_expect.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

CameraSpec tilted() {
  CameraSpec c;
  c.eye = Vec3(3.0, 4.0, 9.0);
  c.lookat = Vec3(0.5, 1.0, -1.0);
  c.up = Vec3(0.0, 1.0, 0.0);
  c.fov = 50.0;
  return c;
}

TEST(CameraControls, OrbitKeepsDistanceAndLookat) {
  const CameraSpec c = tilted();
  const double distance = glm::length(c.eye - c.lookat);
  for (double yaw : {-170.0, -30.0, 0.0, 10.0, 90.0}) {
    for (double pitch : {-40.0, 0.0, 25.0}) {
      const CameraSpec o = orbit(c, yaw, pitch);
      EXPECT_NEAR(glm::length(o.eye - o.lookat), distance, 1e-9 * distance);
      EXPECT_EQ(o.lookat, c.lookat);
      EXPECT_EQ(o.up, c.up);
      EXPECT_EQ(o.fov, c.fov);
    }
  }
}

TEST(CameraControls, YawTurnsAboutUpAndFullCircleReturns) {
  const CameraSpec c = tilted();
  const CameraSpec o = orbit(c, 37.0, 0.0);
  // Height above lookat along up is unchanged by yaw.
  EXPECT_NEAR(o.eye.y, c.eye.y, 1e-9);
  test::expectVecNear(orbit(c, 360.0, 0.0).eye, c.eye, 1e-9);
  test::expectVecNear(orbit(orbit(c, 25.0, 0.0), -25.0, 0.0).eye, c.eye, 1e-9);
  // From +z, a positive yaw (right-handed about +y) takes the eye toward +x.
  CameraSpec front;
  EXPECT_GT(orbit(front, 30.0, 0.0).eye.x, 0.0);
}

TEST(CameraControls, PitchRaisesTheEyeAndStopsShortOfThePoles) {
  CameraSpec front; // eye (0, 0, 5) looking at the origin, up +y
  const CameraSpec up30 = orbit(front, 0.0, 30.0);
  EXPECT_NEAR(up30.eye.y, 5.0 * std::sin(glm::radians(30.0)), 1e-9);
  EXPECT_NEAR(up30.eye.z, 5.0 * std::cos(glm::radians(30.0)), 1e-9);
  for (double pitch : {89.5, 90.0, 200.0, -95.0, -1000.0}) {
    const CameraSpec o = orbit(front, 0.0, pitch);
    const Vec3 view = glm::normalize(o.lookat - o.eye);
    // At least 1 degree away from up: the camera stays well defined.
    EXPECT_LE(std::abs(glm::dot(view, glm::normalize(o.up))), std::cos(glm::radians(1.0)) + 1e-12)
        << pitch;
    EXPECT_TRUE(isFinite(Camera(o, 64, 48).eyeRay(3.0, 5.0).dir)) << pitch;
  }
}

TEST(CameraControls, PanMovesEyeAndLookatTogetherAndFollowsTheMouse) {
  const CameraSpec c = tilted();
  const int w = 320, h = 200;
  const CameraSpec p = pan(c, 40.0, -25.0, h);
  test::expectVecNear(p.eye - c.eye, p.lookat - c.lookat, 1e-9);
  // A point at the old lookat moves on screen by the mouse's motion.
  const auto before = projectToScreen(c, w, h, c.lookat);
  const auto after = projectToScreen(p, w, h, c.lookat);
  ASSERT_TRUE(before && after);
  EXPECT_NEAR(after->x - before->x, 40.0, 1e-6);
  EXPECT_NEAR(after->y - before->y, -25.0, 1e-6);
}

TEST(CameraControls, ZoomScalesTheDistanceAndNeverReachesLookat) {
  const CameraSpec c = tilted();
  const double distance = glm::length(c.eye - c.lookat);
  const CameraSpec in = zoom(c, 0.5);
  EXPECT_NEAR(glm::length(in.eye - in.lookat), 0.5 * distance, 1e-12);
  test::expectVecNear(glm::normalize(in.eye - in.lookat), glm::normalize(c.eye - c.lookat), 1e-9);
  test::expectVecNear(zoom(in, 2.0).eye, c.eye, 1e-9);
  for (double factor : {0.0, -3.0, 1e-300}) {
    const CameraSpec z = zoom(c, factor);
    EXPECT_GT(glm::length(z.eye - z.lookat), 0.0) << factor;
    EXPECT_TRUE(isFinite(Camera(z, 8, 8).eyeRay(1.0, 2.0).dir)) << factor;
  }
}

TEST(CameraControls, ProjectionInvertsEyeRays) {
  const CameraSpec c = tilted();
  const int w = 640, h = 480;
  const Camera camera(c, w, h);
  for (double sx : {0.0, 0.5, 123.25, 320.0, 639.5, 640.0}) {
    for (double sy : {0.0, 17.5, 240.0, 479.5}) {
      const Ray ray = camera.eyeRay(sx, sy);
      for (double t : {0.1, 3.0, 250.0}) {
        const auto p = projectToScreen(c, w, h, ray.at(t));
        ASSERT_TRUE(p);
        EXPECT_NEAR(p->x, sx, 1e-7);
        EXPECT_NEAR(p->y, sy, 1e-7);
      }
    }
  }
  EXPECT_FALSE(projectToScreen(c, w, h, c.eye - (c.lookat - c.eye))); // behind the eye
  EXPECT_FALSE(projectToScreen(c, w, h, c.eye));
}

} // namespace
} // namespace prism

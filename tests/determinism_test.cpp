// The same inputs give the same picture and the same counts whatever the number
// of threads and the tile size (which changes the order of work).
#include "core/renderer.h"
#include "core/scene_parser.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

RenderResult renderWith(const Scene& scene, const Accel& accel, int threads, int tileSize,
                        bool jitter) {
  RenderSettings s;
  s.width = 96;
  s.height = 72;
  s.maxDepth = 6;
  s.thresh = 0.05;
  s.jitter = jitter;
  s.threads = threads;
  s.tileSize = tileSize;
  return render(scene, accel, s);
}

void expectIdentical(const RenderResult& a, const RenderResult& b) {
  EXPECT_EQ(a.avgmax, b.avgmax);
  EXPECT_EQ(a.counts, b.counts);
  EXPECT_EQ(a.supersampledPixels, b.supersampledPixels);
  ASSERT_EQ(a.film.radiance.size(), b.film.radiance.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.film.radiance.size(); ++i)
    differing += a.film.radiance[i] != b.film.radiance[i];
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(a.film.supersampled, b.film.supersampled);
}

class Determinism : public ::testing::TestWithParam<const char*> {};

TEST_P(Determinism, OneThreadEqualsManyThreads) {
  const Scene scene = loadScene(std::string(PRISM_SOURCE_DIR) + "/scenes/" + GetParam());
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  for (bool jitter : {false, true}) {
    const RenderResult one = renderWith(scene, *accel, 1, 32, jitter);
    EXPECT_GT(one.supersampledPixels, 0);
    expectIdentical(one, renderWith(scene, *accel, 2, 32, jitter));
    expectIdentical(one, renderWith(scene, *accel, 5, 7, jitter));
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, Determinism,
                         ::testing::Values("table.sc", "glass.sc", "chex.sc"));

TEST(Determinism, AccelerationDoesNotChangeThePicture) {
  const Scene scene = loadScene(std::string(PRISM_SOURCE_DIR) + "/scenes/glass.sc");
  const auto bvh = makeAccel(scene, AccelKind::Bvh);
  const auto groups = makeAccel(scene, AccelKind::Groups);
  const auto none = makeAccel(scene, AccelKind::None);
  const RenderResult reference = renderWith(scene, *none, 2, 32, false);
  expectIdentical(reference, renderWith(scene, *groups, 2, 32, false));
  expectIdentical(reference, renderWith(scene, *bvh, 2, 32, false));
}

TEST(Determinism, BvhAndGroupsGiveTheSamePictureOfEveryShippedScene) {
  for (const char* name : {"table.sc", "chex.sc", "tree.sc"}) {
    const Scene scene = loadScene(std::string(PRISM_SOURCE_DIR) + "/scenes/" + name);
    const auto bvh = makeAccel(scene, AccelKind::Bvh);
    const auto groups = makeAccel(scene, AccelKind::Groups);
    SCOPED_TRACE(name);
    expectIdentical(renderWith(scene, *groups, 2, 32, false),
                    renderWith(scene, *bvh, 2, 32, false));
  }
}

} // namespace
} // namespace prism

// The same inputs give the same picture and the same counts whatever the number
// of threads and the tile size (which changes the order of work).
#include "core/io/scene_parser.h"
#include "core/render/renderer.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "counting_accel.h"

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

// That no hierarchy changes a picture against brute force (glass.sc and the
// other small scenes, every accel kind, one and two threads) is held by
// RadianceFingerprint.SameUnderEveryAccelAndThreadCount.

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

class BlockerCache : public ::testing::TestWithParam<const char*> {};

// The tracer's memory of the last shadow blocker answers some shadow rays
// without the Accel, and every answer is the one the Accel alone gives.
TEST_P(BlockerCache, SameRadianceAndCountsWithFewerAccelQueries) {
  const Scene scene = loadScene(std::string(PRISM_SOURCE_DIR) + "/scenes/" + GetParam());
  const auto bvh = makeAccel(scene, AccelKind::Bvh);
  const test::CountingAccel cached(*bvh), uncached(*bvh);
  const int depth = 6;
  Tracer withCache(scene, cached, depth, Tracer::BlockerCache::On);
  Tracer without(scene, uncached, depth, Tracer::BlockerCache::Off);
  const Camera camera(scene.camera, 120, 90);
  RayCounts countsWith, countsWithout;
  long long differing = 0;
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 120; ++x) {
      const Ray ray = camera.eyeRay(x + 0.5, y + 0.5);
      differing += withCache.trace(ray, 1, countsWith) != without.trace(ray, 1, countsWithout);
    }
  EXPECT_EQ(differing, 0);
  EXPECT_EQ(countsWith, countsWithout);
  // Every shadow ray reaches the Accel without the cache; with it, fewer do.
  EXPECT_EQ(uncached.anyHits.load(), (long long)countsWithout.shadow);
  EXPECT_GT(countsWithout.shadow, 1000);
  EXPECT_LT(cached.anyHits.load(), uncached.anyHits.load());
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, BlockerCache,
                         ::testing::Values("table.sc", "glass.sc", "chex.sc"));

} // namespace
} // namespace prism

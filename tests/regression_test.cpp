// Each shipped scene against a committed reference picture.
//
// The references were rendered by Prism itself at 160x120 (depth 5, thresh 0.1)
// and inspected by eye; the physics behind them is checked independently against
// hand-computed values in physics_test and image_formation_test. These tests
// catch unintended changes to the pictures. After an intended change, regenerate
// with PRISM_UPDATE_REFERENCES=1 ctest -R Regression, look at the new pictures,
// and commit them with the change.
#include "core/io/scene_parser.h"
#include "core/render/exposure.h"
#include "core/render/renderer.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cstdlib>

namespace prism {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// Tolerances on 8-bit values scaled to [0, 1]: different compilers or
// optimisation levels may move a few values by a level or two where a pixel
// straddles an antialiasing decision; a real change moves many more.
constexpr double kPixelTolerance = 3.0 / 255.0; // a pixel beyond this "differs"
constexpr double kMaxDifferingShare = 0.002;    // at most 0.2% of pixels differ
constexpr double kMeanErrorLimit = 0.5 / 255.0;

OIIO::ImageBuf renderPicture(const std::string& sceneFile) {
  const Scene scene = loadScene(sceneFile);
  RenderSettings s;
  s.width = kWidth;
  s.height = kHeight;
  s.maxDepth = 5;
  s.thresh = 0.1;
  const auto accel = makeAccel(scene, AccelKind::Bvh); // the default; every accel agrees
  const RenderResult r = render(scene, *accel, s);
  const auto bytes = exposeImage(r.film.radiance, exposureScale(r.avgmax));
  OIIO::ImageBuf image(OIIO::ImageSpec(kWidth, kHeight, 3, OIIO::TypeDesc::UINT8));
  image.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, bytes.data());
  return image;
}

class Regression : public ::testing::TestWithParam<const char*> {};

TEST_P(Regression, MatchesReferencePicture) {
  const std::string name = GetParam();
  const std::string sceneFile = std::string(PRISM_SOURCE_DIR) + "/scenes/" + name + ".sc";
  const std::string reference = std::string(PRISM_SOURCE_DIR) + "/tests/reference/" + name + ".png";
  const OIIO::ImageBuf actual = renderPicture(sceneFile);

  if (const char* update = std::getenv("PRISM_UPDATE_REFERENCES"); update && *update == '1') {
    ASSERT_TRUE(actual.write(reference)) << actual.geterror();
    GTEST_SKIP() << "wrote " << reference;
  }

  OIIO::ImageBuf expected(reference);
  ASSERT_TRUE(expected.read()) << expected.geterror();
  ASSERT_EQ(expected.spec().width, kWidth);
  ASSERT_EQ(expected.spec().height, kHeight);
  const auto result = OIIO::ImageBufAlgo::compare(actual, expected, float(kPixelTolerance), 1.0f);
  ASSERT_FALSE(result.error) << "comparison failed";
  const double differingShare = double(result.nfail) / double(kWidth * kHeight);
  EXPECT_LE(differingShare, kMaxDifferingShare)
      << result.nfail << " pixels differ by more than 3 levels; max error " << result.maxerror * 255
      << " levels at (" << result.maxx << ", " << result.maxy << ")";
  EXPECT_LE(result.meanerror, kMeanErrorLimit)
      << "mean error " << result.meanerror * 255 << " levels";

  if (testing::Test::HasFailure()) {
    const std::string actualPath = ::testing::TempDir() + name + "-actual.png";
    actual.write(actualPath);
    ADD_FAILURE() << "the picture rendered now is at " << actualPath;
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, Regression,
                         ::testing::Values("table", "glass", "chex", "tree"));

} // namespace
} // namespace prism

// The chart writer behind `prism sweep`'s plots (app/chart.h): its ticks,
// ranges and pixel mapping computed by hand, and pictures it writes read
// back to find what should be where; and the sweep's three charts.
#include "app/chart.h"
#include "app/sweep_plots.h"

#include "test_files.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prism {
namespace {

using test::ScratchDir;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ChartTicks, NiceStepIsOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(niceStep(10.0, 5), 2.0);   // 2 exactly
  EXPECT_DOUBLE_EQ(niceStep(1.0, 6), 0.2);    // 0.167 -> 0.2
  EXPECT_DOUBLE_EQ(niceStep(100.0, 4), 20.0); // 25 -> 20 (2.5 < sqrt 10)
  EXPECT_DOUBLE_EQ(niceStep(37.0, 6), 5.0);   // 6.17 -> 5 (6.17 < sqrt 50)
  EXPECT_DOUBLE_EQ(niceStep(0.7, 6), 0.1);    // 0.117 -> 0.1 (1.17 < sqrt 2)
  EXPECT_DOUBLE_EQ(niceStep(80.0, 10), 10.0); // 8 -> 10 (8 > sqrt 50)
}

TEST(ChartTicks, LinearTicksAreTheStepsMultiplesInside) {
  const std::vector<double> unit = axisTicks({0.0, 1.0, false});
  ASSERT_EQ(unit.size(), 6u);
  for (size_t i = 0; i < unit.size(); ++i)
    EXPECT_NEAR(unit[i], 0.2 * double(i), 1e-12);

  // 17.7 / 6 = 2.95 -> step 2: 24, 26, ... 40.
  const std::vector<double> psnr = axisTicks({23.5, 41.2, false});
  ASSERT_EQ(psnr.size(), 9u);
  EXPECT_DOUBLE_EQ(psnr.front(), 24.0);
  EXPECT_DOUBLE_EQ(psnr.back(), 40.0);
}

TEST(ChartTicks, LogTicksAreDecadesOrOneTwoFive) {
  EXPECT_EQ(axisTicks({0.05, 20.0, true}), (std::vector<double>{0.1, 1.0, 10.0}));
  // Ten decades are too many: every second one, keeping 10^0.
  const std::vector<double> wide = axisTicks({1e-3, 1e6, true});
  ASSERT_EQ(wide.size(), 5u);
  const double expected[] = {1e-2, 1.0, 1e2, 1e4, 1e6};
  for (size_t i = 0; i < wide.size(); ++i)
    EXPECT_NEAR(wide[i], expected[i], 1e-9 * expected[i]);
  // Two decades inside (0.1 and 1) or one: 1, 2 and 5 times the powers of ten.
  const std::vector<double> twoDecades = axisTicks({0.03, 7.0, true});
  const double oneTwoFive[] = {0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 5.0};
  ASSERT_EQ(twoDecades.size(), std::size(oneTwoFive));
  for (size_t i = 0; i < twoDecades.size(); ++i)
    EXPECT_NEAR(twoDecades[i], oneTwoFive[i], 1e-12) << i;
  const std::vector<double> narrow = axisTicks({0.2, 1.5, true});
  ASSERT_EQ(narrow.size(), 3u);
  EXPECT_NEAR(narrow[0], 0.2, 1e-12);
  EXPECT_NEAR(narrow[1], 0.5, 1e-12);
  EXPECT_NEAR(narrow[2], 1.0, 1e-12);
  // Not even that: linear steps of 0.02 (0.15 / 6 = 0.025 -> 0.02).
  const std::vector<double> tiny = axisTicks({0.3, 0.45, true});
  ASSERT_EQ(tiny.size(), 8u);
  EXPECT_NEAR(tiny.front(), 0.30, 1e-12);
  EXPECT_NEAR(tiny.back(), 0.44, 1e-12);
}

TEST(ChartTicks, LabelsHaveTheDecimalsTheStepNeeds) {
  EXPECT_EQ(tickLabel(0.4, 0.2, false), "0.4");
  EXPECT_EQ(tickLabel(0.05, 0.05, false), "0.05");
  EXPECT_EQ(tickLabel(20.0, 5.0, false), "20");
  EXPECT_EQ(tickLabel(-1e-17, 0.1, false), "0.0"); // round-off does not print "-0.0"
  EXPECT_EQ(tickLabel(1e-3, 0.0, true), "0.001");
  EXPECT_EQ(tickLabel(1e6, 0.0, true), "1e+06");
}

TEST(ChartRange, CoversTheValuesWithAMargin) {
  const double psnr[] = {20.0, kNaN, 40.0, kInf};
  const AxisRange linear = axisRangeOf(psnr, false);
  EXPECT_DOUBLE_EQ(linear.lo, 19.0);
  EXPECT_DOUBLE_EQ(linear.hi, 41.0);
  EXPECT_FALSE(linear.log);

  // On a log axis the margin is in decades, and non-positive values are left out.
  const double seconds[] = {-1.0, 0.0, 10.0, 1000.0};
  const AxisRange log = axisRangeOf(seconds, true);
  EXPECT_NEAR(std::log10(log.lo), 0.9, 1e-12);
  EXPECT_NEAR(std::log10(log.hi), 3.1, 1e-12);
  EXPECT_TRUE(log.log);
}

TEST(ChartRange, DegenerateValuesStillGiveARange) {
  const double one[] = {30.0};
  EXPECT_DOUBLE_EQ(axisRangeOf(one, false).lo, 27.0);
  EXPECT_DOUBLE_EQ(axisRangeOf(one, false).hi, 33.0);
  const double zeros[] = {0.0, 0.0};
  EXPECT_DOUBLE_EQ(axisRangeOf(zeros, false).lo, -1.0);
  EXPECT_DOUBLE_EQ(axisRangeOf(zeros, false).hi, 1.0);
  const double ten[] = {10.0};
  EXPECT_NEAR(axisRangeOf(ten, true).lo, std::pow(10.0, 0.5), 1e-12);
  EXPECT_NEAR(axisRangeOf(ten, true).hi, std::pow(10.0, 1.5), 1e-12);
  const double nothing[] = {kNaN};
  EXPECT_DOUBLE_EQ(axisRangeOf(nothing, false).lo, 0.0);
  EXPECT_DOUBLE_EQ(axisRangeOf(nothing, false).hi, 1.0);
  EXPECT_DOUBLE_EQ(axisRangeOf({}, true).lo, 1.0);
  EXPECT_DOUBLE_EQ(axisRangeOf({}, true).hi, 10.0);
}

TEST(ChartMapping, CornersAndMiddleLandOnTheirPixels) {
  const PlotArea area{100, 50, 500, 350};
  const AxisRange x{0.0, 10.0, false}, y{1.0, 100.0, true};
  using Pixel = std::array<double, 2>;
  EXPECT_EQ(dataToPixel(x, y, area, 0.0, 1.0), (Pixel{100.0, 350.0}));   // bottom left
  EXPECT_EQ(dataToPixel(x, y, area, 10.0, 100.0), (Pixel{500.0, 50.0})); // top right
  EXPECT_EQ(dataToPixel(x, y, area, 10.0, 1.0), (Pixel{500.0, 350.0}));  // bottom right
  const Pixel middle = dataToPixel(x, y, area, 5.0, 10.0); // 10 is halfway up in decades
  EXPECT_NEAR(middle[0], 300.0, 1e-9);
  EXPECT_NEAR(middle[1], 200.0, 1e-9);
}

// ---- Pictures ----

std::array<float, 3> pixelAt(const OIIO::ImageBuf& image, double x, double y) {
  std::array<float, 3> rgb{};
  image.getpixel(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)), rgb.data(), 3);
  return rgb;
}

bool reddish(const std::array<float, 3>& c) { return c[0] > 0.7f && c[1] < 0.3f && c[2] < 0.3f; }
bool white(const std::array<float, 3>& c) { return c[0] > 0.99f && c[1] > 0.99f && c[2] > 0.99f; }

// Pixels in the band of rows [top, bottom) that are darker than mid grey.
int darkPixelsInRows(const OIIO::ImageBuf& image, int top, int bottom) {
  int count = 0;
  for (int y = top; y < bottom; ++y)
    for (int x = 0; x < image.spec().width; ++x)
      count += pixelAt(image, x, y)[0] < 0.5f;
  return count;
}

Chart onePoint(const std::string& font) {
  Chart chart{.title = "One point", .xLabel = "x", .yLabel = "y"};
  chart.series.push_back(
      {.label = "the point", .points = {{3.0, 42.0}}, .color = {1.f, 0.f, 0.f}, .markerSize = 5});
  chart.fontName = font;
  return chart;
}

TEST(ChartPicture, TheMarkerIsWhereTheMappingSays) {
  ScratchDir dir;
  const Chart chart = onePoint("DejaVuSans");
  const std::string path = (dir / "point.png").string();
  EXPECT_EQ(writeChartPng(chart, path, 640, 480), ""); // fonts-dejavu-core is installed

  OIIO::ImageBuf image(path);
  ASSERT_TRUE(image.read()) << image.geterror();
  EXPECT_EQ(image.spec().width, 640);
  EXPECT_EQ(image.spec().height, 480);
  const ChartLayout layout = layoutChart(chart, 640, 480);
  const auto [x, y] = dataToPixel(layout.x, layout.y, layout.area, 3.0, 42.0);
  EXPECT_TRUE(reddish(pixelAt(image, x, y)));
  EXPECT_TRUE(reddish(pixelAt(image, x + 3, y - 3))); // inside the radius-5 disc
  EXPECT_TRUE(white(pixelAt(image, 3, 3)));           // the picture's corner
  EXPECT_FALSE(reddish(pixelAt(image, x + 40, y)));   // off the marker
  // The title was drawn: dark pixels above the plot area.
  EXPECT_GT(darkPixelsInRows(image, 0, layout.area.top), 50);
}

TEST(ChartPicture, WithoutItsFontTheChartIsWrittenWithoutText) {
  ScratchDir dir;
  const std::string path = (dir / "point.png").string();
  const std::string warning = writeChartPng(onePoint("NoSuchFontAnywhere"), path, 640, 480);
  EXPECT_NE(warning.find("NoSuchFontAnywhere"), std::string::npos) << warning;

  OIIO::ImageBuf image(path);
  ASSERT_TRUE(image.read()) << image.geterror();
  const ChartLayout layout = layoutChart(onePoint("x"), 640, 480);
  EXPECT_EQ(darkPixelsInRows(image, 0, layout.area.top - 6), 0); // no title
  const auto [x, y] = dataToPixel(layout.x, layout.y, layout.area, 3.0, 42.0);
  EXPECT_TRUE(reddish(pixelAt(image, x, y))); // the data is still there
}

TEST(ChartPicture, ASkippedPointBreaksTheLine) {
  ScratchDir dir;
  Chart chart;
  chart.series.push_back({.points = {{0.0, 0.0}, {1.0, kNaN}, {2.0, 0.0}, {3.0, 1.0}},
                          .color = {1.f, 0.f, 0.f},
                          .lines = true,
                          .markers = false});
  const std::string path = (dir / "gap.png").string();
  writeChartPng(chart, path, 400, 300);
  OIIO::ImageBuf image(path);
  ASSERT_TRUE(image.read()) << image.geterror();
  const ChartLayout layout = layoutChart(chart, 400, 300);
  const auto map = [&](double x, double y) {
    return dataToPixel(layout.x, layout.y, layout.area, x, y);
  };
  const auto [gapX, gapY] = map(1.0, 0.0); // where (0,0)-(2,0) would pass
  EXPECT_FALSE(reddish(pixelAt(image, gapX, gapY)));
  const auto [joinedX, joinedY] = map(2.5, 0.5); // on the drawn segment (2,0)-(3,1)
  EXPECT_TRUE(reddish(pixelAt(image, joinedX, joinedY)));
}

TEST(ChartPicture, AnUnwritablePathThrows) {
  EXPECT_THROW(writeChartPng(onePoint("DejaVuSans"), "/nonexistent-prism-dir/chart.png"),
               std::runtime_error);
}

// ---- The sweep's charts ----

SweepRow row(SweepSetting setting, double cpuSeconds, double psnr, bool pareto = false) {
  SweepRow r;
  r.setting = setting;
  r.cpuSeconds = cpuSeconds;
  r.wallSeconds = cpuSeconds / 2;
  r.error.psnr = psnr;
  r.pareto = pareto;
  return r;
}

TEST(SweepPlots, WritesThreeChartsOfTheStatedSize) {
  const std::vector<SweepRow> rows = {
      row({}, 2.0, 38.0, true), // the default
      row({.antialias = false}, 0.5, 30.0, true),
      row({.antialias = false, .depth = 3}, 0.4, 26.0),
      row({.depth = 3}, 1.5, 33.0),
      row({.depth = 8}, 3.0, 39.0, true),
      row({.depth = 5, .bailout = 0.5}, 1.8, 37.5),
      row({.thresh = 0.0, .depth = 5}, 6.0, kInf, true), // the reference's own setting
      row({.thresh = 0.02, .depth = 5, .jitter = true}, 4.0, 40.0),
      row({.thresh = 0.3}, 1.0, 20.0), // no threshold category: only on time-vs-error
  };
  ScratchDir dir;
  EXPECT_EQ(writeSweepPlots(rows, dir.path().string(), "test.sc"), "");
  for (const char* name : {"time-vs-error.png", "error-vs-depth.png", "error-vs-threshold.png"}) {
    const auto path = dir / name;
    ASSERT_TRUE(std::filesystem::exists(path)) << name;
    EXPECT_GT(std::filesystem::file_size(path), 1000u) << name;
    OIIO::ImageBuf image(path.string());
    ASSERT_TRUE(image.read()) << name << ": " << image.geterror();
    EXPECT_EQ(image.spec().width, 900) << name;
    EXPECT_EQ(image.spec().height, 600) << name;
  }

  // The Pareto front is a red line, the default a large blue disc (and its
  // legend entry another).
  OIIO::ImageBuf timeVsError((dir / "time-vs-error.png").string());
  ASSERT_TRUE(timeVsError.read());
  int red = 0, blue = 0;
  for (int y = 0; y < 600; ++y)
    for (int x = 0; x < 900; ++x) {
      const auto c = pixelAt(timeVsError, x, y);
      red += reddish(c);
      blue += c[2] > 0.7f && c[0] < 0.3f;
    }
  EXPECT_GT(red, 300);
  EXPECT_GT(blue, 150);
}

TEST(SweepPlots, AnUnwritableFolderThrows) {
  EXPECT_THROW(writeSweepPlots({}, "/nonexistent-prism-dir", "test.sc"), std::runtime_error);
}

} // namespace
} // namespace prism

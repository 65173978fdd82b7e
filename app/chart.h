// A small chart writer for the plots `prism sweep` saves: scatter and line
// series on linear or logarithmic axes, drawn with OpenImageIO into a PNG.
// The arithmetic (tick values, axis ranges, data-to-pixel mapping) is here in
// the header so that it can be tested without reading pictures back.
#pragma once

#include <array>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace prism {

// (Here and in Chart every member has an initializer, so designated
// initializers may leave out any.)
struct ChartSeries {
  std::string label{}; // in the legend; an empty label keeps the series out of it
  // (x, y) in data units. A non-finite point (or a non-positive one on a
  // log axis) is skipped and breaks the line there, so a missing
  // measurement shows as a gap.
  std::vector<std::array<double, 2>> points{};
  std::array<float, 3> color{0.f, 0.f, 0.f}; // 0..1, written as is (no colour conversion)
  bool lines = false;                        // join consecutive points
  bool dashed = false;                       // draw those lines dashed
  bool markers = true;                       // a filled disc at every point
  int markerSize = 3;                        // the disc's radius in pixels
};

struct Chart {
  std::string title{};
  std::string subtitle{}; // smaller, under the title; e.g. how outliers were drawn
  std::string xLabel{}, yLabel{};
  bool logX = false, logY = false;
  // When not empty, these (value, label) pairs replace the computed x ticks:
  // a categorical axis, e.g. thresholds 0, 0.01, ... 1 drawn evenly spaced.
  std::vector<std::pair<double, std::string>> xTicks{};
  std::vector<ChartSeries> series{};
  // A font OpenImageIO can find by name. Its default font is not found on
  // Debian, so the name is always given; the field exists for the test of a
  // missing font.
  std::string fontName = "DejaVuSans";
};

// Writes `chart` as a `width` x `height` PNG at `path`. Throws
// std::runtime_error when the file cannot be written. Returns warnings (empty
// when none): a chart whose text cannot be drawn (font missing) is still
// written, without its labels, and the warning says so.
std::string writeChartPng(const Chart& chart, const std::string& path, int width = 900,
                          int height = 600);

// ---- The pure parts, for tests ----

// Whether a value can be drawn on an axis: finite, and positive on a log axis.
inline bool plottable(double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); }

// The values shown on one axis, `lo` < `hi` in data units; `log` means the
// axis is drawn in log10 of the values (then 0 < lo).
struct AxisRange {
  double lo = 0.0, hi = 1.0;
  bool log = false;
};

// The range that shows all `values` (non-finite ones, and non-positive ones
// on a log axis, ignored) with a 5% margin either side; in decades on a log
// axis. All-equal values get a range around them, no values [0, 1] (log:
// [1, 10]), so the result always has lo < hi.
AxisRange axisRangeOf(std::span<const double> values, bool log);

// The step of about `targetCount` ticks over `span` > 0: 1, 2 or 5 times a
// power of ten.
double niceStep(double span, int targetCount);

// Tick values inside [lo, hi]: multiples of niceStep(hi - lo, targetCount)
// on a linear axis. On a log axis the powers of ten (every n-th decade when
// there are many); when fewer than three fall inside, 1, 2 and 5 times the
// powers of ten; when fewer than two of those, linear nice ticks.
std::vector<double> axisTicks(const AxisRange& range, int targetCount = 6);

// The text of a tick value: on a linear axis with as many decimals as the
// step between ticks needs ("0.05", "20"); on a log axis the shortest form
// ("0.001", "100", "1e+06").
std::string tickLabel(double value, double step, bool log);

// The pixel rectangle the data is drawn in (inclusive pixel coordinates,
// y growing downwards as in the picture).
struct PlotArea {
  int left = 0, top = 0, right = 0, bottom = 0;
};

// Where a picture of `width` x `height` leaves room for the data once the
// title, tick labels and axis labels have theirs.
PlotArea plotAreaOf(int width, int height);

// The pixel (fractional) of data point (x, y): lo maps to left / bottom, hi
// to right / top, linearly in the value or in its log10.
std::array<double, 2> dataToPixel(const AxisRange& xRange, const AxisRange& yRange,
                                  const PlotArea& area, double x, double y);

// The axes and the plot area writeChartPng uses for `chart` (the ranges of
// every series' points; with xTicks, the x range covers those too).
struct ChartLayout {
  AxisRange x, y;
  PlotArea area;
};
ChartLayout layoutChart(const Chart& chart, int width, int height);

} // namespace prism

#include "chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace prism {

namespace {

// Tolerance for "this value is a whole number of steps" against round-off.
constexpr double kStepSlack = 1e-9;

double toAxis(double v, bool log) { return log ? std::log10(v) : v; }

// Integer multiples k * step inside [lo, hi], computed from k rather than
// accumulated so that round-off does not drift along the axis.
std::vector<double> multiplesInside(double lo, double hi, double step) {
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - kStepSlack), last = std::floor(hi / step + kStepSlack);
  if (!(last - first < 1000.0)) return ticks; // a step far too small for the range
  for (double k = first; k <= last; k += 1.0)
    ticks.push_back(k * step);
  return ticks;
}

std::vector<double> logTicks(const AxisRange& range, int targetCount) {
  const double loDecade = std::log10(range.lo), hiDecade = std::log10(range.hi);
  const double first = std::ceil(loDecade - kStepSlack), last = std::floor(hiDecade + kStepSlack);
  std::vector<double> ticks;
  if (last - first >= 2.0) {
    // Every decade while they fit, otherwise every n-th, keeping 10^0.
    const double stride = std::max(1.0, std::ceil((last - first + 1.0) / targetCount));
    for (double e = first; e <= last; e += 1.0)
      if (std::fmod(std::abs(e), stride) == 0.0) ticks.push_back(std::pow(10.0, e));
    return ticks;
  }
  // Two decades or fewer would leave the axis nearly bare: 1, 2 and 5 times
  // the powers of ten.
  for (double e = std::floor(loDecade); e <= std::ceil(hiDecade); e += 1.0)
    for (const double mantissa : {1.0, 2.0, 5.0}) {
      const double v = mantissa * std::pow(10.0, e);
      if (v >= range.lo * (1 - kStepSlack) && v <= range.hi * (1 + kStepSlack)) ticks.push_back(v);
    }
  if (ticks.size() >= 2) return ticks;
  ticks = multiplesInside(range.lo, range.hi, niceStep(range.hi - range.lo, targetCount));
  std::erase_if(ticks, [](double v) { return v <= 0.0; });
  return ticks;
}

} // namespace

AxisRange axisRangeOf(std::span<const double> values, bool log) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double v : values)
    if (plottable(v, log)) {
      lo = std::min(lo, toAxis(v, log));
      hi = std::max(hi, toAxis(v, log));
    }
  if (lo > hi) return log ? AxisRange{1.0, 10.0, true} : AxisRange{0.0, 1.0, false};
  double margin = 0.05 * (hi - lo);
  if (!(margin > 0.0)) {
    // One value (or all equal): half a decade, or 10% of it, either side.
    margin = log ? 0.5 : (lo != 0.0 ? 0.1 * std::abs(lo) : 1.0);
  }
  lo -= margin;
  hi += margin;
  if (log) return {std::pow(10.0, lo), std::pow(10.0, hi), true};
  return {lo, hi, false};
}

double niceStep(double span, int targetCount) {
  const double raw = span / std::max(targetCount, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  const double mantissa = raw / power; // in [1, 10)
  // The nearest of 1, 2, 5, 10 on a log scale: the cut-offs are their
  // geometric means, so the tick count is as close to the target as 1-2-5
  // steps allow.
  if (mantissa < std::sqrt(2.0)) return power;
  if (mantissa < std::sqrt(10.0)) return 2 * power;
  if (mantissa < std::sqrt(50.0)) return 5 * power;
  return 10 * power;
}

std::vector<double> axisTicks(const AxisRange& range, int targetCount) {
  if (range.log) return logTicks(range, targetCount);
  return multiplesInside(range.lo, range.hi, niceStep(range.hi - range.lo, targetCount));
}

std::string tickLabel(double value, double step, bool log) {
  char text[64];
  if (log) {
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }
  // A multiple of the step that is zero up to round-off prints as "0", not "-0.00".
  if (std::abs(value) < 1e-6 * step) value = 0.0;
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-6));
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

PlotArea plotAreaOf(int width, int height) {
  // Left: the rotated y label and the y tick labels; bottom: the x tick
  // labels and the x label; top: the title and subtitle. Small pictures give
  // up room in proportion.
  return {std::min(84, width / 5), std::min(62, height / 5), width - 1 - std::min(24, width / 20),
          height - 1 - std::min(62, height / 5)};
}

std::array<double, 2> dataToPixel(const AxisRange& xRange, const AxisRange& yRange,
                                  const PlotArea& area, double x, double y) {
  const auto fraction = [](const AxisRange& r, double v) {
    return (toAxis(v, r.log) - toAxis(r.lo, r.log)) / (toAxis(r.hi, r.log) - toAxis(r.lo, r.log));
  };
  return {area.left + fraction(xRange, x) * (area.right - area.left),
          area.bottom - fraction(yRange, y) * (area.bottom - area.top)};
}

ChartLayout layoutChart(const Chart& chart, int width, int height) {
  std::vector<double> xs, ys;
  for (const ChartSeries& s : chart.series)
    for (const auto& [x, y] : s.points)
      if (plottable(x, chart.logX) && plottable(y, chart.logY)) {
        xs.push_back(x);
        ys.push_back(y);
      }
  for (const auto& tick : chart.xTicks)
    xs.push_back(tick.first);
  return {axisRangeOf(xs, chart.logX), axisRangeOf(ys, chart.logY), plotAreaOf(width, height)};
}

} // namespace prism

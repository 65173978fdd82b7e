#include "sweep_plots.h"

#include "chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace prism {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN(); // a gap in a line

constexpr std::array<float, 3> kGrey{0.62f, 0.62f, 0.62f};
constexpr std::array<float, 3> kRed{0.85f, 0.1f, 0.1f};
constexpr std::array<float, 3> kBlue{0.12f, 0.35f, 0.85f};
constexpr std::array<float, 3> kOrange{0.95f, 0.55f, 0.05f};
constexpr std::array<float, 3> kGreen{0.1f, 0.6f, 0.25f};
constexpr std::array<float, 3> kPurple{0.55f, 0.2f, 0.7f};
constexpr std::array<float, 3> kDarkGrey{0.3f, 0.3f, 0.3f};

// What `prism render` does without options.
constexpr SweepSetting kDefaultSetting{};

// PSNR is +infinity for a setting whose picture equals the reference. A chart
// has no room at infinity, so such rows are drawn 5 dB above the most
// accurate measured one (the same height on every chart), and the chart's
// subtitle says so.
class PsnrScale {
public:
  explicit PsnrScale(const std::vector<SweepRow>& rows) {
    double best = -std::numeric_limits<double>::infinity();
    for (const SweepRow& row : rows)
      if (std::isfinite(row.error.psnr)) best = std::max(best, row.error.psnr);
    infinityDrawnAt_ = std::isfinite(best) ? best + 5.0 : 100.0;
  }

  double operator()(const SweepRow* row) {
    if (row == nullptr) return kMissing;
    if (row->error.psnr == std::numeric_limits<double>::infinity()) {
      drewInfinity_ = true;
      return infinityDrawnAt_;
    }
    return row->error.psnr;
  }

  // For the subtitle; empty unless some row of this chart was infinite.
  std::string note() const {
    if (!drewInfinity_) return "";
    char text[120];
    std::snprintf(text, sizeof text, "PSNR = inf (same picture as the reference) drawn at %.1f dB",
                  infinityDrawnAt_);
    return text;
  }

private:
  double infinityDrawnAt_ = 0.0;
  bool drewInfinity_ = false;
};

// What a chart holds fixed, then how it draws infinite PSNR if it had to.
std::string withNote(const std::string& fixed, const PsnrScale& psnr) {
  return psnr.note().empty() ? fixed : fixed + "; " + psnr.note();
}

ChartSeries lineSeries(std::string label, const std::array<float, 3>& color) {
  return {.label = std::move(label), .color = color, .lines = true, .markerSize = 4};
}

const char* const kPsnrLabel = "PSNR against the reference (dB, higher is better)";

Chart timeVsError(const std::vector<SweepRow>& rows, const std::string& sceneName) {
  PsnrScale psnr(rows);
  ChartSeries all{.label = "every setting", .color = kGrey, .markerSize = 3};
  for (const SweepRow& row : rows)
    all.points.push_back({row.cpuSeconds, psnr(&row)});

  std::vector<const SweepRow*> front;
  for (const SweepRow& row : rows)
    if (row.pareto) front.push_back(&row);
  std::ranges::sort(front, {}, [](const SweepRow* r) { return r->cpuSeconds; });
  ChartSeries pareto = lineSeries("Pareto front", kRed);
  pareto.markerSize = 5;
  for (const SweepRow* row : front)
    pareto.points.push_back({row->cpuSeconds, psnr(row)});

  // Drawn before the front and larger, so a default on the front shows as a
  // blue ring around its red marker.
  ChartSeries defaults{.label = "default", .color = kBlue, .markerSize = 8};
  if (const SweepRow* row = findSetting(rows, kDefaultSetting))
    defaults.points.push_back({row->cpuSeconds, psnr(row)});

  return {.title = sceneName + ": time against error",
          .subtitle = psnr.note(),
          .xLabel = "CPU time of the render (s, all threads, log scale)",
          .yLabel = kPsnrLabel,
          .logX = true,
          .series = {all, defaults, pareto}};
}

Chart errorVsDepth(const std::vector<SweepRow>& rows, const std::string& sceneName) {
  PsnrScale psnr(rows);
  constexpr int kMaxDepth = 8;
  // Grid sub-samples (no jitter) throughout; only the named option varies.
  const auto along = [&](std::string label, const std::array<float, 3>& color,
                         SweepSetting setting) {
    ChartSeries s = lineSeries(std::move(label), color);
    for (setting.depth = 1; setting.depth <= kMaxDepth; ++setting.depth)
      s.points.push_back({double(setting.depth), psnr(findSetting(rows, setting))});
    return s;
  };
  Chart chart{.title = sceneName + ": error against ray depth",
              .xLabel = "maximum ray depth (--depth)",
              .yLabel = kPsnrLabel,
              .series = {along("antialias, thresh 0.1", kBlue, kDefaultSetting),
                         along("--no-aa", kDarkGrey, {.antialias = false}),
                         along("--bailout 0.5", kGreen, {.bailout = 0.5}),
                         along("--bailout 2", kPurple, {.bailout = 2.0})}};
  for (int depth = 1; depth <= kMaxDepth; ++depth)
    chart.xTicks.push_back({double(depth), std::to_string(depth)});
  chart.subtitle = withNote("grid sub-samples; thresh 0.1 and bailout 0 unless named", psnr);
  return chart;
}

Chart errorVsThreshold(const std::vector<SweepRow>& rows, const std::string& sceneName) {
  PsnrScale psnr(rows);
  // The thresholds span 0 (supersample every pixel) to 1 over two decades,
  // and a log axis has no place for 0; so they are categories, evenly
  // spaced in this order, at x = 0, 1, 2, ... Rows at other thresholds are
  // not drawn here.
  constexpr std::array kThresholds{0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0};
  Chart chart{.title = sceneName + ": error against supersampling threshold",
              .xLabel = "supersampling threshold (--thresh; categories, evenly spaced)",
              .yLabel = kPsnrLabel};
  for (size_t i = 0; i < kThresholds.size(); ++i) {
    char label[16];
    std::snprintf(label, sizeof label, "%g", kThresholds[i]);
    chart.xTicks.push_back({double(i), label});
  }
  const auto along = [&](std::string label, const std::array<float, 3>& color, bool jitter) {
    ChartSeries s = lineSeries(std::move(label), color);
    for (size_t i = 0; i < kThresholds.size(); ++i)
      s.points.push_back(
          {double(i), psnr(findSetting(rows, {.thresh = kThresholds[i], .jitter = jitter}))});
    return s;
  };
  chart.series = {along("grid sub-samples", kBlue, false), along("jittered", kOrange, true)};

  // Without antialiasing the threshold does not apply: one value, drawn
  // across every category for comparison.
  if (const SweepRow* noAa = findSetting(rows, {.antialias = false})) {
    const double level = psnr(noAa);
    chart.series.push_back({.label = "--no-aa",
                            .points = {{0.0, level}, {double(kThresholds.size() - 1), level}},
                            .color = kDarkGrey,
                            .lines = true,
                            .dashed = true,
                            .markers = false});
  }
  chart.subtitle = withNote("depth 5, bailout 0", psnr);
  return chart;
}

} // namespace

std::string writeSweepPlots(const std::vector<SweepRow>& rows, const std::string& dir,
                            const std::string& sceneName) {
  const std::filesystem::path folder(dir);
  std::string warnings;
  const auto write = [&](const Chart& chart, const char* file) {
    const std::string warning = writeChartPng(chart, (folder / file).string());
    if (warning.empty()) return;
    warnings += (warnings.empty() ? "" : "\n") + warning;
  };
  write(timeVsError(rows, sceneName), "time-vs-error.png");
  write(errorVsDepth(rows, sceneName), "error-vs-depth.png");
  write(errorVsThreshold(rows, sceneName), "error-vs-threshold.png");
  return warnings;
}

} // namespace prism

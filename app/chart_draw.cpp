// The drawing half of the charts of `prism sweep` (chart.h), with OpenImageIO:
// built into the module libprism_oiio.so (core/io/oiio_module.h), never into
// the `prism` executable, whose writeChartPng (chart_loader.cpp) calls it.
#include "chart.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace prism {

namespace {

namespace IBA = OIIO::ImageBufAlgo;
using Color = std::array<float, 3>;

constexpr Color kBlack{0.f, 0.f, 0.f};
constexpr Color kWhite{1.f, 1.f, 1.f};
constexpr Color kFrameGrey{0.25f, 0.25f, 0.25f};
constexpr Color kGridGrey{0.88f, 0.88f, 0.88f};
constexpr Color kLegendEdge{0.6f, 0.6f, 0.6f};

constexpr int kTitleSize = 20, kSubtitleSize = 14, kAxisLabelSize = 16, kTickSize = 13,
              kLegendSize = 14;

int px(double v) { return static_cast<int>(std::lround(v)); }

// The picture being drawn and whether its font works: text is drawn only
// while it does, and the first failure is remembered for the warning.
class Canvas {
public:
  Canvas(int width, int height, std::string fontName)
      : image_(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)),
        font_(std::move(fontName)) {
    IBA::fill(image_, kWhite);
    fontWorks_ = IBA::text_size("0", kTickSize, font_).defined();
  }

  bool hasFont() const { return fontWorks_; }
  const std::string& fontName() const { return font_; }

  void line(int x1, int y1, int x2, int y2, const Color& c) {
    IBA::render_line(image_, x1, y1, x2, y2, c);
  }

  // Two pixels wide: the line and its copies one pixel right and down.
  void thickLine(int x1, int y1, int x2, int y2, const Color& c) {
    line(x1, y1, x2, y2, c);
    line(x1 + 1, y1, x2 + 1, y2, c);
    line(x1, y1 + 1, x2, y2 + 1, c);
  }

  void dashedLine(double x1, double y1, double x2, double y2, const Color& c) {
    constexpr double kDash = 9.0, kGap = 6.0;
    const double length = std::hypot(x2 - x1, y2 - y1);
    if (length == 0.0) return;
    for (double s = 0.0; s < length; s += kDash + kGap) {
      const double e = std::min(s + kDash, length);
      thickLine(px(x1 + (x2 - x1) * s / length), px(y1 + (y2 - y1) * s / length),
                px(x1 + (x2 - x1) * e / length), px(y1 + (y2 - y1) * e / length), c);
    }
  }

  void box(int x1, int y1, int x2, int y2, const Color& c, bool filled) {
    IBA::render_box(image_, x1, y1, x2, y2, c, filled);
  }

  // A filled disc, one horizontal span per row.
  void disc(int cx, int cy, int radius, const Color& c) {
    for (int dy = -radius; dy <= radius; ++dy) {
      const int half = static_cast<int>(std::sqrt(double(radius * radius - dy * dy)) + 0.5);
      box(cx - half, cy + dy, cx + half, cy + dy, c, true);
    }
  }

  // The extent of `text` relative to its baseline origin (undefined without font).
  OIIO::ROI textSize(const std::string& text, int size) const {
    return fontWorks_ ? IBA::text_size(text, size, font_) : OIIO::ROI();
  }

  void text(int x, int y, const std::string& text, int size, IBA::TextAlignX alignX,
            IBA::TextAlignY alignY, const Color& c = kBlack) {
    if (!fontWorks_ || text.empty()) return;
    if (!IBA::render_text(image_, x, y, text, size, font_, c, alignX, alignY)) {
      fontWorks_ = false;
      image_.geterror(); // taken here: it is reported as the warning instead
    }
  }

  // Reading upwards, centred on (cx, cy): drawn level into a picture of its
  // own, turned a quarter anticlockwise and pasted in.
  void verticalText(int cx, int cy, const std::string& text, int size) {
    const OIIO::ROI extent = textSize(text, size);
    if (!extent.defined() || text.empty()) return;
    OIIO::ImageBuf level(
        OIIO::ImageSpec(extent.width() + 2, extent.height() + 2, 3, OIIO::TypeDesc::UINT8));
    IBA::fill(level, kWhite);
    if (!IBA::render_text(level, 1 - extent.xbegin, 1 - extent.ybegin, text, size, font_, kBlack)) {
      fontWorks_ = false;
      level.geterror();
      return;
    }
    const OIIO::ImageBuf upright = IBA::rotate270(level);
    const OIIO::ROI r = upright.roi();
    IBA::paste(image_, cx - r.width() / 2, cy - r.height() / 2, 0, 0, upright);
  }

  void write(const std::string& path) const {
    if (!image_.write(path, OIIO::TypeDesc::UINT8, "png"))
      throw std::runtime_error("cannot write the chart " + path + ": " + image_.geterror());
  }

private:
  OIIO::ImageBuf image_;
  std::string font_;
  bool fontWorks_ = false;
};

struct Tick {
  double value;
  std::string label;
};

std::vector<Tick> ticksOf(const AxisRange& range) {
  const std::vector<double> values = axisTicks(range);
  const double step = values.size() >= 2 ? values[1] - values[0] : niceStep(range.hi - range.lo, 6);
  std::vector<Tick> ticks;
  for (const double v : values)
    ticks.push_back({v, tickLabel(v, step, range.log)});
  return ticks;
}

// A series' drawable points in pixels, split into runs at the skipped ones.
std::vector<std::vector<std::array<double, 2>>> pixelRuns(const ChartSeries& s,
                                                          const ChartLayout& layout) {
  std::vector<std::vector<std::array<double, 2>>> runs(1);
  for (const auto& [x, y] : s.points) {
    if (plottable(x, layout.x.log) && plottable(y, layout.y.log)) {
      runs.back().push_back(dataToPixel(layout.x, layout.y, layout.area, x, y));
    } else if (!runs.back().empty()) {
      runs.emplace_back();
    }
  }
  return runs;
}

void drawSeries(Canvas& canvas, const ChartSeries& s, const ChartLayout& layout) {
  for (const auto& run : pixelRuns(s, layout)) {
    if (s.lines)
      for (size_t i = 1; i < run.size(); ++i) {
        const auto& [x1, y1] = run[i - 1];
        const auto& [x2, y2] = run[i];
        if (s.dashed) {
          canvas.dashedLine(x1, y1, x2, y2, s.color);
        } else {
          canvas.thickLine(px(x1), px(y1), px(x2), px(y2), s.color);
        }
      }
    if (s.markers)
      for (const auto& [x, y] : run)
        canvas.disc(px(x), px(y), s.markerSize, s.color);
  }
}

void drawAxes(Canvas& canvas, const Chart& chart, const ChartLayout& layout) {
  const PlotArea& a = layout.area;
  std::vector<Tick> xTicks;
  if (chart.xTicks.empty()) {
    xTicks = ticksOf(layout.x);
  } else {
    for (const auto& [value, label] : chart.xTicks)
      xTicks.push_back({value, label});
  }
  constexpr int kTickLength = 5, kTickGap = 4;
  for (const Tick& t : xTicks) {
    const int x = px(dataToPixel(layout.x, layout.y, a, t.value, layout.y.lo)[0]);
    canvas.line(x, a.top, x, a.bottom, kGridGrey);
    canvas.line(x, a.bottom, x, a.bottom + kTickLength, kFrameGrey);
    canvas.text(x, a.bottom + kTickLength + kTickGap, t.label, kTickSize, IBA::TextAlignX::Center,
                IBA::TextAlignY::Top);
  }
  for (const Tick& t : ticksOf(layout.y)) {
    const int y = px(dataToPixel(layout.x, layout.y, a, layout.x.lo, t.value)[1]);
    canvas.line(a.left, y, a.right, y, kGridGrey);
    canvas.line(a.left - kTickLength, y, a.left, y, kFrameGrey);
    canvas.text(a.left - kTickLength - kTickGap, y, t.label, kTickSize, IBA::TextAlignX::Right,
                IBA::TextAlignY::Center);
  }
  canvas.box(a.left, a.top, a.right, a.bottom, kFrameGrey, false);
}

void drawTexts(Canvas& canvas, const Chart& chart, const ChartLayout& layout, int height) {
  const PlotArea& a = layout.area;
  const int centreX = (a.left + a.right) / 2;
  canvas.text(centreX, 8, chart.title, kTitleSize, IBA::TextAlignX::Center, IBA::TextAlignY::Top);
  canvas.text(centreX, 34, chart.subtitle, kSubtitleSize, IBA::TextAlignX::Center,
              IBA::TextAlignY::Top, kFrameGrey);
  canvas.text(centreX, height - 8, chart.xLabel, kAxisLabelSize, IBA::TextAlignX::Center,
              IBA::TextAlignY::Bottom);
  canvas.verticalText(16, (a.top + a.bottom) / 2, chart.yLabel, kAxisLabelSize);
}

// The legend goes in the corner of the plot area it hides the least data
// in: the series' points and points along their lines, counted inside.
void drawLegend(Canvas& canvas, const Chart& chart, const ChartLayout& layout) {
  std::vector<const ChartSeries*> entries;
  for (const ChartSeries& s : chart.series)
    if (!s.label.empty() && !pixelRuns(s, layout).front().empty()) entries.push_back(&s);
  if (entries.empty() || !canvas.hasFont()) return;

  constexpr int kPad = 8, kRow = 20, kSample = 30, kInset = 10;
  int textWidth = 0;
  for (const ChartSeries* s : entries)
    textWidth = std::max(textWidth, canvas.textSize(s->label, kLegendSize).width());
  const int w = kPad + kSample + kPad + textWidth + kPad;
  const int h = 2 * kPad + kRow * static_cast<int>(entries.size());

  const PlotArea& a = layout.area;
  const std::array<std::array<int, 2>, 4> corners{{{a.right - kInset - w, a.top + kInset},
                                                   {a.left + kInset, a.top + kInset},
                                                   {a.right - kInset - w, a.bottom - kInset - h},
                                                   {a.left + kInset, a.bottom - kInset - h}}};
  const auto hidden = [&](const std::array<int, 2>& corner) {
    const auto inside = [&](double x, double y) {
      return x >= corner[0] && x <= corner[0] + w && y >= corner[1] && y <= corner[1] + h;
    };
    int count = 0;
    for (const ChartSeries& s : chart.series)
      for (const auto& run : pixelRuns(s, layout))
        for (size_t i = 0; i < run.size(); ++i) {
          count += inside(run[i][0], run[i][1]);
          if (!s.lines || i == 0) continue;
          for (double t = 0.1; t < 1.0; t += 0.1)
            count += inside(run[i - 1][0] + t * (run[i][0] - run[i - 1][0]),
                            run[i - 1][1] + t * (run[i][1] - run[i - 1][1]));
        }
    return count;
  };
  const auto best = std::min_element(corners.begin(), corners.end(),
                                     [&](auto& l, auto& r) { return hidden(l) < hidden(r); });
  const int x0 = (*best)[0], y0 = (*best)[1];

  canvas.box(x0, y0, x0 + w, y0 + h, kWhite, true);
  canvas.box(x0, y0, x0 + w, y0 + h, kLegendEdge, false);
  for (size_t i = 0; i < entries.size(); ++i) {
    const ChartSeries& s = *entries[i];
    const int y = y0 + kPad + kRow * static_cast<int>(i) + kRow / 2;
    const int sampleLeft = x0 + kPad, sampleRight = sampleLeft + kSample;
    if (s.lines && s.dashed) canvas.dashedLine(sampleLeft, y, sampleRight, y, s.color);
    if (s.lines && !s.dashed) canvas.thickLine(sampleLeft, y, sampleRight, y, s.color);
    if (s.markers) canvas.disc((sampleLeft + sampleRight) / 2, y, s.markerSize, s.color);
    canvas.text(sampleRight + kPad, y, s.label, kLegendSize, IBA::TextAlignX::Left,
                IBA::TextAlignY::Center);
  }
}

} // namespace

std::string drawChartPng(const Chart& chart, const std::string& path, int width, int height) {
  if (width < 64 || height < 64)
    throw std::invalid_argument("a chart needs at least 64 x 64 pixels");
  const ChartLayout layout = layoutChart(chart, width, height);
  Canvas canvas(width, height, chart.fontName);
  drawAxes(canvas, chart, layout);
  for (const ChartSeries& s : chart.series)
    drawSeries(canvas, s, layout);
  drawTexts(canvas, chart, layout, height);
  drawLegend(canvas, chart, layout);
  canvas.write(path);
  if (canvas.hasFont()) return "";
  return "chart " + path + ": the font " + chart.fontName +
         " cannot be drawn (is fonts-dejavu-core installed?); written without its text";
}

} // namespace prism

// The module's entry: draws `chart` at `path`; returns 0 with the exception's
// text in `*error` on failure, 1 with the warnings in `*warnings` otherwise.
extern "C" __attribute__((visibility("default"))) int
prism_oiio_write_chart(const prism::Chart* chart, const char* path, int width, int height,
                       std::string* warnings, std::string* error, int* invalidArgument) {
  try {
    *warnings = prism::drawChartPng(*chart, path, width, height);
    return 1;
  } catch (const std::invalid_argument& e) {
    *error = e.what();
    *invalidArgument = 1;
  } catch (const std::exception& e) {
    *error = e.what();
  }
  return 0;
}

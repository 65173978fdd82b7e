// The table `prism sweep` writes (DIR/sweep.csv; docs/choosing-settings.md):
// one row per setting, its cost and its error against the reference picture;
// and what the previewer reads back to show where its settings sit.
#pragma once

#include "core/sweep/image_error.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// One point of the grid: the settings that trade time for accuracy. The
// defaults are `prism render`'s.
struct SweepSetting {
  bool antialias = true; // false: --no-aa (thresh and jitter then do not apply)
  double thresh = 0.1;
  int depth = 5;
  bool jitter = false;
  double bailout = 0.0; // levels

  bool operator==(const SweepSetting&) const = default;
};

// The command-line options that select `setting`, e.g.
// "--depth 5 --thresh 0.1 --jitter --bailout 0.5" or "--depth 3 --no-aa".
std::string settingOptions(const SweepSetting& setting);

// Rays per pixel by kind (RayCounts over the pixel count).
struct RaysPerPixel {
  double eye = 0.0, shadow = 0.0, reflected = 0.0, transmitted = 0.0, pilot = 0.0;
  double total() const { return eye + shadow + reflected + transmitted + pilot; }
  bool operator==(const RaysPerPixel&) const = default;
};

struct SweepRow {
  SweepSetting setting;
  double cpuSeconds = 0.0;  // rendering, all threads
  double wallSeconds = 0.0; // rendering
  RaysPerPixel rays;
  double supersampled = 0.0; // share of pixels pass 2 supersampled
  ImageError error;
  bool pareto = false; // on the front of cpuSeconds against error.psnr

  bool operator==(const SweepRow&) const = default;
};

// Marks every row that no other row beats: none is at most as costly (CPU)
// and at least as accurate (PSNR) while strictly better in one of the two.
void markParetoFront(std::vector<SweepRow>& rows);

// CSV with a header line; numbers in full precision, an infinite PSNR as "inf".
std::string formatSweepCsv(const std::vector<SweepRow>& rows);

struct SweepCsvError : std::runtime_error {
  using std::runtime_error::runtime_error; // "LINE:COLUMN: what is wrong"
};

// The rows of formatSweepCsv's text (columns found by their header names, so
// later columns may be added). Throws SweepCsvError.
std::vector<SweepRow> parseSweepCsv(std::string_view text);

// The row of exactly this setting (thresholds and bailouts compared to 1e-9),
// if the sweep measured it.
const SweepRow* findSetting(const std::vector<SweepRow>& rows, const SweepSetting& setting);

// The most accurate row on the Pareto front that costs at most `cpuSeconds`
// (nullptr when none is that cheap).
const SweepRow* bestWithinCost(const std::vector<SweepRow>& rows, double cpuSeconds);

} // namespace prism

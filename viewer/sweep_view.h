// Where the previewer's settings sit in a sweep of its scene (`prism sweep`,
// core/sweep/sweep_table.h): the expected error of the current settings and
// the most accurate setting that costs no more. The table is read from
// NAME.sweep.csv beside the scene file NAME.sc, or from `prism view --sweep
// FILE`. Pure: the panel and the view script show what sweepStatus() says.
#pragma once

#include "core/render/renderer.h"
#include "core/sweep/sweep_table.h"

#include <optional>
#include <string>
#include <vector>

namespace prism {

// DIR/NAME.sweep.csv for the scene file DIR/NAME.EXT.
std::string sweepPathBeside(const std::string& scenePath);

// A sweep table as the previewer holds it: none (no path), its rows, or why
// it could not be read.
struct LoadedSweep {
  std::string path;           // the file; "" when there is none
  std::vector<SweepRow> rows; // the Pareto front marked afresh over these rows
  std::string error;          // "PATH:LINE:COLUMN: what is wrong", or "PATH: cannot read it"
  bool present() const { return !path.empty(); }
};

// Reads the table at `path`. A file that does not exist is no sweep, silently,
// unless `mustExist` (the user named it); every other failure is an error
// with its place, never an exception. Files over kMaxSweepBytes are refused.
inline constexpr std::size_t kMaxSweepBytes = 64u << 20;
LoadedSweep loadSweep(const std::string& path, bool mustExist);

// The sweep's setting for these render settings. A threshold set through the
// panel's slider is a float (0.1f is 0.10000000149): one that is exactly a
// float is taken as the shortest decimal that float stands for, so that it
// finds the sweep's 0.1.
SweepSetting sweepSettingOf(const RenderSettings& settings);

// What the Sweep section shows.
struct SweepStatus {
  bool visible = false;            // a sweep was read, or failed to be
  std::string error;               // it failed: why
  SweepSetting setting;            // the current settings, as the sweep names them
  std::optional<SweepRow> current; // their row, if the sweep measured them
  // The most accurate row of the front that costs at most the current row's
  // CPU seconds (bestWithinCost), when the current row is known.
  std::optional<SweepRow> best;
  std::vector<std::string> lines; // the text, one a line

  // No row is as cheap and more accurate than the current one.
  bool currentOnFront() const { return current && current->pareto; }
};

SweepStatus sweepStatus(const LoadedSweep& sweep, const RenderSettings& settings);

} // namespace prism

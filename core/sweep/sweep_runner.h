// The settings sweep (docs/choosing-settings.md): every setting of a grid
// rendered, timed and compared with the reference picture, one SweepRow each.
//
// Settings that differ only in threshold or jitter share their pass 1 (the
// pixel centres depend only on depth and bailout): it is traced once per
// depth and bailout, and each such setting's row counts it in full, cost and
// rays, as if it had been rendered alone. What is shared is the tracing, not
// the measurement: each row is what `prism render` with its options costs.
// Runs shorter than 50 ms of CPU (SweepGrid::minTimedSeconds) are repeated,
// at most 16 times, and their mean taken.
#pragma once

#include "core/accel/accel.h"
#include "core/render/executor.h"
#include "core/sweep/reference.h"
#include "core/sweep/sweep_table.h"

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace prism {

// CPU time is accounted in scheduler ticks: a single 5 ms run would put the
// noise of a tick into the Pareto front, so short runs are repeated.
inline constexpr double kSweepMinTimedSeconds = 0.05;
inline constexpr int kSweepMaxRuns = 16;

struct SweepGrid {
  std::vector<double> thresholds{0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0};
  bool noAa = true; // also each depth and bailout without antialiasing
  std::vector<int> depths{1, 2, 3, 4, 5, 6, 7, 8};
  std::vector<bool> jitters{false, true};
  std::vector<double> bailouts{0.0, 0.5, 2.0};
  // How each setting is timed: its runs repeated until their CPU time adds
  // up to this (at most kSweepMaxRuns runs), the mean taken. 0: one run each.
  double minTimedSeconds = kSweepMinTimedSeconds;

  // Every setting, in the order the sweep runs them: by depth, then bailout;
  // --no-aa first, then by jitter and threshold.
  std::vector<SweepSetting> settings() const;
};

struct SweepProgress {
  int done = 0;           // settings measured
  int total = 0;          // settings in the grid
  double fraction = 0.0;  // of the estimated work, 0..1
  double etaSeconds = -1; // wall seconds still to go; negative until estimated
  std::string current;    // the options of the setting being rendered
};

using SweepProgressCallback = std::function<void(const SweepProgress&)>;

// The settings of `settings` that share their pass 1: runs of consecutive
// settings of one depth and bailout, as [first, last) index ranges, in order.
std::vector<std::pair<std::size_t, std::size_t>>
passOneGroups(const std::vector<SweepSetting>& settings);

// Renders and measures the settings of one such group (one depth and
// bailout) at the reference's size on `executor`: their pass 1 traced once,
// each row counting it in full. Rows in the group's order, the Pareto front
// not marked. `starting(i)`, if given, is called before group[i] is rendered;
// `minTimedSeconds` as in SweepGrid. What runSweep does for each group, and
// what a distributed sweep hands out.
std::vector<SweepRow> runSweepGroup(const Scene& scene, const Accel& accel,
                                    std::span<const SweepSetting> group,
                                    const ReferencePicture& reference, Executor& executor,
                                    const std::function<void(std::size_t index)>& starting = {},
                                    double minTimedSeconds = kSweepMinTimedSeconds);

// Renders every setting of `grid` at the reference's size on `executor`,
// one after the other (each on all of the executor's workers), and compares
// each picture with `reference`. Rows in SweepGrid::settings() order, the
// Pareto front not yet marked.
std::vector<SweepRow> runSweep(const Scene& scene, const Accel& accel, const SweepGrid& grid,
                               const ReferencePicture& reference, Executor& executor,
                               const SweepProgressCallback& progress = {});

} // namespace prism

#include "core/sweep/sweep_runner.h"

#include "core/sweep/timed_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

namespace prism {

namespace {

RaysPerPixel perPixel(const RayCounts& counts, double pixels) {
  RaysPerPixel rays;
  rays.eye = double(counts.eye()) / pixels;
  rays.shadow = double(counts.shadow) / pixels;
  rays.reflected = double(counts.reflected) / pixels;
  rays.transmitted = double(counts.transmitted) / pixels;
  rays.pilot = double(counts.bailoutPilot) / pixels;
  return rays;
}

RenderSettings renderSettingsOf(const SweepSetting& setting, int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.maxDepth = setting.depth;
  settings.thresh = setting.thresh;
  settings.jitter = setting.jitter;
  settings.noAa = !setting.antialias;
  settings.bailout = setting.bailout;
  return settings;
}

// A run shorter than `minSeconds` is timed as the mean of several
// (sweep_runner.h). The pictures are the same each time.
TimedRun timedMean(const std::function<TimedRun()>& once, double minSeconds) {
  TimedRun run = once();
  double cpu = run.cpuSeconds, wall = run.wallSeconds;
  int runs = 1;
  for (; cpu < minSeconds && runs < kSweepMaxRuns; ++runs) {
    const TimedRun again = once();
    cpu += again.cpuSeconds;
    wall += again.wallSeconds;
  }
  run.cpuSeconds = cpu / runs;
  run.wallSeconds = wall / runs;
  return run;
}

// The wall time the groups still to run will take, from those that ran: a
// group's cost grows with depth by about the ratio measured between the last
// two depths (1.3 until two are known), bailouts alike.
class TimeEstimate {
public:
  void measured(int depth, double wallSeconds) {
    byDepth_[depth] += wallSeconds;
    lastDepth_ = depth;
    if (byDepth_.size() >= 2) {
      const auto last = std::prev(byDepth_.end());
      const auto before = std::prev(last);
      if (before->second > 0.0 && last->first == lastDepth_)
        growth_ = std::clamp(last->second / before->second, 1.0, 3.0);
    }
    lastGroup_ = wallSeconds;
  }
  // Predicted wall seconds of a group at `depth`.
  double predict(int depth) const {
    if (lastDepth_ < 0) return -1.0;
    return lastGroup_ * std::pow(growth_, double(std::max(0, depth - lastDepth_)));
  }

private:
  std::map<int, double> byDepth_; // summed over the bailouts
  int lastDepth_ = -1;
  double lastGroup_ = 0.0;
  double growth_ = 1.3;
};

} // namespace

std::vector<SweepSetting> SweepGrid::settings() const {
  std::vector<SweepSetting> all;
  for (int depth : depths) {
    for (double bailout : bailouts) {
      if (noAa) {
        // The threshold and jitter keep their defaults, which do not apply:
        // the setting reads back from the table as it was written.
        SweepSetting plain;
        plain.antialias = false;
        plain.depth = depth;
        plain.bailout = bailout;
        all.push_back(plain);
      }
      for (bool jitter : jitters)
        for (double thresh : thresholds)
          all.push_back({true, thresh, depth, jitter, bailout});
    }
  }
  return all;
}

std::vector<std::pair<std::size_t, std::size_t>>
passOneGroups(const std::vector<SweepSetting>& settings) {
  std::vector<std::pair<std::size_t, std::size_t>> groups; // [first, last)
  for (std::size_t i = 0; i < settings.size(); ++i) {
    if (i == 0 || settings[i].depth != settings[i - 1].depth ||
        settings[i].bailout != settings[i - 1].bailout)
      groups.push_back({i, i});
    groups.back().second = i + 1;
  }
  return groups;
}

std::vector<SweepRow> runSweepGroup(const Scene& scene, const Accel& accel,
                                    std::span<const SweepSetting> group,
                                    const ReferencePicture& reference, Executor& executor,
                                    const std::function<void(std::size_t index)>& starting,
                                    double minTimedSeconds) {
  const int width = reference.width, height = reference.height;
  const double pixels = double(width) * double(height);
  std::vector<SweepRow> rows;
  if (group.empty()) return rows;
  for (const SweepSetting& s : group)
    if (s.depth != group.front().depth || s.bailout != group.front().bailout)
      throw std::invalid_argument("runSweepGroup: the settings differ in depth or bailout");
  rows.reserve(group.size());

  // Pass 1 of this depth and bailout, which every setting of the group has.
  SweepSetting centresOnly = group.front();
  centresOnly.antialias = false;
  const TimedRun pass1 = timedMean(
      [&] {
        return runTimed(scene, accel, renderSettingsOf(centresOnly, width, height), executor,
                        Film(width, height), Pass1::Trace);
      },
      minTimedSeconds);

  for (std::size_t i = 0; i < group.size(); ++i) {
    const SweepSetting& setting = group[i];
    if (starting) starting(i);
    SweepRow row;
    row.setting = setting;
    const TimedRun* picture = &pass1;
    TimedRun pass2;
    RayCounts counts = pass1.counts;
    row.cpuSeconds = pass1.cpuSeconds;
    row.wallSeconds = pass1.wallSeconds;
    if (setting.antialias) {
      pass2 = timedMean(
          [&] {
            return runTimed(scene, accel, renderSettingsOf(setting, width, height), executor,
                            pass1.film, Pass1::Keep);
          },
          minTimedSeconds);
      counts += pass2.counts;
      row.cpuSeconds += pass2.cpuSeconds;
      row.wallSeconds += pass2.wallSeconds;
      picture = &pass2;
    }
    row.rays = perPixel(counts, pixels);
    row.supersampled = double(std::count(picture->film.supersampled.begin(),
                                         picture->film.supersampled.end(), std::uint8_t(1))) /
                       pixels;
    row.error = compareImages(picture->film.radiance, picture->avgmax, reference.radiance,
                              reference.avgmax, width, height);
    rows.push_back(row);
  }
  return rows;
}

std::vector<SweepRow> runSweep(const Scene& scene, const Accel& accel, const SweepGrid& grid,
                               const ReferencePicture& reference, Executor& executor,
                               const SweepProgressCallback& progress) {
  const std::vector<SweepSetting> settings = grid.settings();
  const auto groups = passOneGroups(settings);
  std::vector<SweepRow> rows;
  rows.reserve(settings.size());

  TimeEstimate estimate;
  const auto start = std::chrono::steady_clock::now();
  // Before setting `index` (of `settings`), the first `index` being done.
  auto report = [&](std::size_t group, std::size_t index) {
    if (!progress) return;
    const std::size_t inGroup = index - groups[group].first;
    SweepProgress p;
    p.done = int(index);
    p.total = int(settings.size());
    p.current = settingOptions(settings[index]);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double remaining = 0.0;
    bool known = true;
    for (std::size_t g = group; g < groups.size(); ++g) {
      const double predicted = estimate.predict(settings[groups[g].first].depth);
      if (predicted < 0.0) known = false;
      const std::size_t size = groups[g].second - groups[g].first;
      // The current group: the share of its settings not yet done.
      remaining += g == group ? predicted * double(size - inGroup) / double(size) : predicted;
    }
    if (known) {
      p.etaSeconds = remaining;
      p.fraction = elapsed / std::max(elapsed + remaining, 1e-9);
    } else {
      p.fraction = double(index) / double(std::max<std::size_t>(settings.size(), 1));
    }
    progress(p);
  };

  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto groupStart = std::chrono::steady_clock::now();
    // Named variables, not a structured binding: the lambda below captures
    // `first`, which Clang before 16 does not allow of a binding.
    const std::size_t first = groups[g].first, last = groups[g].second;
    report(g, first);
    const std::vector<SweepRow> groupRows = runSweepGroup(
        scene, accel, std::span(settings).subspan(first, last - first), reference, executor,
        [&](std::size_t i) { report(g, first + i); }, grid.minTimedSeconds);
    rows.insert(rows.end(), groupRows.begin(), groupRows.end());
    estimate.measured(
        settings[first].depth,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - groupStart).count());
  }
  if (progress) {
    SweepProgress p;
    p.done = p.total = int(settings.size());
    p.fraction = 1.0;
    p.etaSeconds = 0.0;
    progress(p);
  }
  return rows;
}

} // namespace prism

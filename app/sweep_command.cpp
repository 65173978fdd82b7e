#include "sweep_command.h"

#include "cli_options.h"
#include "load_scene.h"
#include "process_launch.h"
#include "progress.h"
#include "render_command.h"
#include "sweep_distributed.h"
#include "sweep_plots.h"

#include "core/io/image_io.h"
#include "core/io/pending_file.h"
#include "core/render/exposure.h"
#include "core/render/parallel.h"
#include "core/sweep/reference.h"
#include "core/sweep/sweep_runner.h"
#include "core/system/memory_budget.h"
#include "core/system/system_info.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace prism {

namespace {

namespace fs = std::filesystem;

// The reference, the film of one setting and its pass 1 kept for the others,
// and the 8-bit pictures compared: about four renders' worth per pixel.
constexpr std::uint64_t kSweepBytesPerPixel = 4 * kRenderBytesPerPixel;

std::pair<int, int> sweepSize(const SweepCommandOptions& o, const Scene& scene) {
  if (!o.size.empty()) return {o.size[0], o.size[1]};
  if (!o.quick) return {scene.width, scene.height};
  const double longer = std::max(scene.width, scene.height);
  auto side = [&](int pixels) {
    return std::max(1, int(std::lround(pixels * kQuickSweepSide / longer)));
  };
  return {side(scene.width), side(scene.height)};
}

std::string duration(double seconds) {
  char text[32];
  if (seconds < 60)
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  else
    std::snprintf(text, sizeof text, "%d min %02d s", int(seconds) / 60, int(seconds) % 60);
  return text;
}

std::string progressBar(double fraction) {
  constexpr int kWidth = 24;
  const int filled = std::clamp(int(fraction * kWidth + 0.5), 0, kWidth);
  return "[" + std::string(std::size_t(filled), '#') +
         std::string(std::size_t(kWidth - filled), '.') + "]";
}

// Under MPI rank 0 hears only how many groups of settings the job finished.
std::string distributedSweepLine(int done, int total, int processes, double elapsed) {
  return "sweep: " + progressBar(total > 0 ? double(done) / total : 1.0) + " " +
         std::to_string(done) + "/" + std::to_string(total) + " groups of settings over " +
         std::to_string(processes) + " processes, " + duration(elapsed);
}

std::string sweepLine(const SweepProgress& p, double elapsed) {
  std::string line = "sweep: " + progressBar(p.fraction) + " " + std::to_string(p.done) + "/" +
                     std::to_string(p.total) + " settings, " + duration(elapsed);
  if (p.etaSeconds >= 0) line += ", about " + duration(p.etaSeconds) + " to go";
  if (!p.current.empty()) line += " (" + p.current + ")";
  return line;
}

nlohmann::ordered_json summaryJson(const SweepCommandOptions& o, const ReferencePicture& reference,
                                   const ReferenceSettings& referenceSettings,
                                   const std::vector<SweepRow>& rows, int threads,
                                   double cpuSeconds, double wallSeconds) {
  return {
      {"scene", fs::path(o.scene).filename().string()},
      {"machine", machineDescription()},
      {"threads", threads},
      {"width", reference.width},
      {"height", reference.height},
      {"reference",
       {{"samples_per_pixel", kReferenceSide * kReferenceSide},
        {"first_depth", referenceSettings.firstDepth},
        {"last_depth", referenceSettings.lastDepth},
        {"converged", reference.converged},
        {"deepest", reference.deepest},
        {"avgmax", reference.avgmax},
        {"rays", reference.counts.total()},
        {"cpu_s", reference.cpuSeconds},
        {"wall_s", reference.wallSeconds}}},
      {"settings", rows.size()},
      {"min_timed_seconds", o.minSeconds},
      {"cpu_s", cpuSeconds},
      {"wall_s", wallSeconds},
  };
}

// `ranks`: under MPI, each process's share (empty for one process).
void printSummary(const ReferencePicture& reference, const std::vector<SweepRow>& rows,
                  const std::vector<RankStats>& ranks, const std::string& dir) {
  if (!ranks.empty()) {
    std::string groups;
    for (const RankStats& r : ranks)
      groups += (groups.empty() ? "" : ", ") + std::to_string(r.tiles);
    std::fprintf(stderr, "processes       %zu, groups of settings rendered by each: %s\n",
                 ranks.size(), groups.c_str());
  }
  std::fprintf(stderr, "reference       %d samples per pixel, depth up to %d%s, %.1f s CPU\n",
               kReferenceSide * kReferenceSide, reference.deepest,
               reference.converged ? "" : " (a deeper trace still changed some pixel)",
               reference.cpuSeconds);
  const SweepSetting defaults;
  if (const SweepRow* row = findSetting(rows, defaults))
    std::fprintf(stderr, "default         %s: %.3f s CPU, PSNR %.1f dB, %.2f%% > 2 levels off\n",
                 settingOptions(defaults).c_str(), row->cpuSeconds, row->error.psnr,
                 100.0 * row->error.over2);
  std::vector<const SweepRow*> front;
  for (const SweepRow& row : rows)
    if (row.pareto) front.push_back(&row);
  std::sort(front.begin(), front.end(),
            [](const SweepRow* a, const SweepRow* b) { return a->cpuSeconds < b->cpuSeconds; });
  std::fprintf(stderr, "Pareto front    (CPU s, PSNR dB, setting; cheapest first)\n");
  for (const SweepRow* row : front)
    std::fprintf(stderr, "  %8.3f  %6.1f  %s\n", row->cpuSeconds, row->error.psnr,
                 settingOptions(row->setting).c_str());
  std::fprintf(stderr, "written         %s/{sweep.csv,sweep.json,reference.png,*.png}\n",
               dir.c_str());
}

} // namespace

CLI::App* addSweepCommand(CLI::App& app, SweepCommandOptions& o) {
  CLI::App* command = app.add_subcommand(
      "sweep", "Measure speed against accuracy: render a reference and a grid of settings");
  addSceneArgument(*command, o.scene);
  command->add_option("-o,--output", o.output, "Folder for sweep.csv, sweep.json and the plots")
      ->required();
  command->add_option("--size", o.size, "Image size W H (overrides the scene's resolution)")
      ->expected(2)
      ->check(CLI::Range(1, 32768));
  command->add_flag("--quick", o.quick,
                    "Small pictures: the scene's at " + std::to_string(kQuickSweepSide) +
                        " pixels on the longer side");
  addRangedOption(*command, "--threads", o.threads,
                  "Render threads (0: every core this process may use)", 0, 1024);
  addRangedOption(*command, "--min-seconds", o.minSeconds,
                  "Time each setting over repeated runs until they add up to this much CPU (at "
                  "most " +
                      std::to_string(kSweepMaxRuns) + " runs; 0: one run each)",
                  0.0, 3600.0);
  command->add_flag("-q,--quiet", o.quiet, "No progress and no summary on stderr");
  return command;
}

int runSweepCommand(const SweepCommandOptions& o, ProcessGroup* group) {
  // Under MPI every process runs this function, as in runRenderCommand: rank 0
  // speaks for the job (progress, errors, the files) and the others stay
  // quiet; where a process could fail alone, the processes agree first.
  const bool speaks = !group || group->rank() == 0;
  QuietStderr quietRank(!speaks);
  auto agree = [&](bool ok) { return agreeOnSuccess(group, ok, quietRank); };

  // Every process reads the scene itself.
  std::optional<Scene> loaded = loadSceneReporting(o.scene);
  if (!agree(loaded.has_value())) return kExitUsage;
  // The folder before any rendering, so that a typo in its name costs no
  // sweep; after the scene, so that a scene error leaves no empty folder.
  // Only rank 0 writes files.
  const fs::path dir = o.output;
  const bool writable = !speaks || succeeds([&] {
    fs::create_directories(dir);
    checkWritableFile(dir / "sweep.csv");
  });
  if (!agree(writable)) return kExitFailure;
  const Scene& scene = *loaded;
  // Named variables, not a structured binding: lambdas below capture them,
  // which Clang before 16 does not allow of a binding.
  const std::pair<int, int> sized = sweepSize(o, scene);
  const int width = sized.first, height = sized.second;
  RenderSettings size;
  size.width = width;
  size.height = height;
  const std::optional<std::string> problem = imageMemoryProblem(size, kSweepBytesPerPixel, "sweep");
  if (problem) std::cerr << "prism: error: " << *problem << "\n";
  if (!agree(!problem)) return kExitFailure;

  const auto accel = makeAccel(scene, AccelKind::Bvh);
  const int threads = resolveThreadCount(o.threads);
  ThreadPoolExecutor executor(threads);
  const double cpuStart = processCpuSeconds();
  const auto wallStart = std::chrono::steady_clock::now();

  ReferenceSettings referenceSettings;
  referenceSettings.width = width;
  referenceSettings.height = height;
  ReferencePicture reference;
  SweepGrid grid;
  grid.minTimedSeconds = o.minSeconds;
  std::vector<SweepRow> rows;
  int groupsHere = 0;
  {
    ProgressReporter reporter(!o.quiet && speaks);
    // Under MPI every process renders the whole reference itself, before any
    // setting, rather than the reference being an item of the hand-out: a
    // setting's error is measured where the setting is rendered (sending
    // every setting's float picture to rank 0 instead would move about 400
    // pictures), so each process needs the reference first. Rendered by all
    // at once, it costs the job no more wall time than rank 0 rendering it
    // while the others wait, and needs no transfer; it does not depend on
    // the thread count (its samples are jittered by a hash), so every
    // process holds the single-process sweep's reference.
    reference = renderReference(scene, *accel, referenceSettings, executor, [&](double f) {
      reporter.show([&](double elapsed) {
        return "sweep: reference " + progressBar(f) + " " + duration(elapsed);
      });
    });
    if (group) {
      DistributedSweep sweep = runSweepOverGroup(
          *group, scene, *accel, grid, reference, executor, [&](int done, int total) {
            reporter.show([&](double elapsed) {
              return distributedSweepLine(done, total, group->size(), elapsed);
            });
          });
      rows = std::move(sweep.rows);
      groupsHere = sweep.groupsHere;
    } else {
      rows = runSweep(scene, *accel, grid, reference, executor, [&](const SweepProgress& p) {
        reporter.show([&](double elapsed) { return sweepLine(p, elapsed); });
      });
    }
  }
  markParetoFront(rows);
  double cpuSeconds = processCpuSeconds() - cpuStart;
  const double wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  std::vector<RankStats> ranks; // on rank 0 under MPI
  if (group) {
    // The job's CPU time: every process's (the rays are in the table).
    ranks = group->gatherStats({group->rank(), hostName(), threads, groupsHere, 0, cpuSeconds});
    cpuSeconds = 0.0;
    for (const RankStats& r : ranks)
      cpuSeconds += r.cpuSeconds;
  }

  std::string warnings;
  const bool written = !speaks || succeeds([&] {
    writeFileAtomically(dir / "sweep.csv", [&](std::ostream& out) { out << formatSweepCsv(rows); });
    const auto json =
        summaryJson(o, reference, referenceSettings, rows, threads, cpuSeconds, wallSeconds);
    writeFileAtomically(dir / "sweep.json",
                        [&](std::ostream& out) { out << json.dump(2) << "\n"; });
    writeImage8(dir / "reference.png", width, height,
                exposeImage(reference.radiance, exposureScale(reference.avgmax)),
                "Prism sweep reference: " + std::to_string(kReferenceSide * kReferenceSide) +
                    " samples per pixel, depth up to " + std::to_string(reference.deepest) +
                    ", exposed by avgmax of the pixel centres");
    warnings = writeSweepPlots(rows, dir.string(), fs::path(o.scene).stem().string());
  });
  // The others wait for rank 0's files, so that every process ends with the
  // job's status.
  if (!agree(written)) return kExitFailure;
  if (!speaks) return kExitOk;
  if (!warnings.empty()) std::cerr << "prism: warning: " << warnings << "\n";
  if (!o.quiet) printSummary(reference, rows, ranks, dir.string());
  return kExitOk;
}

} // namespace prism

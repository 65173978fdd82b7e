#include "bench_command.h"

#include "bench_latency.h"
#include "bench_measure.h"
#include "bench_startup.h"
#include "cli_options.h"
#include "load_scene.h"
#include "render_command.h"

#include "core/io/scene_loader.h"
#include "core/render/parallel.h"
#include "core/system/system_info.h"
#include "tools/scene_generators.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

namespace prism {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kRecordCap = 1000000; // recorded shadow/secondary queries per scene

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// "12.34" million rays per second, "~" in front when measured on a sample.
std::string mrays(const Throughput& t) {
  if (t.raysPerSecond <= 0.0) return "-";
  return (t.sampled ? "~" : "") + fixed(t.raysPerSecond * 1e-6, t.raysPerSecond < 1e5 ? 4 : 2);
}

struct Built {
  std::unique_ptr<Accel> accel;
  double buildSeconds = 0.0;
};

Built build(const Scene& scene, AccelKind kind) {
  const auto start = Clock::now();
  Built b;
  b.accel = makeAccel(scene, kind);
  b.buildSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  return b;
}

double bytesPerPrimitive(const Scene& scene, const Accel& accel) {
  return scene.primitiveCount() > 0 ? double(accel.memoryBytes()) / double(scene.primitiveCount())
                                    : 0.0;
}

// One row of a scene table: the figures of one accel on one thread count.
struct Row {
  std::string scene;
  std::size_t primitives = 0;
  AccelKind accel = AccelKind::Bvh;
  double buildSeconds = 0.0, bytesPerPrim = 0.0;
  Throughput eye, eyeOneByOne, shadow, secondary, shaded;
  std::optional<double> renderSeconds; // wall; nullopt: not run
  bool renderEstimated = false;
};

void printTable(const std::vector<Row>& rows, int threads) {
  std::cout << "\n"
            << threads << (threads == 1 ? " thread" : " threads")
            << " (Mrays/s; intersection only for eye, shadow, secondary: eye rays in the "
               "renderer's bundles of 8 x 8 pixels, and one by one; shaded: every ray of a "
               "depth-limited trace of the eye rays, with shading)\n\n";
  std::cout << "| scene | primitives | accel | build s | bytes/prim | eye | eye 1-by-1 | shadow | "
               "secondary | shaded | render s |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    std::cout << "| " << r.scene << " | " << r.primitives << " | " << accelKindName(r.accel)
              << " | " << fixed(r.buildSeconds, 3) << " | " << fixed(r.bytesPerPrim, 1) << " | "
              << mrays(r.eye) << " | " << mrays(r.eyeOneByOne) << " | " << mrays(r.shadow) << " | "
              << mrays(r.secondary) << " | " << mrays(r.shaded) << " | "
              << (r.renderSeconds ? (r.renderEstimated ? "~" : "") + fixed(*r.renderSeconds, 2)
                                  : std::string("-"))
              << " |\n";
  }
}

void benchScenes(const BenchCommandOptions& o, int allThreads) {
  std::vector<int> threadCounts{1};
  if (allThreads > 1) threadCounts.push_back(allThreads);
  std::map<int, std::vector<Row>> tables;
  std::vector<std::string> summary;
  for (const std::string& path : o.scenes) {
    const std::string name = std::filesystem::path(path).filename().string();
    std::cerr << "bench: " << name << "\n";
    const std::optional<Scene> loaded = loadSceneReporting(path);
    if (!loaded) continue;
    const Scene& scene = *loaded;
    RenderSettings settings;
    settings.width = settings.height = o.size;
    settings.maxDepth = o.depth;
    settings.thresh = o.thresh;
    // The rays are the same for every accel (they all find the same hits).
    RaySet rays;
    {
      const auto reference = makeAccel(scene, AccelKind::Bvh);
      rays = recordRays(scene, *reference, o.size, o.size, o.depth, kRecordCap);
    }
    std::optional<std::uint64_t> renderRays; // all rays of the full render, once known
    std::map<std::pair<AccelKind, int>, double> renderTimes;
    for (AccelKind kind : o.accels) {
      const Built b = build(scene, kind);
      for (int threads : threadCounts) {
        Row r;
        r.scene = name;
        r.primitives = scene.primitiveCount();
        r.accel = kind;
        r.buildSeconds = b.buildSeconds;
        r.bytesPerPrim = bytesPerPrimitive(scene, *b.accel);
        r.eye = measureEyeBundles(*b.accel, rays, threads, o.budget);
        r.eyeOneByOne = measureQueries(*b.accel, rays.eye, false, threads, o.budget);
        r.shadow = measureQueries(*b.accel, rays.shadow, true, threads, o.budget);
        r.secondary = measureQueries(*b.accel, rays.secondary, false, threads, o.budget);
        r.shaded = measureShaded(scene, *b.accel, rays, o.depth, threads, o.budget);
        settings.threads = threads;
        if (!r.shaded.sampled) {
          const RenderTiming t = timeRender(scene, *b.accel, settings);
          r.renderSeconds = t.wallSeconds;
          renderRays = t.counts.total();
        } else if (renderRays && r.shaded.raysPerSecond > 0.0) {
          // Too slow to run within the budget: the same rays at the measured rate.
          r.renderSeconds = double(*renderRays) / r.shaded.raysPerSecond;
          r.renderEstimated = true;
        }
        if (r.renderSeconds) renderTimes[{kind, threads}] = *r.renderSeconds;
        tables[threads].push_back(r);
        std::cerr << "  " << accelKindName(kind) << ", " << threads << " thread(s) done\n";
      }
    }
    for (int threads : threadCounts) {
      auto time = [&](AccelKind k) -> std::optional<double> {
        const auto it = renderTimes.find({k, threads});
        return it == renderTimes.end() ? std::nullopt : std::optional<double>(it->second);
      };
      const auto bvh = time(AccelKind::Bvh), groups = time(AccelKind::Groups),
                 none = time(AccelKind::None);
      std::string line = name + ", " + std::to_string(threads) + " thread(s): render";
      if (bvh && groups) line += ", bvh " + fixed(*groups / *bvh, 1) + "x faster than groups";
      if (bvh && none) line += ", bvh " + fixed(*none / *bvh, 0) + "x faster than none";
      summary.push_back(line);
    }
    if (renderTimes.count({AccelKind::Bvh, 1}) && renderTimes.count({AccelKind::Bvh, allThreads}) &&
        allThreads > 1) {
      summary.push_back(
          name + ": bvh render on " + std::to_string(allThreads) + " threads " +
          fixed(renderTimes[{AccelKind::Bvh, 1}] / renderTimes[{AccelKind::Bvh, allThreads}], 2) +
          "x faster than on 1");
    }
  }
  for (const auto& [threads, rows] : tables)
    printTable(rows, threads);
  if (!summary.empty()) {
    std::cout << "\n";
    for (const std::string& s : summary)
      std::cout << "- " << s << "\n";
  }
}

// Per-ray cost of eye and shadow rays as scenes grow, for docs/performance.md's plot.
void benchScaling(const BenchCommandOptions& o) {
  std::ofstream data;
  if (!o.data.empty()) {
    data.open(o.data);
    data << "# generator primitives accel build_s bytes_per_prim eye_ns shadow_ns\n";
  }
  std::cout << "\nScaling: eye rays at " << o.size << " x " << o.size
            << " (one by one: the hierarchy alone) and their shadow rays, intersection only, "
               "1 thread\n\n"
            << "| scene | primitives | accel | build s | bytes/prim | eye ns/ray | shadow ns/ray "
               "|\n|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::map<std::size_t, double>> bvhEye;
  const std::vector<std::pair<std::string, Scene (*)(std::size_t)>> generators{
      {"soup", [](std::size_t n) { return makePolygonSoup(n); }},
      {"scaled-soup", [](std::size_t n) { return makeScaledPolygonSoup(n); }},
      {"sphereflake", [](std::size_t n) { return makeSphereflake(n); }}};
  for (const auto& [generator, make] : generators) {
    for (std::size_t n = 1000; n <= o.scalingMax; n *= 10) {
      std::cerr << "bench: " << generator << " " << n << "\n";
      const Scene scene = make(n);
      RaySet rays;
      {
        const auto reference = makeAccel(scene, AccelKind::Bvh);
        rays = recordRays(scene, *reference, o.size, o.size, 1, kRecordCap);
      }
      for (AccelKind kind : o.accels) {
        if (kind == AccelKind::None && n > 10000) continue; // hours, and says nothing new
        const Built b = build(scene, kind);
        const Throughput eye = measureQueries(*b.accel, rays.eye, false, 1, o.budget);
        const Throughput shadow = measureQueries(*b.accel, rays.shadow, true, 1, o.budget);
        const double eyeNs = eye.raysPerSecond > 0 ? 1e9 / eye.raysPerSecond : 0.0;
        const double shadowNs = shadow.raysPerSecond > 0 ? 1e9 / shadow.raysPerSecond : 0.0;
        const double bpp = bytesPerPrimitive(scene, *b.accel);
        std::cout << "| " << generator << " | " << scene.primitiveCount() << " | "
                  << accelKindName(kind) << " | " << fixed(b.buildSeconds, 3) << " | "
                  << fixed(bpp, 1) << " | " << (eye.sampled ? "~" : "") << fixed(eyeNs, 0) << " | "
                  << (shadow.sampled ? "~" : "") << fixed(shadowNs, 0) << " |\n";
        if (data.is_open())
          data << generator << " " << scene.primitiveCount() << " " << accelKindName(kind) << " "
               << b.buildSeconds << " " << bpp << " " << eyeNs << " " << shadowNs << "\n";
        if (kind == AccelKind::Bvh) bvhEye[generator][n] = eyeNs;
      }
    }
  }
  std::cout << "\n";
  for (const auto& [generator, costs] : bvhEye) {
    if (costs.count(10000) && costs.count(1000000))
      std::cout << "- " << generator << ": bvh eye-ray cost grows "
                << fixed(costs.at(1000000) / costs.at(10000), 2)
                << "x from 10^4 to 10^6 primitives\n";
  }
}

} // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Measure acceleration structures and ray throughput (docs/performance.md)");
  cmd->add_option("scenes", o.scenes, "Scene files to measure (none: only the scaling series)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--accel", o.accels, "Acceleration modes to measure [bvh groups none]")
      ->transform(CLI::CheckedTransformer(accelKindsByName(), CLI::ignore_case))
      ->delimiter(',');
  addRangedOption(*cmd, "--size", o.size, "Image size of the renders and eye rays (square)", 8,
                  8192);
  addRangedOption(*cmd, "--depth", o.depth, "Maximum ray depth", 1, 1000);
  addRangedOption(*cmd, "--thresh", o.thresh, "Antialiasing threshold", 0.0, 1.0);
  addRangedOption(*cmd, "--threads", o.threads, "The \"all threads\" count (0: every core)", 0,
                  1024);
  addRangedOption(*cmd, "--budget", o.budget,
                  "Seconds one throughput figure may take; slower ones are measured on an evenly "
                  "spread sample of the rays (marked ~)",
                  0.01, 3600.0);
  cmd->add_flag("!--no-scaling", o.scaling, "Skip the scaling series on generated scenes");
  cmd->add_option("--scaling-max", o.scalingMax, "Largest scene of the scaling series")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(1000), std::size_t(100000000)));
  cmd->add_option("--data", o.data, "Write the scaling series to this file (for gnuplot)");
  cmd->add_flag("--latency", o.latency,
                "Instead: the previewer's latency after a light move on each scene (640 x 480)");
  cmd->add_flag(
      "--startup", o.startup,
      "Instead: the CPU time and memory of `prism --version`, `--help` and a tiny render");
  return cmd;
}

int runBenchCommand(const BenchCommandOptions& o) {
  const int allThreads = resolveThreadCount(o.threads);
  if (o.startup) {
    benchStartup(25);
    return kExitOk;
  }
  if (o.latency) {
    LatencyOptions latency;
    latency.scenes = o.scenes;
    latency.depth = o.depth;
    latency.threads = o.threads;
    benchLatency(latency);
    return kExitOk;
  }
  std::cout << "prism bench on " << machineDescription() << ", " << allThreads
            << " threads; renders at " << o.size << " x " << o.size << ", depth " << o.depth
            << ", thresh " << o.thresh << "\n";
  if (!o.scenes.empty()) benchScenes(o, allThreads);
  if (o.scaling) benchScaling(o);
  return kExitOk;
}

} // namespace prism

#include "render_command.h"

#include "load_scene.h"
#include "progress.h"

#include "core/exposure.h"
#include "core/image_formation.h"
#include "core/image_io.h"
#include "core/memory_budget.h"
#include "core/parallel.h"
#include "core/pending_file.h"
#include "core/scene_loader.h"
#include "core/stats.h"
#include "core/system_info.h"
#include "core/tracer.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace prism {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int printPixelTree(const Scene& scene, const Accel& accel, const RenderSettings& settings, int x,
                   int y) {
  const Camera camera(scene.camera, settings.width, settings.height);
  Tracer tracer(scene, accel, settings.maxDepth);
  RayCounts counts;
  RayTreeNode root;
  tracer.trace(camera.eyeRay(x + 0.5, y + 0.5), 1, counts, &root);
  std::cout << "pixel (" << x << ", " << y << ") of " << settings.width << " x " << settings.height
            << ", max depth " << settings.maxDepth << ": centre ray\n";
  printRayTree(std::cout, root, scene);
  std::cout << "rays: 1 eye, " << counts.shadow << " shadow, " << counts.reflected << " reflected, "
            << counts.transmitted << " transmitted (" << counts.tirEvents
            << " total internal reflections)\n";
  return kExitOk;
}

} // namespace

void addRenderSettingsOptions(CLI::App& command, RenderCommandOptions& o) {
  command
      .add_option("--depth", o.depth, "Maximum ray depth D >= 1 (1: ray casting with shadows) [5]")
      ->check(CLI::Range(1, 1000));
  command.add_option("--thresh", o.thresh, "Antialiasing threshold in [0, 1]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  command.add_option("--size", o.size, "Image size W H (overrides the scene's resolution)")
      ->expected(2)
      ->check(CLI::Range(1, 32768));
  command.add_option("--threads", o.threads, "Render threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  command.add_flag("--jitter", o.jitter, "Jitter the 16 sub-samples within their cells");
  command
      .add_option("--accel", o.accel,
                  "Ray acceleration: bvh (SAH hierarchy, default), groups (the push/pop "
                  "hierarchy) or none (test every primitive)")
      ->transform(CLI::CheckedTransformer(accelKindsByName(), CLI::ignore_case));
}

CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& o) {
  CLI::App* command = app.add_subcommand("render", "Render a scene to an image file, headless");
  command->add_option("scene", o.scene, "Scene file (.sc, .nff or .obj)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", o.output,
                      "Output image: .tif/.tiff (8-bit RGB), .png, .exr (float radiance), ...");
  addRenderSettingsOptions(*command, o);
  command->add_flag("--float", o.floatTiff,
                    "Write float radiance before exposure (implied by .exr and .hdr)");
  command->add_option("--stats-json", o.statsJson,
                      "Also write the statistics as JSON to this file");
  command->add_option("--pixel", o.pixel, "Print the ray tree of pixel X Y instead of rendering")
      ->expected(2)
      ->check(CLI::NonNegativeNumber);
  command->add_flag("-q,--quiet", o.quiet, "No progress and no statistics on stderr");
  command->callback([&o] {
    if (o.pixel.empty() && o.output.empty())
      throw CLI::RequiredError("-o,--output (unless --pixel is given)");
  });
  return command;
}

int runRenderCommand(const RenderCommandOptions& o) {
  // Every output is checked before any work: a typo in a folder name must not
  // cost a render, or leave a picture without its statistics.
  const bool writable = succeeds([&] {
    if (o.pixel.empty()) checkWritable(o.output);
    if (!o.statsJson.empty()) checkWritableFile(o.statsJson);
  });
  if (!writable) return kExitFailure;

  const auto loadStart = Clock::now();
  const std::optional<Scene> loaded = loadSceneReporting(o.scene);
  if (!loaded) return kExitUsage;
  const Scene& scene = *loaded;
  const double loadSeconds = secondsSince(loadStart);

  RenderSettings settings;
  settings.width = o.size.empty() ? scene.width : o.size[0];
  settings.height = o.size.empty() ? scene.height : o.size[1];
  settings.maxDepth = o.depth.value_or(5);
  settings.thresh = o.thresh;
  settings.jitter = o.jitter;
  settings.threads = resolveThreadCount(o.threads);

  if (!o.pixel.empty() && (o.pixel[0] >= settings.width || o.pixel[1] >= settings.height)) {
    std::cerr << "prism: error: --pixel " << o.pixel[0] << " " << o.pixel[1] << " is outside the "
              << settings.width << " x " << settings.height << " image\n";
    return kExitUsage;
  }
  if (o.pixel.empty()) {
    const std::string what =
        "a " + std::to_string(settings.width) + " x " + std::to_string(settings.height) + " render";
    if (const std::optional<std::string> problem = memoryProblem(
            imageBytes(settings.width, settings.height, kRenderBytesPerPixel), what)) {
      std::cerr << "prism: error: " << *problem << "\n";
      return kExitFailure;
    }
  }

  const auto buildStart = Clock::now();
  const auto accel = makeAccel(scene, o.accel);
  const double buildSeconds = secondsSince(buildStart);
  if (!o.pixel.empty()) return printPixelTree(scene, *accel, settings, o.pixel[0], o.pixel[1]);

  RenderStats stats;
  const double cpuStart = processCpuSeconds();
  const auto renderStart = Clock::now();
  RenderResult result;
  {
    ProgressReporter reporter(!o.quiet);
    result = render(scene, *accel, settings, [&](const RenderProgress& p) { reporter.update(p); });
  }
  stats.wallSeconds = secondsSince(renderStart);
  stats.cpuSeconds = processCpuSeconds() - cpuStart;

  const bool written = succeeds([&] {
    if (isFloatFormat(o.output) || o.floatTiff) {
      writeImageFloat(o.output, settings.width, settings.height, result.film.radiance);
    } else {
      writeImage8(o.output, settings.width, settings.height,
                  exposeImage(result.film.radiance, exposureScale(result.avgmax)));
    }
  });
  if (!written) return kExitFailure;

  stats.scene = o.scene;
  stats.machine = machineDescription();
  stats.accel = accelKindName(o.accel);
  stats.width = settings.width;
  stats.height = settings.height;
  stats.maxDepth = settings.maxDepth;
  stats.thresh = settings.thresh;
  stats.jitter = settings.jitter;
  stats.threads = settings.threads;
  stats.primitives = scene.primitiveCount();
  stats.loadSeconds = loadSeconds;
  stats.buildSeconds = buildSeconds;
  stats.counts = result.counts;
  stats.supersampledPixels = result.supersampledPixels;
  stats.avgmax = result.avgmax;
  if (!o.quiet) std::cerr << formatStatsText(stats);
  if (!o.statsJson.empty()) {
    const std::string json = formatStatsJson(stats);
    if (!succeeds(
            [&] { writeFileAtomically(o.statsJson, [&](std::ostream& out) { out << json; }); }))
      return kExitFailure;
  }
  return kExitOk;
}

} // namespace prism

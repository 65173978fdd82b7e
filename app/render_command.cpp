#include "render_command.h"

#include "cli_options.h"
#include "load_scene.h"
#include "process_launch.h"
#include "progress.h"

#include "core/io/file_extension.h"
#include "core/io/image_io.h"
#include "core/io/pending_file.h"
#include "core/io/picture_writer.h"
#include "core/io/scene_loader.h"
#include "core/math/math.h"
#include "core/math/model_range.h"
#include "core/render/exposure.h"
#include "core/render/image_formation.h"
#include "core/render/parallel.h"
#include "core/render/pixel_tree.h"
#include "core/render/stats.h"
#include "core/render/tracer.h"
#include "core/render/work_estimate.h"
#include "core/system/memory_budget.h"
#include "core/system/system_info.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace prism {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The shortest text that reads back as exactly `x`.
std::string number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

Vec3 point(const std::vector<double>& xyz) { return Vec3(xyz[0], xyz[1], xyz[2]); }

std::string text(const Vec3& v) { return number(v.x) + " " + number(v.y) + " " + number(v.z); }

bool isStdio(const std::string& name) { return name == kStdio; }

// The picture's format as an extension (".png"): --format's for `-o -`,
// otherwise the output file's.
std::string outputExtension(const RenderCommandOptions& o) {
  if (!isStdio(o.output)) return lowerExtension(o.output);
  std::string format = o.format;
  if (!format.empty() && format[0] == '.') format.erase(0, 1);
  return lowerExtension("x." + format);
}

bool writesFloat(const RenderCommandOptions& o) {
  return o.floatTiff || isFloatFormat("x" + outputExtension(o));
}

// The pixels [x0, x1) x [y0, y1) of `film`.
Film cropped(const Film& film, int x0, int y0, int x1, int y1) {
  Film out(x1 - x0, y1 - y0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t from = film.index(x, y), to = out.index(x - x0, y - y0);
      out.centre[to] = film.centre[from];
      out.radiance[to] = film.radiance[from];
      out.supersampled[to] = film.supersampled[from];
    }
  return out;
}

// One side of the scene's resolution at `percent`: rounded, at least 1.
int scaledSide(int side, double percent) {
  return std::max(1, int(std::lround(double(side) * percent / 100.0)));
}

} // namespace

void addRenderSettingsOptions(CLI::App& command, RenderCommandOptions& o) {
  command
      .add_option("--depth", o.depth, "Maximum ray depth D >= 1 (1: ray casting with shadows) [5]")
      ->check(CLI::Range(1, 1000));
  addRangedOption(command, "--thresh", o.thresh, "Antialiasing threshold in [0, 1]", 0.0, 1.0);
  command.add_option("--size", o.size, "Image size W H (overrides the scene's resolution)")
      ->expected(2)
      ->check(CLI::Range(1, 32768));
  addRangedOption(command, "--threads", o.threads,
                  "Render threads (0: every core this process may use)", 0, 1024);
  command.add_flag("--jitter", o.jitter, "Jitter the 16 sub-samples within their cells");
  command.add_flag("--no-aa", o.noAa,
                   "No antialiasing: pass 1 only, one eye ray through each pixel centre");
  addRangedOption(command, "--bailout", o.bailout,
                  "Skip mirror and refracted rays that cannot change a sample's 8-bit value by "
                  "more than W levels in all (0: exact)",
                  0.0, 255.0);
  command
      .add_option("--accel", o.accel,
                  "Ray acceleration: bvh (SAH hierarchy, default), groups (the push/pop "
                  "hierarchy) or none (test every primitive)")
      ->transform(CLI::CheckedTransformer(accelKindsByName(), CLI::ignore_case));
  // Checked once the scene is loaded (applyCameraOptions), with the scene
  // language's rules and messages.
  command.add_option("--eye", o.eye, "Camera position X Y Z (overrides the scene's eye)")
      ->expected(3);
  command.add_option("--lookat", o.lookat, "Point X Y Z the camera looks at (overrides lookat)")
      ->expected(3);
  command.add_option("--fov", o.fov,
                     "Full vertical field of view in degrees, 0 < fov < 180 (overrides fov)");
}

bool hasCameraOptions(const RenderCommandOptions& o) {
  return !o.eye.empty() || !o.lookat.empty() || o.fov.has_value();
}

std::optional<std::string> cameraOptionsProblem(const RenderCommandOptions& o) {
  if (o.fov && !(*o.fov > 0.0 && *o.fov < 180.0))
    return "--fov: DEGREES must be greater than 0 and less than 180, found " + number(*o.fov);
  for (const auto& [name, xyz] : {std::pair{"--eye", &o.eye}, std::pair{"--lookat", &o.lookat}})
    if (!xyz->empty() && !withinModelRange(point(*xyz)))
      return std::string(name) + " " + text(point(*xyz)) + ": the point must be within +-" +
             kMaxCoordinateText;
  return std::nullopt;
}

std::optional<std::string> applyCameraOptions(const RenderCommandOptions& o, CameraSpec& camera) {
  if (std::optional<std::string> problem = cameraOptionsProblem(o)) return problem;
  CameraSpec c = camera;
  if (!o.eye.empty()) c.eye = point(o.eye);
  if (!o.lookat.empty()) c.lookat = point(o.lookat);
  if (o.fov) c.fov = *o.fov;
  if (!o.eye.empty() || !o.lookat.empty()) {
    // The parser's camera checks (core/io/scene_parser.cpp).
    const std::string given = !o.eye.empty() && !o.lookat.empty() ? "--eye and --lookat"
                              : !o.eye.empty()                    ? "--eye"
                                                                  : "--lookat";
    if (std::optional<std::string> problem = viewProblem(c)) return given + ": " + *problem;
  }
  camera = c;
  return std::nullopt;
}

CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& o) {
  CLI::App* command = app.add_subcommand("render", "Render a scene to an image file, headless");
  addSceneArgument(*command, o.scene, true);
  command->add_option("-o,--output", o.output,
                      "Output image: .tif/.tiff (8-bit RGB), .png, .exr (float radiance), ...; "
                      "- for standard output (with --format)");
  command->add_option("--format", o.format,
                      "With -o -: the picture's format, as an extension: png, tiff, exr, ...");
  addRenderSettingsOptions(*command, o);
  addRangedOption(*command, "--scale", o.scale,
                  "Render at PERCENT of the scene's resolution, 0 < PERCENT <= 100 (each side "
                  "rounded, at least 1 pixel; not with --size)",
                  0.0, 100.0)
      ->check(CLI::PositiveNumber)
      ->excludes("--size");
  command
      ->add_option("--crop", o.crop,
                   "Render only the region X0 Y0 X1 Y1 (pixels X0 <= x < X1, Y0 <= y < Y1; pass 1 "
                   "and the exposure stay the whole frame's) and write only it")
      ->expected(4)
      ->check(CLI::Range(0, 32768));
  command->add_flag("--float", o.floatTiff,
                    "Write float radiance before exposure (implied by .exr and .hdr)");
  command->add_flag("--srgb", o.srgb,
                    "Encode the 8-bit values with the sRGB transfer function after exposure "
                    "(default: the model's linear values)");
  command->add_option("--stats-json", o.statsJson,
                      "Also write the statistics as JSON to this file (- for standard output)");
  command->add_option("--pixel", o.pixel, "Print the ray tree of pixel X Y instead of rendering")
      ->expected(2)
      ->check(CLI::NonNegativeNumber);
  command->add_flag("-q,--quiet", o.quiet, "No progress and no statistics on stderr");
  command->callback([&o] {
    if (o.pixel.empty() && o.output.empty())
      throw CLI::RequiredError("-o,--output (unless --pixel is given)");
    if (isStdio(o.output) && o.format.empty())
      throw CLI::ValidationError("-o -", "the picture's format must be given with --format");
    if (!o.format.empty() && !isStdio(o.output))
      throw CLI::ValidationError("--format", "only with -o - (a file's format follows its "
                                             "extension)");
    if (isStdio(o.output) && isStdio(o.statsJson))
      throw CLI::ValidationError("-o - and --stats-json -",
                                 "only one of them can be written to standard output");
    if (o.srgb && !o.output.empty() && writesFloat(o))
      throw CLI::ValidationError("--srgb", "is for 8-bit pictures; this one keeps float radiance");
  });
  return command;
}

RenderSettings renderSettings(const RenderCommandOptions& o, const Scene& scene) {
  RenderSettings settings;
  settings.width = o.size.empty() ? scene.width : o.size[0];
  settings.height = o.size.empty() ? scene.height : o.size[1];
  if (o.size.empty() && o.scale != 100.0) {
    settings.width = scaledSide(scene.width, o.scale);
    settings.height = scaledSide(scene.height, o.scale);
  }
  settings.maxDepth = o.depth.value_or(5);
  settings.thresh = o.thresh;
  settings.jitter = o.jitter;
  settings.noAa = o.noAa;
  settings.bailout = o.bailout;
  settings.threads = resolveThreadCount(o.threads);
  if (o.crop.size() == 4) {
    settings.cropX0 = o.crop[0];
    settings.cropY0 = o.crop[1];
    settings.cropX1 = o.crop[2];
    settings.cropY1 = o.crop[3];
  }
  return settings;
}

std::optional<std::string> imageMemoryProblem(const RenderSettings& settings,
                                              std::uint64_t bytesPerPixel,
                                              const std::string& what) {
  return memoryProblem(imageBytes(settings.width, settings.height, bytesPerPixel),
                       "a " + std::to_string(settings.width) + " x " +
                           std::to_string(settings.height) + " " + what);
}

int runRenderCommand(const RenderCommandOptions& o, ProcessGroup* group) {
  // Under MPI every process runs this function; rank 0 speaks for the job
  // (progress, warnings, errors, the files) and the others stay quiet. Where
  // a process could fail alone, the processes agree before going on, so none
  // waits for another that has left.
  const bool speaks = !group || group->rank() == 0;
  QuietStderr quietRank(!speaks);
  auto agree = [&](bool ok) { return agreeOnSuccess(group, ok, quietRank); };

  if (const std::optional<std::string> problem = cameraOptionsProblem(o)) {
    std::cerr << "prism: error: " << *problem << "\n";
    return kExitUsage;
  }
  // Only rank 0 would be given standard input: every process reads the scene.
  if (group && isStdio(o.scene)) {
    std::cerr << "prism: error: the scene cannot be read from standard input under MPI (every "
                 "process reads the scene file itself)\n";
    return kExitUsage;
  }
  // Every output is checked before any work: a typo in a folder name must not
  // cost a render, or leave a picture without its statistics.
  const bool writable = !speaks || succeeds([&] {
    if (o.pixel.empty() && !isStdio(o.output)) checkWritable(o.output);
    if (o.pixel.empty() && isStdio(o.output) && !hasImageFormat("x" + outputExtension(o)))
      throw std::runtime_error("--format " + o.format + ": no image format of that name");
    if (!o.statsJson.empty() && !isStdio(o.statsJson)) checkWritableFile(o.statsJson);
  });
  if (!agree(writable)) return kExitFailure;

  // Every process reads the scene itself (docs/distributed.md#loading).
  const auto loadStart = Clock::now();
  std::optional<Scene> loaded = loadSceneReporting(o.scene);
  if (!agree(loaded.has_value())) return kExitUsage;
  if (const std::optional<std::string> problem = applyCameraOptions(o, loaded->camera)) {
    std::cerr << "prism: error: " << *problem << "\n";
    return kExitUsage;
  }
  const Scene& scene = *loaded;
  const double loadSeconds = secondsSince(loadStart);

  const RenderSettings settings = renderSettings(o, scene);

  if (!o.pixel.empty() && (o.pixel[0] >= settings.width || o.pixel[1] >= settings.height)) {
    std::cerr << "prism: error: --pixel " << o.pixel[0] << " " << o.pixel[1] << " is outside the "
              << settings.width << " x " << settings.height << " image\n";
    return kExitUsage;
  }
  if (o.crop.size() == 4 && !(o.crop[0] < o.crop[2] && o.crop[2] <= settings.width &&
                              o.crop[1] < o.crop[3] && o.crop[3] <= settings.height)) {
    std::cerr << "prism: error: --crop " << o.crop[0] << " " << o.crop[1] << " " << o.crop[2] << " "
              << o.crop[3] << ": the region must be X0 < X1 <= " << settings.width
              << ", Y0 < Y1 <= " << settings.height << " (the image is " << settings.width << " x "
              << settings.height << ")\n";
    return kExitUsage;
  }
  if (o.pixel.empty()) {
    const std::optional<std::string> problem =
        imageMemoryProblem(settings, kRenderBytesPerPixel, "render");
    if (problem) std::cerr << "prism: error: " << *problem << "\n";
    if (!agree(!problem)) return kExitFailure;
  }

  const auto buildStart = Clock::now();
  const auto accel = makeAccel(scene, o.accel);
  const double buildSeconds = secondsSince(buildStart);
  if (!o.pixel.empty()) {
    if (speaks) std::cout << pixelRayTreeText(scene, *accel, settings, o.pixel[0], o.pixel[1]);
    return kExitOk;
  }

  // Before the render, which it does not change: a warning when pass 1 looks
  // endless (a deep render only; nothing is traced for depth <= 8, or with -q).
  if (!o.quiet && speaks) {
    const WorkEstimate estimate = estimateWork(scene, *accel, settings);
    if (estimate.explodes)
      std::cerr << "prism: warning: " << workWarning(estimate, settings) << "\n";
  }

  RenderStats stats;
  const double cpuStart = processCpuSeconds();
  const auto renderStart = Clock::now();
  RenderResult result;
  {
    ProgressReporter reporter(!o.quiet && speaks, !settings.noAa);
    ThreadPoolExecutor local(settings.threads);
    if (group) {
      const std::unique_ptr<DistributedExecutor> executor = group->makeExecutor(local);
      executor->setGroupProgress([&](int pass, double fraction) {
        reporter.update({pass, 0.5 * fraction + (pass == 2 ? 0.5 : 0.0)});
      });
      result = render(scene, *accel, settings, *executor);
      stats.ranks =
          group->gatherStats({group->rank(), hostName(), settings.threads, executor->itemsRunHere(),
                              executor->raysHere(), processCpuSeconds() - cpuStart});
    } else {
      result = render(scene, *accel, settings, local,
                      [&](const RenderProgress& p) { reporter.update(p); });
    }
  }
  stats.wallSeconds = secondsSince(renderStart);
  stats.cpuSeconds = processCpuSeconds() - cpuStart;
  if (!speaks) return kExitOk; // rank 0 holds the picture and writes it
  if (!stats.ranks.empty()) {
    stats.cpuSeconds = 0.0;
    for (const RankStats& r : stats.ranks)
      stats.cpuSeconds += r.cpuSeconds;
  }

  PictureExposure exposure;
  exposure.srgb = o.srgb;
  // With --crop, the region alone, exposed by the whole frame's avgmax.
  RenderResult region;
  if (settings.cropX1 != 0) {
    region.film =
        cropped(result.film, settings.cropX0, settings.cropY0, settings.cropX1, settings.cropY1);
    region.avgmax = result.avgmax;
  }
  const RenderResult& picture = settings.cropX1 != 0 ? region : result;
  const bool written = succeeds([&] {
    if (isStdio(o.output))
      writePictureTo(std::cout, "standard output", outputExtension(o), picture, writesFloat(o),
                     exposure);
    else
      writePicture(o.output, picture, writesFloat(o), exposure);
  });
  if (!written) return kExitFailure;

  stats.scene = isStdio(o.scene) ? "<stdin>" : o.scene;
  stats.machine = machineDescription();
  stats.accel = accelKindName(o.accel);
  stats.primitives = scene.primitiveCount();
  stats.loadSeconds = loadSeconds;
  stats.buildSeconds = buildSeconds;
  recordInStats(settings, result, stats);
  if (!o.quiet) std::cerr << formatStatsText(stats);
  if (!o.statsJson.empty()) {
    const std::string json = formatStatsJson(stats);
    if (!succeeds([&] {
          if (!isStdio(o.statsJson))
            writeFileAtomically(o.statsJson, [&](std::ostream& out) { out << json; });
          else if (!(std::cout << json).flush())
            throw std::runtime_error("cannot write the statistics to standard output");
        }))
      return kExitFailure;
  }
  return kExitOk;
}

} // namespace prism

// prism: the command line. Parses arguments and hands them to a command.
#include "bench_command.h"
#include "convert_command.h"
#include "render_command.h"
#include "view_command.h"

#include <CLI/CLI.hpp>

#include <map>

int main(int argc, char** argv) {
  using namespace prism;
  CLI::App app{"Prism: a recursive ray tracer with adaptive antialiasing and automatic exposure"};
  app.set_version_flag("--version", "prism " PRISM_VERSION);
  app.require_subcommand(1);

  RenderCommandOptions render;
  CLI::App* renderCmd = app.add_subcommand("render", "Render a scene to an image file, headless");
  renderCmd->add_option("scene", render.scene, "Scene file (.sc, .nff or .obj)")
      ->required()
      ->check(CLI::ExistingFile);
  auto* output = renderCmd->add_option(
      "-o,--output", render.output,
      "Output image: .tif/.tiff (8-bit RGB), .png, .exr (float radiance), ...");
  renderCmd->add_option("--depth", render.depth, "Maximum ray depth D >= 1 (1: ray casting with shadows) [5]")
      ->check(CLI::Range(1, 1000));
  renderCmd->add_option("--thresh", render.thresh, "Antialiasing threshold in [0, 1]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  renderCmd->add_option("--size", render.size, "Image size W H (overrides the scene's resolution)")
      ->expected(2)
      ->check(CLI::Range(1, 32768));
  renderCmd->add_option("--threads", render.threads, "Render threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  renderCmd->add_flag("--jitter", render.jitter, "Jitter the 16 sub-samples within their cells");
  renderCmd->add_flag("--float", render.floatTiff,
                      "Write float radiance before exposure (implied by .exr and .hdr)");
  renderCmd->add_option("--accel", render.accel,
                        "Ray acceleration: bvh (SAH hierarchy, default), groups (the push/pop "
                        "hierarchy) or none (test every primitive)")
      ->transform(CLI::CheckedTransformer(accelKindsByName(), CLI::ignore_case));
  renderCmd->add_option("--stats-json", render.statsJson, "Also write the statistics as JSON to this file");
  renderCmd->add_option("--pixel", render.pixel, "Print the ray tree of pixel X Y instead of rendering")
      ->expected(2)
      ->check(CLI::NonNegativeNumber);
  renderCmd->add_flag("-q,--quiet", render.quiet, "No progress and no statistics on stderr");
  renderCmd->callback([&] {
    if (render.pixel.empty() && render.output.empty())
      throw CLI::RequiredError("-o,--output (unless --pixel is given)");
  });
  (void)output;

  BenchCommandOptions bench;
  CLI::App* benchCmd = addBenchCommand(app, bench);

  ViewCommandOptions view;
  CLI::App* viewCmd = addViewCommand(app, view);

  ConvertCommandOptions convert;
  CLI::App* convertCmd = addConvertCommand(app, convert);

  try {
    const std::vector<const char*> args = withDefaultCommand(app, argc, argv); // prism SCENE
    app.parse(int(args.size()), args.data());
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitUsage;
  }
  if (renderCmd->parsed()) return runRenderCommand(render);
  if (viewCmd->parsed()) return runViewCommand(view);
  if (benchCmd->parsed()) return runBenchCommand(bench);
  if (convertCmd->parsed()) return runConvertCommand(convert);
  return kExitUsage;
}

#include "view_command.h"

#include "cli_options.h"

#include "core/io/scene_loader.h"
#include "core/render/parallel.h"
#include "core/system/memory_budget.h"

#ifdef PRISM_HAVE_PREVIEWER
#include "viewer/view_app.h"
#endif

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace prism {

namespace {

// Says in one line why there is no window, then renders what the window would
// have shown: same scene and settings, written to -o or SCENE-STEM.tiff here.
int renderHeadless(const ViewCommandOptions& o, const std::string& why) {
  RenderCommandOptions render = o.render;
  if (render.output.empty())
    render.output = std::filesystem::path(render.scene).stem().string() + ".tiff";
  std::cerr << "prism: " << why << "; rendering headless to " << render.output << " instead\n";
  return runRenderCommand(render);
}

#ifdef PRISM_HAVE_PREVIEWER
// Reads the scene and makes the previewer's controller (which builds the
// hierarchy), on the window's loader thread. Failures are reported on stderr
// as `prism render` reports them, with the same exit codes.
PreparedView prepareView(const ViewCommandOptions& o, LoadProgress& progress) {
  try {
    std::vector<Diagnostic> loadWarnings;
    Scene scene = loadAnyScene(o.render.scene, &loadWarnings);
    std::vector<std::string> warnings;
    for (const Diagnostic& d : loadWarnings)
      warnings.push_back(formatWarning(d)); // printed by the controller
    ViewOptions v;
    CameraSpec camera = scene.camera;
    if (const std::optional<std::string> problem = applyCameraOptions(o.render, camera)) {
      std::cerr << "prism: error: " << *problem << "\n";
      return {nullptr, kExitUsage};
    }
    if (hasCameraOptions(o.render)) v.camera = camera; // an edit over the file's camera
    v.scenePath = o.render.scene;
    v.sizeFromScene = o.render.size.empty();
    v.settings = renderSettings(o.render, scene);
    v.accel = o.render.accel;
    v.sweepPath = o.sweep;
    if (const std::optional<std::string> problem =
            imageMemoryProblem(v.settings, kPreviewBytesPerPixel, "preview")) {
      std::cerr << "prism: error: " << *problem << "\n";
      return {nullptr, kExitFailure};
    }
    progress.primitives = scene.primitiveCount();
    progress.stage = 1;
    return {std::make_unique<ViewController>(std::move(scene), v, std::move(warnings)), kExitOk};
  } catch (const SceneError& error) {
    for (const Diagnostic& d : error.diagnostics())
      std::cerr << d.format() << "\n";
    return {nullptr, kExitUsage};
  } catch (const std::bad_alloc&) {
    std::cerr << "prism: error: out of memory\n";
    return {nullptr, kExitFailure};
  }
}
#endif

} // namespace

CLI::App* addViewCommand(CLI::App& app, ViewCommandOptions& o) {
  CLI::App* view = app.add_subcommand(
      "view", "Open the interactive previewer (the default: `prism SCENE`); without a display, "
              "render headless");
  RenderCommandOptions& r = o.render;
  addSceneArgument(*view, r.scene);
  view->add_option("-o,--output", r.output,
                   "Where Save writes (and the headless fallback) [SCENE-STEM.tiff]");
  addRenderSettingsOptions(*view, r);
  view->add_flag("-q,--quiet", r.quiet, "Headless fallback: no progress and no statistics");
  view->add_option("--script", o.script,
                   "Run a scripted session from FILE (waits, edits, save, screenshot, quit)")
      ->check(CLI::ExistingFile);
  view->add_option("--sweep", o.sweep,
                   "The scene's sweep table (`prism sweep`'s CSV), to show where the settings "
                   "sit [NAME.sweep.csv beside the scene NAME.sc]")
      ->check(CLI::ExistingFile);
  view->add_option("--dump-widgets", o.dumpWidgets,
                   "Write every frame's interactive widgets (label, kind, place) as JSON to FILE, "
                   "for tests that drive the window with real input");
  return view;
}

std::vector<const char*> withDefaultCommand(const CLI::App& app, int argc, char** argv) {
  std::vector<const char*> args(argv, argv + argc);
  if (argc < 2 || argv[1][0] == '-') return args;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->check_name(argv[1])) return args; // a name or an alias (`check`)
  std::error_code error;
  if (std::filesystem::is_regular_file(argv[1], error)) args.insert(args.begin() + 1, "view");
  return args;
}

int runViewCommand(const ViewCommandOptions& o) {
  if (const std::optional<std::string> problem = cameraOptionsProblem(o.render)) {
    std::cerr << "prism: error: " << *problem << "\n";
    return kExitUsage;
  }
#ifndef PRISM_HAVE_PREVIEWER
  return renderHeadless(o, "this prism was built without the previewer");
#else
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    return renderHeadless(o, "no display (DISPLAY is not set)");
  std::string why;
  if (!openWindowSystem(why)) return renderHeadless(o, "cannot open a window (" + why + ")");

  ViewAppOptions app;
  try {
    if (!o.script.empty()) app.script = loadScript(o.script);
  } catch (const SceneError& error) { // the script
    for (const Diagnostic& d : error.diagnostics())
      std::cerr << d.format() << "\n";
    closeWindowSystem();
    return kExitUsage;
  }
  app.scenePath = o.render.scene;
  app.dumpWidgets = o.dumpWidgets;
  if (!o.render.size.empty()) {
    app.width = o.render.size[0];
    app.height = o.render.size[1];
  }
  app.savePath = o.render.output.empty()
                     ? std::filesystem::path(o.render.scene).stem().string() + ".tiff"
                     : o.render.output;
  app.prepare = [&o](LoadProgress& progress) { return prepareView(o, progress); };
  const std::optional<int> ran = runViewApp(app, why);
  closeWindowSystem();
  return ran ? *ran : renderHeadless(o, why);
#endif
}

} // namespace prism

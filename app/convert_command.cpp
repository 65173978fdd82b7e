#include "convert_command.h"

#include "load_scene.h"
#include "render_command.h"

#include "core/io/file_extension.h"
#include "core/io/image_io.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_loader.h"
#include "core/io/scene_writer.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace prism {

namespace {

// The output's format, by its extension: .pov is POV-Ray's, anything else
// Prism's own .sc (an .nff or .obj name is refused: Prism does not write those).
bool writesPov(const std::string& output) { return lowerExtension(output) == ".pov"; }

} // namespace

CLI::App* addConvertCommand(CLI::App& app, ConvertCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "convert", "Write a scene (.sc, .nff or .obj) as a .sc or POV-Ray .pov file");
  cmd->add_option("input", o.input, "Scene to read: .sc, .nff (NFF) or .obj (with its .mtl)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("output", o.output, "The file to write: .pov for POV-Ray 3.7, else .sc")
      ->required();
  cmd->add_flag("-q,--quiet", o.quiet, "No summary on stderr");
  return cmd;
}

int runConvertCommand(const ConvertCommandOptions& o) {
  const bool pov = writesPov(o.output);
  if (!pov && sceneFormatOf(o.output) != SceneFormat::Sc) {
    std::cerr << "prism: error: convert writes .sc and .pov scenes; '" << o.output
              << "' names another format\n";
    return kExitUsage;
  }
  if (!succeeds([&] { checkWritableFile(o.output); })) return kExitFailure;
  const std::optional<Scene> loaded = loadSceneReporting(o.input);
  if (!loaded) return kExitUsage;
  const Scene& scene = *loaded;
  const std::string header = "Converted by prism convert from " + o.input;
  if (!succeeds([&] {
        if (pov)
          savePov(o.output, scene, header);
        else
          saveScene(o.output, scene, header);
      }))
    return kExitFailure;
  if (!o.quiet) {
    const std::string kinds = scene.kindCounts();
    std::cerr << "wrote " << o.output << ": " << scene.primitiveCount() << " primitives"
              << (kinds.empty() ? "" : " (" + kinds + ")") << ", " << scene.lights.size()
              << " lights, " << scene.materials.size() << " materials\n";
  }
  return kExitOk;
}

} // namespace prism

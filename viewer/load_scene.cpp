#include "load_scene.h"

#include "core/scene_loader.h"

#include <iostream>

namespace prism {

std::optional<Scene> loadSceneReporting(const std::string& path) {
  std::vector<Diagnostic> warnings;
  try {
    Scene scene = loadAnyScene(path, &warnings);
    for (const Diagnostic& d : warnings)
      std::cerr << formatWarning(d) << "\n";
    return scene;
  } catch (const SceneError& error) {
    for (const Diagnostic& d : error.diagnostics())
      std::cerr << d.format() << "\n";
    return std::nullopt;
  }
}

} // namespace prism

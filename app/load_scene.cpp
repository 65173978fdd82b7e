#include "load_scene.h"

#include "core/io/scene_loader.h"

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

bool succeeds(const std::function<void()>& io) {
  try {
    io();
    return true;
  } catch (const std::exception& error) {
    std::cerr << "prism: error: " << error.what() << "\n";
    return false;
  }
}

} // namespace prism

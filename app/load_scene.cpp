#include "load_scene.h"

#include "core/io/scene_loader.h"

#include <iostream>
#include <iterator>

namespace prism {

std::optional<Scene> loadSceneReporting(const std::string& path) {
  std::vector<Diagnostic> warnings;
  try {
    Scene scene = [&] {
      if (path != "-") return loadAnyScene(path, &warnings);
      const std::string text{std::istreambuf_iterator<char>(std::cin),
                             std::istreambuf_iterator<char>()};
      return parseScene(text, "<stdin>");
    }();
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

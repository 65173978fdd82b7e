// What the render session and pass schedule tests render: shipped scenes at a
// small size (80 x 60: six tiles of 32, quick, with pass 2 work on every scene).
#pragma once

#include "core/io/scene_loader.h"
#include "core/render/renderer.h"

#include <string>

namespace prism::test {

inline RenderSettings smallSettings() {
  RenderSettings s;
  s.width = 80;
  s.height = 60;
  s.maxDepth = 5;
  s.thresh = 0.1;
  s.threads = 2;
  return s;
}

inline Scene shipped(const char* name) {
  return loadScene(std::string(PRISM_SOURCE_DIR) + "/scenes/" + name);
}

} // namespace prism::test
